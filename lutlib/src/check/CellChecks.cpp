// SPDX-License-Identifier: Apache-2.0
// The LUT check's measures over the table's cells: invertibility (the sign of each tetrahedron's
// Jacobian, as the tetrahedral interpolant lut::Sampler uses cuts a cell) and the share of the
// output cube the LUT reaches.
#include "check/CheckDetail.h"

#include "lut/Math.h"
#include "lut/Parallel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>

namespace lut::check {

namespace {

// The six tetrahedra of a cell, as the order their path from corner 000 to 111 takes the axes.
constexpr std::array<std::array<int, 3>, 6> kPaths = {
    {{0, 1, 2}, {0, 2, 1}, {2, 0, 1}, {1, 0, 2}, {1, 2, 0}, {2, 1, 0}}};

// A tetrahedron is flat when one of its edges hardly moves the output (under 1e-5 per unit of
// input) or its three edges are nearly in one plane: |det| under 1e-3 of the product of their
// lengths (the sine of the angles they make); folded when det is below minus that.
constexpr double kStillEdge = 1e-5, kFlatSine = 1e-3;

} // namespace

void measureInvertibility(const Context& ctx, CheckFigures& figures, glm::vec3& worstFold) {
    const Lut3D& t = ctx.table();
    const int cells = ctx.cellsPerAxis();
    const double volume = lut::math::pow(1.0 / cells, 3.0); // of a cell in normalised input, cubed
    std::vector<double> dets(static_cast<std::size_t>(cells) * cells * cells * 6);
    std::vector<double> volumes(dets.size()); // signed, per unit of input volume
    parallelFor(cells, ctx.nthreads(), [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b)
            for (int g = 0; g < cells; ++g)
                for (int r = 0; r < cells; ++r) {
                    const std::size_t base = 6 * static_cast<std::size_t>(ctx.cellIndex(r, g, b));
                    for (std::size_t k = 0; k < kPaths.size(); ++k) {
                        glm::ivec3 p(r, g, b);
                        glm::dvec3 prev(t.at(p.x, p.y, p.z));
                        glm::dvec3 col[3];
                        for (int s = 0; s < 3; ++s) {
                            const int axis = kPaths[k][static_cast<std::size_t>(s)];
                            ++p[axis];
                            const glm::dvec3 next(t.at(p.x, p.y, p.z));
                            col[axis] = next - prev;
                            prev = next;
                        }
                        const double l0 = glm::length(col[0]), l1 = glm::length(col[1]),
                                     l2 = glm::length(col[2]);
                        const double still = kStillEdge / cells;
                        dets[base + k] =
                            l0 < still || l1 < still || l2 < still
                                ? 0.0
                                : glm::dot(col[0], glm::cross(col[1], col[2])) / (l0 * l1 * l2);
                        volumes[base + k] = dets[base + k] * l0 * l1 * l2 / volume;
                    }
                }
    });
    // The LUT's orientation is the sign of its total volume (a negative LUT is turned over
    // everywhere, and that is one-to-one).
    double total = 0.0;
    for (double v : volumes)
        total += v;
    const double sign = total < 0.0 ? -1.0 : 1.0;
    double folded = 0.0, flat = 0.0, worst = 0.0;
    std::size_t worstCell = 0;
    for (std::size_t i = 0; i < dets.size(); ++i) {
        const double d = sign * dets[i];
        const double w = ctx.cellWeight(static_cast<std::uint32_t>(i / 6)) / 6.0;
        if (std::fabs(d) <= kFlatSine)
            flat += w;
        else if (d < 0.0) {
            folded += w;
            if (d < worst) {
                worst = d;
                worstCell = i / 6;
            }
        }
    }
    figures.foldedShare = folded;
    figures.flatShare = flat;
    const int r = static_cast<int>(worstCell % cells);
    const int g = static_cast<int>((worstCell / cells) % cells);
    const int b = static_cast<int>(worstCell / (static_cast<std::size_t>(cells) * cells));
    worstFold = (glm::vec3(r, g, b) + 0.5f) / static_cast<float>(cells);
}

void measureGamut(const Context& ctx, CheckFigures& figures) {
    // 65 samples per axis of the input domain; the outputs land in 16 bins per axis of [0, 1]:
    // a LUT whose slope stays under 4 hits every bin it passes through.
    constexpr int kSamples = 65, kBins = 16;
    std::vector<glm::vec3> colours;
    colours.reserve(static_cast<std::size_t>(kSamples) * kSamples * kSamples);
    const glm::vec3 lo = ctx.inputMin(), hi = ctx.inputMax();
    for (int b = 0; b < kSamples; ++b)
        for (int g = 0; g < kSamples; ++g)
            for (int r = 0; r < kSamples; ++r)
                colours.push_back(lo + (hi - lo) * glm::vec3(r, g, b) / float(kSamples - 1));
    ctx.evaluate(colours);
    std::vector<char> hit(kBins * kBins * kBins, 0);
    for (const glm::vec3& c : colours) {
        int idx[3];
        bool inside = true;
        for (int k = 0; k < 3; ++k) {
            if (!(c[k] >= 0.0f && c[k] <= 1.0f))
                inside = false;
            idx[k] = std::clamp(static_cast<int>(c[k] * kBins), 0, kBins - 1);
        }
        if (inside)
            hit[static_cast<std::size_t>(idx[0] + kBins * (idx[1] + kBins * idx[2]))] = 1;
    }
    std::size_t count = 0;
    for (char h : hit)
        count += h ? 1 : 0;
    figures.gamutCoverage = static_cast<double>(count) / static_cast<double>(hit.size());
}

} // namespace lut::check
