// SPDX-License-Identifier: Apache-2.0
#include "StorageError.h"

#include "lut/interp/Sampler.h"
#include "lut/ops/ErrorBound.h"

#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace lut::formats {

namespace {

// The steepest slope of a table's interpolant: [axis][channel] = the largest |change| of the
// channel along an edge of a cell parallel to the axis, per unit of input. Tetrahedral and
// trilinear interpolation step along such edges, so no slope of either is steeper.
glm::dmat3 cubeSlopes(const Lut3D& cube) {
    glm::dmat3 out(0.0);
    const int n = cube.size();
    for (int axis = 0; axis < 3; ++axis) {
        const double h = (double(cube.domainMax()[axis]) - cube.domainMin()[axis]) / (n - 1);
        for (int b = 0; b < n; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r) {
                    int q[3] = {r, g, b};
                    if (++q[axis] >= n)
                        continue;
                    const glm::vec3 d = cube.at(q[0], q[1], q[2]) - cube.at(r, g, b);
                    for (int c = 0; c < 3; ++c)
                        out[axis][c] = std::max(out[axis][c], std::fabs(double(d[c])) / h);
                }
    }
    return out;
}

// The same per slab: [axis][i] = the steepest slope per channel of the cells between lattice
// planes i and i + 1 along the axis (over every other index).
std::vector<std::vector<glm::dvec3>> slabSlopes(const Lut3D& cube) {
    const int n = cube.size();
    std::vector<std::vector<glm::dvec3>> out(3, std::vector<glm::dvec3>(n - 1, glm::dvec3(0.0)));
    for (int axis = 0; axis < 3; ++axis) {
        const double h = (double(cube.domainMax()[axis]) - cube.domainMin()[axis]) / (n - 1);
        for (int b = 0; b < n; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r) {
                    int q[3] = {r, g, b};
                    const int i = q[axis];
                    if (++q[axis] >= n)
                        continue;
                    const glm::vec3 d = cube.at(q[0], q[1], q[2]) - cube.at(r, g, b);
                    glm::dvec3& s =
                        out[static_cast<std::size_t>(axis)][static_cast<std::size_t>(i)];
                    for (int c = 0; c < 3; ++c)
                        s[c] = std::max(s[c], std::fabs(double(d[c])) / h);
                }
    }
    return out;
}

// A shaper's channel at x, in double: linear between entries, clamped outside its domain.
double shaperAt(const Lut1D& sh, int c, double x) {
    const int n = sh.size();
    const double lo = sh.domainMin()[c], hi = sh.domainMax()[c];
    const double t = std::clamp((x - lo) / (hi - lo), 0.0, 1.0) * (n - 1);
    const int i = std::min(static_cast<int>(t), n - 2);
    const double f = t - i;
    return double(sh[i][c]) + f * (double(sh[i + 1][c]) - double(sh[i][c]));
}

void addKnots(std::vector<double>& x, const Lut1D& sh, int c) {
    const int n = sh.size();
    const double lo = sh.domainMin()[c], hi = sh.domainMax()[c];
    for (int i = 0; i < n; ++i)
        x.push_back(lo + (hi - lo) * i / (n - 1));
}

bool oneTable(const Lut3D& a, const Lut3D& b) {
    return a.size() == b.size() && a.domainMin() == b.domainMin() && a.domainMax() == b.domainMax();
}

double largestEntryChange(const Lut3D& a, const Lut3D& b) {
    double m = 0.0;
    const auto& x = a.entries();
    const auto& y = b.entries();
    for (std::size_t i = 0; i < x.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = std::fabs(double(x[i][c]) - double(y[i][c]));
            m = std::isnan(d) ? INFINITY : std::max(m, d);
        }
    return m;
}

// Two shapers over one table: see the header.
double boundShapersOverOneTable(const LutFile& written, const LutFile& back) {
    const Lut3D& cube = *written.cube;
    const auto slopes = slabSlopes(cube);
    const int m = cube.size();
    glm::dvec3 total(largestEntryChange(cube, *back.cube));
    for (int a = 0; a < 3; ++a) {
        std::vector<double> x;
        addKnots(x, *written.shaper, a);
        addKnots(x, *back.shaper, a);
        std::sort(x.begin(), x.end());
        x.erase(std::unique(x.begin(), x.end()), x.end());
        const double c0 = cube.domainMin()[a], c1 = cube.domainMax()[a];
        auto cellOf = [&](double u) {
            return std::clamp((u - c0) / (c1 - c0) * (m - 1), 0.0, double(m - 1));
        };
        glm::dvec3 worst(0.0);
        // Both shapers are linear between consecutive knots (and constant outside them), so
        // their difference is largest at a piece's ends, and the shaped inputs stay within the
        // span of the ends' values.
        for (std::size_t k = 0; k + 1 < x.size(); ++k) {
            const double w0 = shaperAt(*written.shaper, a, x[k]);
            const double w1 = shaperAt(*written.shaper, a, x[k + 1]);
            const double b0 = shaperAt(*back.shaper, a, x[k]);
            const double b1 = shaperAt(*back.shaper, a, x[k + 1]);
            const double d = std::max(std::fabs(w0 - b0), std::fabs(w1 - b1));
            if (!(d > 0.0)) {
                if (std::isnan(d))
                    return INFINITY;
                continue;
            }
            const double p0 = cellOf(std::min({w0, w1, b0, b1}));
            const double p1 = cellOf(std::max({w0, w1, b0, b1}));
            const int i0 = std::min(static_cast<int>(p0), m - 2);
            const int i1 = std::max(i0, std::min(static_cast<int>(std::ceil(p1)) - 1, m - 2));
            glm::dvec3 s(0.0);
            for (int i = i0; i <= i1; ++i)
                s = glm::max(s, slopes[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)]);
            worst = glm::max(worst, s * d);
        }
        total += worst;
    }
    return std::max({total.x, total.y, total.z});
}

