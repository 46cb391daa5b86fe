// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib's match: references whose colours lie on a curve of lightness (posterised
// palettes, gradient maps, duotones, sepia, greys), and the gradient-map transfer that
// reproduces them (lut/match/MatchOptions.h, MatchMethod::GradientMap).
//
// Recognised by binning the reference's samples by their luma (Rec. 709 weights on the working
// values, as ImageMagick's and most editors' "grey" take it) into 1024 bins: when the colours
// stay within a few 8-bit steps of their bin's mean colour (root mean square), the look is a
// colour per luma. Its kind: a palette of N colours when the picture holds few colours; greys
// when the bins' colours are neutral; one hue (sepia, a tint) when their hue stays within 15
// degrees; else a gradient map or duotone.
#include "lut/match/MatchTransfer.h"
#include "match/MatchSamples.h"

#include <cstddef>
#include <string>

namespace lut::detail {

struct CurveLook {
    bool onCurve = false;    // the reference is a colour per luma
    double rmsSteps = 0.0;   // how far its colours are from their bin's mean (8-bit steps)
    std::size_t colours = 0; // distinct colours (up to 256 counted; 0 = more)
    std::string kind;        // "posterised palette of 4 colours", "gradient map or duotone"...
};

// `distinct`: the reference's distinct colours (PictureFacts::distinct, summed over pictures).
CurveLook detectCurveLook(const SampleSet& reference, std::size_t distinct);

// The gradient-map transfer (lumaMatch, tone) of source to reference into t.
void fitGradientMap(const SampleSet& source, const SampleSet& reference, MatchTransfer& t);

} // namespace lut::detail
