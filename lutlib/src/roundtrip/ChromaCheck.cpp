// SPDX-License-Identifier: Apache-2.0
// Chroma subsampling from a patch's pixels; see lut/roundtrip/ChromaCheck.h.
#include "lut/roundtrip/ChromaCheck.h"

#include "lut/io/Layout.h"
#include "roundtrip/MarkerFrame.h"

#include <algorithm>
#include <cmath>

namespace lut {

namespace {

// JPEG's (BT.601 full range) luma and chroma of a pixel.
void ycc(const float* p, double out[3]) {
    const double r = std::isfinite(p[0]) ? p[0] : 0.0, g = std::isfinite(p[1]) ? p[1] : 0.0,
                 b = std::isfinite(p[2]) ? p[2] : 0.0;
    out[0] = 0.299 * r + 0.587 * g + 0.114 * b;
    out[1] = -0.168736 * r - 0.331264 * g + 0.5 * b;
    out[2] = 0.5 * r - 0.418688 * g - 0.081312 * b;
}

// Changes smaller than this (in [0,1]) say nothing about sharpness.
constexpr double kMinChange = 6.0 / 255.0;
// Chroma this much softer than luma, with luma sharp, is subsampled.
constexpr double kSharpLuma = 0.8;
constexpr double kSoftChroma = 0.72;

} // namespace

std::string ChromaCheck::scheme() const {
    if (!measured)
        return {};
    return horizontal && vertical ? "4:2:0" : horizontal ? "4:2:2" : vertical ? "4:4:0" : "4:4:4";
}

ChromaCheck checkChroma(const ImageView& img, const PatchPlacement& pl) {
    ChromaCheck out;
    const int cell = pl.cell;
    if (cell < 3 || pl.size < 2)
        return out;
    int cw = 0, ch = 0;
    detail::patchCells(pl.layout, pl.size, cw, ch);
    const int px0 = pl.patchX(), py0 = pl.patchY();
    if (px0 < 0 || py0 < 0 || px0 + cw * cell > img.width || py0 + ch * cell > img.height)
        return out;
    const int reach = std::min(cell, 3); // pixels looked at on each side of a boundary
    bool enough = true;
    for (int dir = 0; dir < 2; ++dir) {
        double sumL = 0.0, wL = 0.0, sumC = 0.0, wC = 0.0;
        // boundaries between cell columns (dir 0) or rows (dir 1), sampled along the middle of
        // each block in the other direction
        const int lines = dir == 0 ? cw - 1 : ch - 1, along = dir == 0 ? ch : cw;
        for (int i = 1; i <= lines; ++i)
            for (int j = 0; j < along; ++j)
                for (int k = cell / 3; k < cell - cell / 3; ++k) {
                    auto at = [&](int offset) {
                        const int x = dir == 0 ? px0 + i * cell + offset : px0 + j * cell + k;
                        const int y = dir == 0 ? py0 + j * cell + k : py0 + i * cell + offset;
                        return img.pixel(x, y);
                    };
                    double a[3], b[3], lo[3], hi[3];
                    ycc(at(-1), a);
                    ycc(at(0), b);
                    ycc(at(-reach), lo);
                    ycc(at(reach - 1), hi);
                    for (int c = 0; c < 3; ++c) {
                        const double total = hi[c] - lo[c];
                        if (std::fabs(total) < kMinChange)
                            continue;
                        const double share = std::clamp((b[c] - a[c]) / total, 0.0, 1.0);
                        const double w = std::fabs(total);
                        if (c == 0) {
                            sumL += w * share;
                            wL += w;
                        } else {
                            sumC += w * share;
                            wC += w;
                        }
                    }
                }
        if (wL < 1.0 || wC < 1.0) { // fewer than some tens of clear edges
            enough = false;
            continue;
        }
        out.lumaSharpness[dir] = sumL / wL;
        out.chromaSharpness[dir] = sumC / wC;
    }
    out.measured = enough;
    if (!enough)
        return out;
    for (int dir = 0; dir < 2; ++dir) {
        const bool soft = out.lumaSharpness[dir] >= kSharpLuma &&
                          out.chromaSharpness[dir] < kSoftChroma * out.lumaSharpness[dir];
        (dir == 0 ? out.horizontal : out.vertical) = soft;
    }
    return out;
}

} // namespace lut
