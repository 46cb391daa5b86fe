// SPDX-License-Identifier: Apache-2.0
// Reading the patch's blocks and evaluating the measured edit between them; see
// lut/roundtrip/PatchReader.h.
#include "lut/roundtrip/PatchReader.h"

#include "interp/LatticeMapping.h"
#include "interp/ScalarLattice.h"
#include "lut/Error.h"
#include "lut/io/Layout.h"
#include "roundtrip/BlockAnalysis.h"
#include "roundtrip/ColourDistance.h"
#include "roundtrip/MarkerFrame.h"

#include <algorithm>
#include <cmath>

namespace lut {

using detail::maxDiff;

int blockInset(int cell) {
    return cell >= 6 ? 2 : cell >= 3 ? 1 : 0;
}

namespace {

// Mean colour of the inner part of the cell (cx, cy) of the frame (outer ring included).
glm::dvec3 frameCellMean(const ImageView& img, const PatchPlacement& pl, int cx, int cy) {
    const int inset = blockInset(pl.cell), m = pl.cell - 2 * inset;
    glm::dvec3 acc(0.0);
    for (int dy = 0; dy < m; ++dy)
        for (int dx = 0; dx < m; ++dx) {
            const float* p = img.pixel(pl.frameX + cx * pl.cell + inset + dx,
                                       pl.frameY + cy * pl.cell + inset + dy);
            for (int c = 0; c < 3; ++c)
                acc[c] += std::isfinite(p[c]) ? p[c] : 0.0f;
        }
    return acc / (static_cast<double>(m) * m);
}

// How far the outer ring's cells sit from the mean of their symbol: two colours drawn many
// times, so their spread is the read error of a uniform block in this file.
double frameSpread(const ImageView& img, const PatchPlacement& pl) {
    const int fw = pl.frameWidth / pl.cell, fh = pl.frameHeight / pl.cell;
    std::vector<std::pair<int, int>> cells;
    for (int x = 0; x < fw; ++x) {
        cells.emplace_back(x, 0);
        cells.emplace_back(x, fh - 1);
    }
    for (int y = 1; y < fh - 1; ++y) {
        cells.emplace_back(0, y);
        cells.emplace_back(fw - 1, y);
    }
    glm::dvec3 sum[2] = {glm::dvec3(0.0), glm::dvec3(0.0)};
    int count[2] = {0, 0};
    std::vector<glm::dvec3> means(cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i) {
        means[i] = frameCellMean(img, pl, cells[i].first, cells[i].second);
        const int sym = (cells[i].first + cells[i].second) & 1;
        sum[sym] += means[i];
        ++count[sym];
    }
    double worst = 0.0;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const int sym = (cells[i].first + cells[i].second) & 1;
        const glm::dvec3 mean = sum[sym] / static_cast<double>(std::max(count[sym], 1));
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::fabs(means[i][c] - mean[c]));
    }
    return worst;
}

// v is k/levels up to float rounding (a float holds k/65535 to about 0.004 of a level).
bool multipleOf(float v, double levels) {
    const double x = static_cast<double>(v) * levels;
    return std::fabs(x - std::round(x)) < 0.02;
}

} // namespace

