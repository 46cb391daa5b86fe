// SPDX-License-Identifier: Apache-2.0
#pragma once
// The editor script's (ScriptRunner.h) user input, sent as the window system would: keys to the
// focused widget, a slider's handle dragged with the mouse, files dropped on the window.
#include <QKeySequence>
#include <QStringList>

class QSlider;

namespace lut::gui {

class MainWindow;

// A key press and release per key of `seq`: the focused widget is offered the shortcut first
// (ShortcutOverride), then the window's shortcuts, then the widget. Throws ScriptFailure when no
// widget has the focus.
void sendKeys(const QKeySequence& seq);
// Drags the slider's handle with the mouse to `position`: in a few moves at once, or over `ms`
// milliseconds with a move every 16 ms and the window's events run between them (as a hand).
void dragSlider(QSlider* s, int position, int ms = 0);
// Drops `files` on the window's centre and waits for what they open; returns whether the drop
// was accepted (throws ScriptFailure when the drag is refused).
bool dropFiles(MainWindow& w, const QStringList& files);

} // namespace lut::gui
