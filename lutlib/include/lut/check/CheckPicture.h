// SPDX-License-Identifier: Apache-2.0
#pragma once
// The check's report as one picture a person reads at a glance (`lutkit check --report OUT.png`):
//  - the overall result and one line per check (pass / warn / fail and its figures);
//  - the stress charts (lut/check/StressCharts.h) before and after the LUT: the grey ramp, its
//    shadows (input 0..0.25, shown 4 times brighter so banding there is visible), hue x
//    saturation, hue x lightness, the skin line and five slices of the cube; every finding
//    circled where its colour shows (red: fail, amber: warn) and numbered as in the list;
//  - the worst rays plotted: the output R, G, B along the grey axis and along the lines through
//    the first findings, with the input dashed and each finding's place marked;
//  - the numbered findings, worst first.
#include "lut/Image.h"
#include "lut/LutFile.h"
#include "lut/check/CheckLut.h"

#include <string>

namespace lut {

// Where the parts of the picture are, so tests can find them.
struct CheckPictureLayout {
    struct Rect {
        int x = 0, y = 0, width = 0, height = 0;
    };
    Rect before[6], after[6]; // grey, shadows, hue-saturation, hue-lightness, skin, slices
    struct Mark {
        int finding = 0;  // 1-based, as listed
        int row = 0;      // chart row (0..5) it is circled in
        int x = 0, y = 0; // the circle's centre on the AFTER side
    };
    std::vector<Mark> marks;
};

struct CheckPicture {
    Image image; // RGBA, display-encoded, alpha 1
    CheckPictureLayout layout;
};

// `title` heads the picture (e.g. the file's name). Throws lut::Error for an empty file.
CheckPicture drawCheckReport(const LutFile& file, const CheckReport& report,
                             const std::string& title);

} // namespace lut
