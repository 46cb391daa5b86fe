// SPDX-License-Identifier: Apache-2.0
#pragma once
// The shaper + table source the OpenColorIO-oracle tests share (tests/cli/test_shaper_oracle.cpp,
// tests/truth): a Resolve .cube written from float64 formulas, never by lutkit.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace lut::test {

// A log2 shaper (log2(x) + 8) / 14 clamped to [0, 1], 4096 entries over 0..64, then a warm
// tone-mapped grade of the linear value the shaper stands for, 33^3 (no TITLE: OpenColorIO's
// Resolve reader refuses one). Returns path.
inline std::string writeShapedCube(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f)
        return path;
    std::fprintf(f, "LUT_1D_SIZE 4096\nLUT_1D_INPUT_RANGE 0 64\nLUT_3D_SIZE 33\n"
                    "LUT_3D_INPUT_RANGE 0 1\n");
    for (int i = 0; i < 4096; ++i) {
        const double x = 64.0 * i / 4095.0;
        const double y = x <= 0 ? 0.0 : std::clamp((std::log2(x) + 8.0) / 14.0, 0.0, 1.0);
        std::fprintf(f, "%.7f %.7f %.7f\n", y, y, y);
    }
    for (int b = 0; b < 33; ++b)
        for (int g = 0; g < 33; ++g)
            for (int r = 0; r < 33; ++r) {
                double lin[3];
                const int idx[3] = {r, g, b};
                for (int c = 0; c < 3; ++c)
                    lin[c] = idx[c] == 0 ? 0.0 : std::pow(2.0, idx[c] / 32.0 * 14.0 - 8.0);
                const double m[3] = {lin[0] * 1.1 + 0.05 * lin[1], lin[1] * 0.95 + 0.05 * lin[0],
                                     lin[2] * 0.8 + 0.1 * lin[1]};
                double o[3];
                for (int c = 0; c < 3; ++c)
                    o[c] = std::pow(m[c] / (1.0 + m[c]), 1.0 / 2.2);
                std::fprintf(f, "%.7f %.7f %.7f\n", o[0], o[1], o[2]);
            }
    std::fclose(f);
    return path;
}

} // namespace lut::test
