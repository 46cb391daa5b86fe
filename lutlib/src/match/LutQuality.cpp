// SPDX-License-Identifier: Apache-2.0
// Monotonicity, fold-overs and smoothness of a LUT file: see lut/match/LutQuality.h.
#include "lut/match/LutQuality.h"

#include "lut/interp/Sampler.h"
#include "lut/match/WorkingSpace.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lut {

struct LutFileSampler::Impl {
    std::optional<Lut1D> shaper;
    std::unique_ptr<Sampler> table;
};

LutFileSampler::LutFileSampler(const LutFile& lut, Interpolation interp)
    : m_impl(std::make_unique<Impl>()) {
    m_impl->shaper = lut.shaper;
    if (lut.cube)
        m_impl->table = makeSampler(*lut.cube, interp);
}

LutFileSampler::~LutFileSampler() = default;
LutFileSampler::LutFileSampler(LutFileSampler&&) noexcept = default;

glm::vec3 LutFileSampler::operator()(glm::vec3 in) const {
    if (m_impl->shaper)
        in = m_impl->shaper->apply(in);
    return m_impl->table ? m_impl->table->sample(in) : in;
}

void LutFileSampler::applyPixels(float* rgba, std::size_t count) const {
    if (m_impl->shaper)
        for (std::size_t i = 0; i < count; ++i) {
            float* p = rgba + 4 * i;
            const glm::vec3 v = m_impl->shaper->apply(glm::vec3(p[0], p[1], p[2]));
            p[0] = v.x;
            p[1] = v.y;
            p[2] = v.z;
        }
    if (m_impl->table)
        m_impl->table->applyPixels(rgba, count);
}

namespace {
std::string fmt3(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}
} // namespace

std::string LutQuality::str() const {
    char buf[512];
    const bool monotone = decreasingSteps == 0;
    std::snprintf(
        buf, sizeof buf,
        "%s along each channel's own axis (slopes %.3g..%.3g), %s along grey; %s; "
        "largest second difference %.3g 8-bit steps",
        monotone ? "monotone" : "NOT monotone", smallestSlope, largestSlope,
        monotoneAlongGrey
            ? "monotone"
            : ("NOT monotone (down by up to " + fmt3(largestGreyDrop) + " 8-bit steps)").c_str(),
        ((foldedCells == 0
              ? std::string("no fold-overs")
              : std::to_string(foldedCells) + " of " + std::to_string(cells) + " cells folded") +
         (flatCells == 0 ? std::string()
                         : " (" + std::to_string(flatCells) + " flat: colours merged)"))
            .c_str(),
        largestSecondDifference);
    std::string s = buf;
    if (decreasingSteps > 0)
        s += " (" + std::to_string(decreasingSteps) + " of " + std::to_string(steps) +
             " steps go down)";
    return s;
}