// A fixed sequence in [0, 1): splitmix64.
double unitRandom(std::uint64_t i) {
    std::uint64_t z = (i + 1) * 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) / 9007199254740992.0;
}

} // namespace

ErrorStats storageError(const LutFile& written, const LutFile& back) {
    const bool sameShape =
        written.cube && back.cube && oneTable(*written.cube, *back.cube) &&
        written.shaper.has_value() == back.shaper.has_value() &&
        (!written.shaper || (written.shaper->size() == back.shaper->size() &&
                             written.shaper->domainMin() == back.shaper->domainMin() &&
                             written.shaper->domainMax() == back.shaper->domainMax()));
    if (sameShape) {
        // One lattice: the cubes' interpolants differ by at most their largest entry difference,
        // and a shaper stored differently moves each lookup in the cube by at most its largest
        // entry difference per channel, which changes the output by at most the cube's slope
        // times that.
        ErrorAccumulator acc;
        const auto& a = written.cube->entries();
        const auto& b = back.cube->entries();
        for (std::size_t i = 0; i < a.size(); ++i)
            for (int c = 0; c < 3; ++c)
                acc.add(a[i][c], b[i][c]);
        ErrorStats s = acc.result();
        if (written.shaper) {
            glm::dvec3 moved(0.0);
            for (int i = 0; i < written.shaper->size(); ++i)
                for (int c = 0; c < 3; ++c)
                    moved[c] = std::max(moved[c], std::fabs(double((*written.shaper)[i][c]) -
                                                            double((*back.shaper)[i][c])));
            if (moved != glm::dvec3(0.0)) {
                const glm::dmat3 slope = cubeSlopes(*written.cube);
                double worst = 0.0;
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, slope[0][c] * moved[0] + slope[1][c] * moved[1] +
                                                slope[2][c] * moved[2]);
                s.maxAbs += worst;
            }
        }
        s.bounded = true;
        s.sampledMax = s.maxAbs;
        return s;
    }

    // The two as files, on pseudo-random inputs of the written file's domain: the mean.
    const auto w = makeSampler(written, Interpolation::Tetrahedral);
    const auto r = makeSampler(back, Interpolation::Tetrahedral);
    const glm::dvec3 lo(written.inputDomainMin()), hi(written.inputDomainMax());
    ErrorAccumulator acc;
    constexpr int kPoints = 65536;
    for (int i = 0; i < kPoints; ++i) {
        glm::vec3 x;
        for (int c = 0; c < 3; ++c)
            x[c] = static_cast<float>(
                lo[c] + (hi[c] - lo[c]) * unitRandom(3 * static_cast<std::uint64_t>(i) + c));
        const glm::vec3 a = w->sample(x), b = r->sample(x);
        for (int c = 0; c < 3; ++c)
            acc.add(a[c], b[c]);
    }
    ErrorStats s = acc.result();
    s.sampledMax = s.maxAbs;
    if (written.shaper && back.shaper && written.cube && back.cube &&
        oneTable(*written.cube, *back.cube)) {
        s.maxAbs = std::max(s.sampledMax, boundShapersOverOneTable(written, back));
        s.heldOutPoints = kPoints;
        s.bounded = true;
        return s;
    }
    // Anything else: bounded between the points of the finer table (its planes, and the other
    // table's, in the grid when neither has a shaper).
    BoundOptions o;
    o.lo = lo;
    o.hi = hi;
    o.cells =
        std::max(written.cube ? written.cube->size() : 2, back.cube ? back.cube->size() : 2) - 1;
    if (!written.shaper && !back.shaper && written.cube && back.cube) {
        o.breaks = latticeBreaks(*written.cube, Interpolation::Tetrahedral);
        addBreaks(o.breaks, latticeBreaks(*back.cube, Interpolation::Tetrahedral));
    }
    const ErrorStats b = boundError(
        [&](const glm::dvec3* in, glm::dvec3* diff, std::size_t n) {
            for (std::size_t i = 0; i < n; ++i) {
                const glm::vec3 x(in[i]);
                diff[i] = glm::dvec3(w->sample(x)) - glm::dvec3(r->sample(x));
            }
        },
        o);
    s.maxAbs = std::max(s.sampledMax, b.maxAbs);
    s.sampledMax = std::max(s.sampledMax, b.sampledMax);
    s.heldOutPoints = kPoints + b.heldOutPoints;
    s.bounded = true;
    return s;
}

} // namespace lut::formats
