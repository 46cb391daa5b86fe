// SPDX-License-Identifier: Apache-2.0
#pragma once
// The picture `lutkit match --report-image` writes and the editor shows: the source, the result
// (the LUT applied to the source) and the reference side by side, each scaled to fit 480x270,
// with its red, green and blue histograms (256 bins, each scaled to its own tallest bin) below.
// Scene-linear pictures are shown sRGB-encoded and clipped; a reference of the other kind is
// converted to the source's first (as the match does).
#include "lut/Image.h"
#include "lut/LutFile.h"

namespace lut {

struct MatchReportPicture {
    ImageView pixels;
    bool linear = false;
};

// Throws lut::Error for an empty picture.
Image matchReportImage(const MatchReportPicture& source, const LutFile& lut,
                       const MatchReportPicture& reference, int nthreads = 0);

// The LUT file (shaper, then table, tetrahedral) applied to every pixel; alpha kept.
Image applyLutFile(const LutFile& lut, const ImageView& image, int nthreads = 0);

} // namespace lut
