// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Lattice.h"

#include "lut/Error.h"
#include "lut/Math.h"
#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/ErrorBound.h"
#include "ops/OpsDetail.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

namespace lut {

namespace {

// At most this many planes per axis come from the shaper (its entries inside the domain, then
// where it crosses the table's planes); past that the slope term covers its kinks.
constexpr std::size_t kMaxShaperPlanes = 256;

// The one filter of fileBreaks and shaperBreaks: x strictly inside the domain on axis a (a kink
// at an edge is no break between lattice points).
bool insideDomain(double x, glm::vec3 lo, glm::vec3 hi, int a) {
    return x > lo[a] && x < hi[a];
}

// Per axis: the inputs in (lo, hi) where the file's shaper kinks (its entries) and where it
// crosses one of its table's lattice planes (the composition kinks there too).
Breaks shaperBreaks(const LutFile& file, glm::vec3 lo, glm::vec3 hi) {
    Breaks out;
    const Lut1D& sh = *file.shaper;
    const int n = sh.size();
    for (int a = 0; a < 3; ++a) {
        const double d0 = sh.domainMin()[a], d1 = sh.domainMax()[a];
        auto inputOf = [&](double i) { return d0 + (d1 - d0) * i / (n - 1); };
        std::vector<double> knots, crossings;
        for (int i = 0; i < n; ++i) {
            const double x = inputOf(i);
            if (insideDomain(x, lo, hi, a))
                knots.push_back(x);
        }
        if (file.cube) {
            const int m = file.cube->size();
            const double c0 = file.cube->domainMin()[a], c1 = file.cube->domainMax()[a];
            for (int i = 0; i + 1 < n; ++i) {
                const double y0 = sh[i][a], y1 = sh[i + 1][a];
                if (!(y0 != y1))
                    continue;
                // planes k with the plane's value strictly between y0 and y1
                const double p0 = (std::min(y0, y1) - c0) / (c1 - c0) * (m - 1);
                const double p1 = (std::max(y0, y1) - c0) / (c1 - c0) * (m - 1);
                for (double k = std::max(0.0, std::floor(p0) + 1); k < p1 && k <= m - 1; ++k) {
                    const double y = c0 + (c1 - c0) * k / (m - 1);
                    const double x = inputOf(i + (y - y0) / (y1 - y0));
                    if (insideDomain(x, lo, hi, a))
                        crossings.push_back(x);
                }
            }
        }
        auto& v = out[static_cast<std::size_t>(a)];
        if (knots.size() <= kMaxShaperPlanes)
            v = knots;
        if (v.size() + crossings.size() <= kMaxShaperPlanes)
            v.insert(v.end(), crossings.begin(), crossings.end());
    }
    return out;
}

} // namespace

Breaks fileBreaks(const LutFile& file, glm::vec3 lo, glm::vec3 hi) {
    if (file.shaper)
        return shaperBreaks(file, lo, hi);
    Breaks out;
    if (!file.cube)
        return out;
    // Held here: a range-for over an element of the temporary would read it after its end.
    const Breaks all = latticeBreaks(*file.cube, Interpolation::Tetrahedral);
    for (int a = 0; a < 3; ++a)
        for (const double x : all[static_cast<std::size_t>(a)])
            if (insideDomain(x, lo, hi, a))
                out[static_cast<std::size_t>(a)].push_back(x);
    return out;
}

LatticeResult sampleOnLattice(const LutFile& file, const LatticeRequest& q) {
    if (!file.cube && !file.shaper)
        throw Error("the LUT file holds no table");
    const auto t0 = std::chrono::steady_clock::now();
    const int size = q.size > 0 ? q.size : file.cube ? file.cube->size() : 33;
    const glm::vec3 lo = q.domainMin.value_or(file.inputDomainMin());
    const glm::vec3 hi = q.domainMax.value_or(file.inputDomainMax());
    LatticeResult res;
    res.lut = Lut3D(size);
    res.lut.setDomain(lo, hi); // throws for a bad domain
    res.lut.setTitle(file.cube ? file.cube->title() : file.shaper->title());
    if (file.cube)
        res.lut.comments() = file.cube->comments();
    const auto exact = makeSampler(file, q.fileMethod);
    Lut3D& out = res.lut;
    parallelFor(size, q.nthreads, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b)
            for (int g = 0; g < size; ++g)
                for (int r = 0; r < size; ++r) {
                    const glm::vec3 x = out.latticeInput(r, g, b);
                    const glm::vec3 y = exact->sample(x);
                    out.at(r, g, b) =
                        q.finish ? glm::vec3(q.finish(glm::dvec3(x), glm::dvec3(y))) : y;
                }
    });

    // The cost of reading the lattice instead of the file, bounded over the whole domain
    // (lut/ops/ErrorBound.h): held-out points between the lattice points, plus the slope between
    // them. The grid's planes are the lattice's, where the shaper kinks (its entries) and where
    // the shaper crosses the file's table's planes (where the composition kinks), so that the
    // difference is linear, or nearly, inside each box.
    const auto read = makeSampler(out, q.readWith);
    BoundOptions o;
    o.lo = glm::dvec3(lo);
    o.hi = glm::dvec3(hi);
    o.cells = size - 1;
    o.nthreads = q.nthreads;
    o.breaks = latticeBreaks(out, q.readWith);
    if (file.cube && !file.shaper)
        addBreaks(o.breaks, latticeBreaks(*file.cube, q.fileMethod));
    if (file.shaper)
        addBreaks(o.breaks, shaperBreaks(file, lo, hi));
    res.error = boundError(
        [&](const glm::dvec3* in, glm::dvec3* diff, std::size_t n) {
            for (std::size_t i = 0; i < n; ++i) {
                const glm::vec3 x(in[i]);
                const glm::dvec3 y(exact->sample(x));
                diff[i] = (q.finish ? q.finish(glm::dvec3(x), y) : y) - glm::dvec3(read->sample(x));
            }
        },
        o);
    res.heldOut = res.error.heldOutPoints;
    res.error.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
}