LutQuality measureLutQuality(const LutFile& lut, bool linear, const glm::dvec3& domainMin,
                             const glm::dvec3& domainMax, Interpolation interp, int grid) {
    LutQuality q;
    grid = std::clamp(grid, 3, 129);
    q.grid = grid;
    const LutFileSampler f(lut, interp);
    glm::dvec3 w0, w1;
    for (int c = 0; c < 3; ++c) {
        w0[c] = encodeWorking(domainMin[c], linear);
        w1[c] = encodeWorking(domainMax[c], linear);
    }
    const std::size_t n = static_cast<std::size_t>(grid);
    std::vector<glm::dvec3> out(n * n * n);
    auto at = [&](std::size_t r, std::size_t g, std::size_t b) -> glm::dvec3& {
        return out[r + n * (g + n * b)];
    };
    const glm::dvec3 step = (w1 - w0) / static_cast<double>(grid - 1);
    for (std::size_t b = 0; b < n; ++b)
        for (std::size_t g = 0; g < n; ++g)
            for (std::size_t r = 0; r < n; ++r) {
                const glm::dvec3 w = w0 + step * glm::dvec3(r, g, b);
                glm::vec3 x;
                for (int c = 0; c < 3; ++c)
                    x[c] = static_cast<float>(decodeWorking(w[c], linear));
                const glm::vec3 y = f(x);
                glm::dvec3& o = at(r, g, b);
                for (int c = 0; c < 3; ++c)
                    o[c] = encodeWorking(y[c], linear);
            }
    q.smallestSlope = INFINITY;
    q.largestSlope = 0.0;
    for (std::size_t b = 0; b < n; ++b)
        for (std::size_t g = 0; g < n; ++g)
            for (std::size_t r = 0; r < n; ++r) {
                const std::size_t idx[3] = {r, g, b};
                for (int c = 0; c < 3; ++c) {
                    const std::size_t i = idx[c];
                    auto neighbour = [&](std::ptrdiff_t d) {
                        std::size_t j[3] = {r, g, b};
                        j[c] = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + d);
                        return at(j[0], j[1], j[2]);
                    };
                    if (i + 1 < n) {
                        const double d = neighbour(1)[c] - at(r, g, b)[c];
                        ++q.steps;
                        if (d < -1e-6)
                            ++q.decreasingSteps;
                        const double slope = d / step[c];
                        q.smallestSlope = std::min(q.smallestSlope, slope);
                        q.largestSlope = std::max(q.largestSlope, slope);
                    }
                    if (i >= 1 && i + 1 < n) {
                        const glm::dvec3 d2 = neighbour(1) - 2.0 * at(r, g, b) + neighbour(-1);
                        for (int k = 0; k < 3; ++k)
                            q.largestSecondDifference =
                                std::max(q.largestSecondDifference, std::fabs(d2[k]) * 255.0);
                    }
                }
                if (r + 1 < n && g + 1 < n && b + 1 < n) {
                    ++q.cells;
                    glm::dmat3 j(0.0); // column c: the derivative along axis c
                    for (int corner = 0; corner < 4; ++corner) {
                        const std::size_t u = corner & 1, v = (corner >> 1) & 1;
                        j[0] += at(r + 1, g + u, b + v) - at(r, g + u, b + v);
                        j[1] += at(r + u, g + 1, b + v) - at(r + u, g, b + v);
                        j[2] += at(r + u, g + v, b + 1) - at(r + u, g + v, b);
                    }
                    // Negative: the cell is turned over; zero (to round-off): flat, its colours
                    // merged (a curve that holds a value past the picture's range), no fold.
                    const double det = glm::determinant(j);
                    double scale = 1.0;
                    for (int c = 0; c < 3; ++c)
                        scale *= glm::length(j[c]);
                    if (!(det >= -1e-9 * scale))
                        ++q.foldedCells;
                    else if (!(det > 1e-9 * scale))
                        ++q.flatCells;
                }
            }
    // The grey axis, finer than the grid.
    constexpr int kGreySteps = 256;
    q.smallestGreySlope = INFINITY;
    glm::dvec3 prev(0.0), peak(-INFINITY);
    for (int i = 0; i <= kGreySteps; ++i) {
        const double t = static_cast<double>(i) / kGreySteps;
        glm::vec3 x;
        for (int c = 0; c < 3; ++c)
            x[c] = static_cast<float>(decodeWorking(w0[c] + (w1[c] - w0[c]) * t, linear));
        const glm::vec3 y = f(x);
        glm::dvec3 o;
        for (int c = 0; c < 3; ++c)
            o[c] = encodeWorking(y[c], linear);
        if (i > 0)
            for (int c = 0; c < 3; ++c) {
                const double d = o[c] - prev[c];
                if (d < -1e-6)
                    q.monotoneAlongGrey = false;
                q.largestGreyDrop = std::max(q.largestGreyDrop, (peak[c] - o[c]) * 255.0);
                q.smallestGreySlope =
                    std::min(q.smallestGreySlope, d * kGreySteps / std::max(w1[c] - w0[c], 1e-12));
            }
        prev = o;
        peak = glm::max(peak, o);
    }
    if (!std::isfinite(q.smallestSlope))
        q.smallestSlope = 0.0;
    if (!std::isfinite(q.smallestGreySlope))
        q.smallestGreySlope = 0.0;
    return q;
}

} // namespace lut
