// SPDX-License-Identifier: Apache-2.0
#pragma once
// The editor's scripted mode (lutkit-editor --script FILE): drives the real window the way a user
// does, one command per line, for the tests that run under a real X server (Xvfb) and for
// reproducible bug reports. Files open through the same worker as the menus, keys go through
// the window's shortcut handling to the focused widget, the export takes the dialog's defaults.
//
//   open-image PATH            open-lut PATH [LAYOUT]        drop PATH...    new-neutral N
//   target smash|engine|cube   input screenshot|scene        chain filmic|cinematic|none
//   bloom on|off   lut on|off   brighten on|off   interp NAME   clipping on|off
//   set KEY VALUE              (an adjustment: exposure, lift.r, strength...; one undo step)
//   curve NAME X,Y...          (master red green blue hue.hue hue.sat hue.lum; one undo step)
//   drag KEY VALUE             (a slider dragged by the mouse to VALUE; one undo step)
//   focus OBJECTNAME           type TEXT        key SEQUENCE (e.g. ctrl+z, Return)
//   undo  redo  save  save-as PATH  adjustments-save PATH  adjustments-load PATH
//   export [PATH [FORMAT [LAYOUT]]] [overwrite]   (no PATH: the export dialog's suggestion)
//   hue-range hue.hue|hue.sat|hue.lum RANGE AMOUNT   (the curve's button, the range's button
//                              reds..magentas, AMOUNT typed in Amount: one undo step)
//   save-preview PATH   screenshot PATH   wait   sleep MS   close
//   start-open-image PATH   start-compare FILE   start-save-preview PATH   (return at once)
//   start-match REFERENCE      (Tools > Match to Reference; its dialog, once the fit is done, is
//                               answered as `dialogs` says: accept = OK at the default amounts)
//   cancel load|compare|match|save-preview   (the status bar's Cancel)   wait-task NAME
//   probe on|off               (the repaint probe, RepaintProbe.h; off prints the longest gap)
//   check [N]                  (the Check panel raised and current, its verdict printed; with N,
//                               finding N clicked: its colours highlighted on the picture)
//   dialogs accept|reject|hold (how modal dialogs a command opens are answered: Return or Escape;
//                               default reject; hold: left open for the commands below)
//   match-drag strength|luma|chroma PERCENT [MS]  (the open match dialog's slider dragged by the
//                               mouse, over MS ms with a move every 16 ms: bench/editor_probe.sh)
//   print WHAT                 (state on stdout: target input chain bloom param:KEY undo-count
//                               modified notes error clip title export-path focus dialogs
//                               task:NAME curve:NAME zoom)
// Each command is a row of ScriptCommands.cpp's table (print's WHATs: ScriptPrint.cpp's).
// '#' starts a comment. A failing command prints "script:LINE: reason" and ends the run with 1.
#include <QString>
#include <QTextStream>

namespace lut::gui {

class MainWindow;

// Runs the script; returns 0 when every command worked, else 1 (after the first failure).
int runScript(MainWindow& window, const QString& path, QTextStream& out);

} // namespace lut::gui
