// SPDX-License-Identifier: Apache-2.0
// The pixels inside a patch's blocks; see BlockAnalysis.h and lut/roundtrip/BlockEvidence.h.
#include "roundtrip/BlockAnalysis.h"

#include "roundtrip/ColourDistance.h"
#include "roundtrip/MarkerFrame.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lut::detail {

namespace {

constexpr double kNonUniformSteps = 2.5;
constexpr double kMinNeighbourSteps = 3.0; // a neighbour this different tells a direction

glm::dvec3 pixel(const ImageView& img, int x, int y) {
    const float* p = img.pixel(x, y);
    return glm::dvec3(std::isfinite(p[0]) ? p[0] : 0.0, std::isfinite(p[1]) ? p[1] : 0.0,
                      std::isfinite(p[2]) ? p[2] : 0.0);
}

// Luma and chroma energy of a colour difference (JPEG's YCbCr).
void split(const glm::dvec3& d, double& luma, double& chroma) {
    const double y = 0.299 * d.x + 0.587 * d.y + 0.114 * d.z;
    const double cb = -0.168736 * d.x - 0.331264 * d.y + 0.5 * d.z;
    const double cr = 0.5 * d.x - 0.418688 * d.y - 0.081312 * d.z;
    luma = y * y;
    chroma = cb * cb + cr * cr;
}

} // namespace

BlockEvidence gatherBlockEvidence(const ImageView& img, const PatchPlacement& pl) {
    BlockEvidence ev;
    const int cell = pl.cell;
    if (cell < 3 || pl.cell % pl.scale != 0)
        return ev;
    int cw = 0, ch = 0;
    patchCells(pl.layout, pl.size, cw, ch);
    const int px0 = pl.patchX(), py0 = pl.patchY();
    if (px0 < 0 || py0 < 0 || px0 + cw * cell > img.width || py0 + ch * cell > img.height)
        return ev;
    // every cell's mean (inner part, as readPatch averages)
    const int inset = cell >= 6 ? 2 : 1;
    std::vector<glm::dvec3> mean(static_cast<std::size_t>(cw) * ch);
    for (int cy = 0; cy < ch; ++cy)
        for (int cx = 0; cx < cw; ++cx) {
            glm::dvec3 acc(0.0);
            for (int y = inset; y < cell - inset; ++y)
                for (int x = inset; x < cell - inset; ++x)
                    acc += pixel(img, px0 + cx * cell + x, py0 + cy * cell + y);
            mean[static_cast<std::size_t>(cy) * cw + cx] =
                acc / static_cast<double>((cell - 2 * inset) * (cell - 2 * inset));
        }
    double towardsSum = 0.0, towardsWeight = 0.0, border2 = 0.0, interior2 = 0.0;
    std::size_t borderN = 0, interiorN = 0;
    double lumaE = 0.0, chromaE = 0.0;
    const int rim = std::max(1, cell / 4); // border pixels: within this of the block's edge
    for (int cy = 0; cy < ch; ++cy)
        for (int cx = 0; cx < cw; ++cx) {
            ++ev.blocks;
            const glm::dvec3 m = mean[static_cast<std::size_t>(cy) * cw + cx];
            double worst = 0.0;
            for (int y = 0; y < cell; ++y)
                for (int x = 0; x < cell; ++x)
                    worst = std::max(
                        worst, static_cast<double>(maxDiff(
                                   glm::vec3(pixel(img, px0 + cx * cell + x, py0 + cy * cell + y)),
                                   glm::vec3(m))));
            if (worst * 255.0 <= kNonUniformSteps)
                continue;
            ++ev.nonUniform;
            ev.boxX0 = ev.nonUniform == 1 ? cx : std::min(ev.boxX0, cx);
            ev.boxY0 = ev.nonUniform == 1 ? cy : std::min(ev.boxY0, cy);
            ev.boxX1 = std::max(ev.boxX1, cx);
            ev.boxY1 = std::max(ev.boxY1, cy);
            for (int y = 0; y < cell; ++y)
                for (int x = 0; x < cell; ++x) {
                    const glm::dvec3 d = pixel(img, px0 + cx * cell + x, py0 + cy * cell + y) - m;
                    double l = 0.0, c = 0.0;
                    split(d, l, c);
                    lumaE += l;
                    chromaE += c;
                    const int dist = std::min({x, y, cell - 1 - x, cell - 1 - y});
                    const double dev2 = glm::dot(d, d) / 3.0;
                    if (dist >= rim) {
                        interior2 += dev2;
                        ++interiorN;
                        continue;
                    }
                    border2 += dev2;
                    ++borderN;
                }
            // The pixels right at each edge (corners left out: two neighbours meet there): how
            // far they moved towards the neighbour across that edge. Clipped pixels are skipped
            // (an overshoot that hit 0 or 1 says less than it moved).
            const int nxs[4] = {cx - 1, cx + 1, cx, cx}, nys[4] = {cy, cy, cy - 1, cy + 1};
            for (int side = 0; side < 4; ++side) {
                const int nx = nxs[side], ny = nys[side];
                if (nx < 0 || ny < 0 || nx >= cw || ny >= ch)
                    continue;
                const glm::dvec3 v = mean[static_cast<std::size_t>(ny) * cw + nx] - m;
                const double vv = glm::dot(v, v);
                if (std::sqrt(vv / 3.0) * 255.0 < kMinNeighbourSteps)
                    continue;
                for (int k = 1; k < cell - 1; ++k) {
                    const int x = side == 0 ? 0 : side == 1 ? cell - 1 : k;
                    const int y = side == 2 ? 0 : side == 3 ? cell - 1 : k;
                    const glm::dvec3 p = pixel(img, px0 + cx * cell + x, py0 + cy * cell + y);
                    if (std::min({p.x, p.y, p.z}) <= 0.0 || std::max({p.x, p.y, p.z}) >= 1.0)
                        continue;
                    towardsSum += glm::dot(p - m, v) / vv;
                    towardsWeight += 1.0;
                }
            }
        }
    if (ev.nonUniform == 0)
        return ev;
    ev.towards = towardsWeight > 0.0 ? towardsSum / towardsWeight : 0.0;
    ev.borderSteps = borderN ? std::sqrt(border2 / double(borderN)) * 255.0 : 0.0;
    ev.interiorSteps = interiorN ? std::sqrt(interior2 / double(interiorN)) * 255.0 : 0.0;
    ev.chromaShare = lumaE + chromaE > 0.0 ? chromaE / (lumaE + chromaE) : 0.0;
    ev.boxShare = static_cast<double>(ev.boxX1 - ev.boxX0 + 1) * (ev.boxY1 - ev.boxY0 + 1) /
                  (static_cast<double>(cw) * ch);
    return ev;
}

} // namespace lut::detail