std::optional<ShaperLatticeResult> finishKeepingShaper(const LutFile& file,
                                                       const LatticeRequest& q) {
    if (!file.shaper || !file.cube)
        return std::nullopt;
    const auto t0 = std::chrono::steady_clock::now();
    const glm::vec3 lo = q.domainMin.value_or(file.inputDomainMin());
    const glm::vec3 hi = q.domainMax.value_or(file.inputDomainMax());
    const Lut1D& sh = *file.shaper;
    const int n = sh.size();
    std::vector<std::unique_ptr<detail::PiecewiseLinearInverse>> inv;
    for (int c = 0; c < 3; ++c) {
        const double d0 = sh.domainMin()[c], d1 = sh.domainMax()[c];
        std::vector<double> xs, ys;
        for (int i = 0; i < n; ++i) {
            const double x = d0 + (d1 - d0) * i / (n - 1);
            const double y = sh[i][c];
            // strictly increasing wherever it meets the domain
            if (i > 0 && !(y > ys.back()) && x > lo[c] && xs.back() < hi[c])
                return std::nullopt;
            xs.push_back(x);
            ys.push_back(std::isfinite(y) ? y : 0.0);
        }
        inv.push_back(std::make_unique<detail::PiecewiseLinearInverse>(xs, ys));
    }
    ShaperLatticeResult res;
    res.file = file;
    Lut3D& t = *res.file.cube;
    const int m = t.size();
    parallelFor(m, q.nthreads, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b)
            for (int g = 0; g < m; ++g)
                for (int r = 0; r < m; ++r) {
                    const glm::dvec3 u(t.latticeInput(r, g, b));
                    glm::dvec3 x;
                    for (int c = 0; c < 3; ++c)
                        x[c] = (*inv[static_cast<std::size_t>(c)])(u[c]).x;
                    const glm::dvec3 y(t.at(r, g, b));
                    t.at(r, g, b) = glm::vec3(q.finish ? q.finish(x, y) : y);
                }
    });
    const auto exact = makeSampler(file, q.fileMethod);
    const auto read = makeSampler(res.file, q.fileMethod);
    BoundOptions o;
    o.lo = glm::dvec3(lo);
    o.hi = glm::dvec3(hi);
    o.cells = m - 1;
    o.nthreads = q.nthreads;
    o.breaks = shaperBreaks(file, lo, hi);
    res.error = boundError(
        [&](const glm::dvec3* in, glm::dvec3* diff, std::size_t count) {
            for (std::size_t i = 0; i < count; ++i) {
                const glm::vec3 x(in[i]);
                const glm::dvec3 y(exact->sample(x));
                diff[i] = (q.finish ? q.finish(glm::dvec3(x), y) : y) - glm::dvec3(read->sample(x));
            }
        },
        o);
    res.error.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
}

} // namespace lut
