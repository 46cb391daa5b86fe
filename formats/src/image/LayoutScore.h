// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to the LUT image formats: how strongly a table read in a layout looks like a LUT read
// the right way round (each output channel following its own input), what the strip reader
// (StripFormat.cpp) and the atlas reader (Atlas.cpp) decide a layout with.
#include "lut/Lut3D.h"
#include "lut/io/Layout.h"

#include <string>

namespace lut::formats {

constexpr double kAxisCorrelationMin = 0.75;
// The layout of an N^2 x N strip when nothing else decides: Unreal's 256x16, and ReShade's
// 1024x32 (the same pixel placement) for N = 32.
LutLayout defaultStripLayout(int n);

// "0.75": a score with two decimals.
std::string fmt2(double v);

// Pearson correlation of output channel c with input index c, c = 0..2 (NaN/Inf entries skipped;
// a constant channel correlates 0).
struct AxisScore {
    double corr[3] = {0, 0, 0};
    double sum() const { return corr[0] + corr[1] + corr[2]; }
    bool followsAxes() const {
        return corr[0] >= kAxisCorrelationMin && corr[1] >= kAxisCorrelationMin &&
               corr[2] >= kAxisCorrelationMin;
    }
    std::string str() const {
        return "r " + fmt2(corr[0]) + ", g " + fmt2(corr[1]) + ", b " + fmt2(corr[2]);
    }
};

AxisScore axisScore(const Lut3D& lut);

} // namespace lut::formats
