// SPDX-License-Identifier: Apache-2.0
#include "image/LayoutScore.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lut::formats {

// The layout of an N^2 x N strip when nothing else decides: Unreal's 256x16, and ReShade's
// 1024x32 (the same pixel placement) for N = 32.
LutLayout defaultStripLayout(int n) {
    return n == layoutFixedSize(LutLayout::Reshade) ? LutLayout::Reshade : LutLayout::Pilot;
}

std::string fmt2(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

AxisScore axisScore(const Lut3D& lut) {
    AxisScore s;
    const int n = lut.size();
    for (int c = 0; c < 3; ++c) {
        double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0, cnt = 0;
        for (int b = 0; b < n; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r) {
                    const double v = lut.at(r, g, b)[c];
                    if (!std::isfinite(v))
                        continue;
                    const double x = c == 0 ? r : c == 1 ? g : b;
                    sx += x;
                    sy += v;
                    sxx += x * x;
                    syy += v * v;
                    sxy += x * v;
                    cnt += 1;
                }
        if (cnt < 2)
            continue;
        const double vx = sxx - sx * sx / cnt, vy = syy - sy * sy / cnt, cxy = sxy - sx * sy / cnt;
        if (vx <= 0 || vy <= 1e-20 * cnt)
            continue;
        const double r = cxy / std::sqrt(vx * vy);
        s.corr[c] = std::isfinite(r) ? std::max(-1.0, std::min(1.0, r)) : 0.0;
    }
    return s;
}

} // namespace lut::formats
