// SPDX-License-Identifier: Apache-2.0
#pragma once
// The file the export dialog suggests, so an export never lands on a file the user has by
// surprise: a new name in the LUT's folder (else the picture's), never the opened LUT or picture.
//   Smash (.nutexb)   color_grading_lut.nutexb, the name the game loads, beside the opened LUT
//                     (else the picture), never in the picture's folder while a LUT is open;
//                     when that is the opened LUT itself, the same name in an "edited" folder
//                     beside it;
//   any other format  <name>_<format>[_<layout>]<extension>, <name> the LUT's file name (else the
//                     picture's, else "grade"): one name per format and layout, so flame and
//                     lustre .3dl, or two strip layouts, never share a file; the game's LUT in
//                     such a format (the Smash target's .cube) is <name>_game_<format>..., so
//                     it never shares a name with the edit the Grading target writes.
// The export still asks before replacing a file that exists (FileActions).
#include <QString>

namespace lut::gui {

struct ExportNameInput {
    QString format;         // registry name ("nutexb", "cube", "strip", "flame"...)
    QString layout;         // "" unless an image layout
    QString extension;      // with the dot
    QString lutPath;        // the opened LUT ("" = untitled)
    QString imagePath;      // the opened picture ("")
    QString fallbackFolder; // when neither has a folder
    bool gameLut = false;   // the file holds the game's LUT (purpose smash), not an edit
};

QString suggestedExportPath(const ExportNameInput& in);

} // namespace lut::gui