PatchReading readPatch(const ImageView& img, const PatchPlacement& pl) {
    PatchReading out;
    out.placement = pl;
    const int n = pl.size, cell = pl.cell;
    int cw = 0, ch = 0;
    detail::patchCells(pl.layout, n, cw, ch);
    const int px0 = pl.patchX(), py0 = pl.patchY();
    if (px0 < 0 || py0 < 0 || pl.frameX < 0 || pl.frameY < 0 ||
        static_cast<long long>(px0) + static_cast<long long>(cw) * cell > img.width ||
        static_cast<long long>(py0) + static_cast<long long>(ch) * cell > img.height ||
        static_cast<long long>(pl.frameX) + pl.frameWidth > img.width ||
        static_cast<long long>(pl.frameY) + pl.frameHeight > img.height)
        throw Error("the LUT patch does not fit inside the image");
    out.values = Lut3D(n);
    out.blockSpread = Lut3D(n);
    out.axis.resize(n);
    for (int i = 0; i < n; ++i)
        out.axis[i] = patchInputValue(pl.lattice, i, n, pl.bitDepth);
    // Average the inner part of each block: its border pixels take the brunt of resampling,
    // JPEG ringing and a neighbour's bleed. Uniformity is judged on the whole block: a global
    // edit leaves a uniform block uniform, a blur or sharpen does not.
    const int inset = blockInset(cell);
    const int m = cell - 2 * inset;
    const double inv = 1.0 / (static_cast<double>(m) * m);
    const bool judgeBlocks = pl.cell % pl.scale == 0;
    bool all8 = true, all16 = true;
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                int x = 0, y = 0;
                layoutPixel(pl.layout, n, r, g, b, x, y);
                const int bx = px0 + x * cell + inset, by = py0 + y * cell + inset;
                double acc[3] = {0, 0, 0}, acc2[3] = {0, 0, 0};
                for (int dy = 0; dy < m; ++dy)
                    for (int dx = 0; dx < m; ++dx) {
                        const float* p = img.pixel(bx + dx, by + dy);
                        for (int c = 0; c < 3; ++c) {
                            const double v = std::isfinite(p[c]) ? p[c] : 0.0f;
                            acc[c] += v;
                            acc2[c] += v * v;
                            all8 = all8 && multipleOf(p[c], 255.0);
                            all16 = all16 && multipleOf(p[c], 65535.0);
                        }
                    }
                const glm::vec3 mean(static_cast<float>(acc[0] * inv),
                                     static_cast<float>(acc[1] * inv),
                                     static_cast<float>(acc[2] * inv));
                glm::vec3 spread;
                for (int c = 0; c < 3; ++c)
                    spread[c] = static_cast<float>(
                        std::sqrt(std::max(0.0, acc2[c] * inv - (acc[c] * inv) * (acc[c] * inv))));
                double dev = 0.0;
                if (judgeBlocks)
                    for (int dy = 0; dy < cell; ++dy)
                        for (int dx = 0; dx < cell; ++dx) {
                            const float* p = img.pixel(px0 + x * cell + dx, py0 + y * cell + dy);
                            dev = std::max(dev, static_cast<double>(
                                                    maxDiff(glm::vec3(p[0], p[1], p[2]), mean)));
                        }
                dev *= 255.0;
                out.blockMaxDeviation = std::max(out.blockMaxDeviation, dev);
                if (dev > 2.5)
                    ++out.nonUniformBlocks;
                out.values.at(r, g, b) = mean;
                out.blockSpread.at(r, g, b) = spread;
            }
    out.storedBits = all8 ? 8 : all16 ? 16 : 32;
    out.frameSpread = frameSpread(img, pl);
    out.chroma = checkChroma(img, pl);
    out.blocks = detail::gatherBlockEvidence(img, pl);
    return out;
}

PatchFunction::PatchFunction(const Lut3D& values, std::vector<float> axis)
    : m_values(values), m_axis(std::move(axis)) {
    if (m_values.empty() || static_cast<int>(m_axis.size()) != m_values.size() || m_axis.size() < 2)
        throw Error("PatchFunction: axis and table sizes differ");
}

glm::vec3 PatchFunction::operator()(glm::vec3 in) const {
    int ir, ig, ib;
    float fr, fg, fb;
    const int n = static_cast<int>(m_axis.size());
    detail::locateOnAxis(m_axis.data(), n, in.x, ir, fr);
    detail::locateOnAxis(m_axis.data(), n, in.y, ig, fg);
    detail::locateOnAxis(m_axis.data(), n, in.z, ib, fb);
    return detail::tetrahedralBlend(
        [this](int r, int g, int b) -> const glm::vec3& { return m_values.at(r, g, b); }, ir, ig,
        ib, fr, fg, fb);
}

} // namespace lut
