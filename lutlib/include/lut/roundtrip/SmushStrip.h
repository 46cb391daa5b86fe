// SPDX-License-Identifier: Apache-2.0
#pragma once
// Smush-LUT's own round trip (github.com/ScanMountGoat/Smush-LUT), read by lutkit extract:
//  - its first versions wrote `<screenshot>.lut.png`: the screenshot darkened for the game's
//    brighten step (each channel v / 1.4, truncated) with a 16^3 strip drawn over its top-left
//    256x16 pixels, entry (r, g, b) at x = r + 16 b, y = g (lutkit's unreal layout), each axis
//    holding the values of the game's default stage LUT, 0 15 30 46 64 82 101 121 140 158 176
//    193 209 224 240 255. The modder grades the whole picture; the strip's pixels are then the
//    game's LUT as Smush-LUT ships it (its model: an edit of the darkened screenshot is an edit
//    of the LUT's own values);
//  - later versions grade its neutral.png instead: a 256x16 identity LUT in its own layout
//    (lutkit's smush layout), an ordinary LUT image (lut::formats reads it, the layout told
//    from the picture).
// This header reads the first kind as a patch (PatchLattice::SmushLegacy).
#include "lut/Image.h"
#include "lut/roundtrip/PatchReader.h"

#include <string_view>
#include <vector>

namespace lut {

constexpr int kSmushStripSize = 16;

// The 16 per-axis input values of the strip, v/255.
std::vector<float> smushStripAxis();

// Whether a file name is one Smush-LUT gave its strips ("name.lut.png": it looks for ".lut.").
bool isSmushStripName(std::string_view fileName);

// Reads the strip from the top-left 256x16 pixels (throws lut::Error when the image is smaller).
PatchReading readSmushStrip(const ImageView& image);

} // namespace lut
