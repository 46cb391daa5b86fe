// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Smooth.h"

#include "lut/Error.h"
#include "lut/Math.h"
#include "lut/Parallel.h"
#include "lut/ops/CompareLuts.h"
#include "ops/OpsDetail.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lut {

namespace {

// One pass of the kernel along axis `axis` (0 = red, 1 = green, 2 = blue) of an n^3 grid of
// deviations. Past an edge the deviation is extended by point reflection about the edge entry
// (d(-k) = 2 d(0) - d(k), repeated while the index is outside), which keeps linear trends, so
// nothing is pulled towards the middle.
// Works on slabs of whole red rows (contiguous in memory) so the strided axes stay cache-friendly.
void blurAxis(std::vector<glm::dvec3>& d, int n, int axis, const std::vector<double>& kernel,
              int nthreads) {
    const int radius = static_cast<int>(kernel.size()) - 1;
    const std::size_t nn = static_cast<std::size_t>(n);
    // Element (i along the axis, u along the row, v the remaining axis) is at
    // v * sv + i * si + u * su.
    const std::size_t si = axis == 0 ? 1 : axis == 1 ? nn : nn * nn;
    const std::size_t su = axis == 0 ? nn : 1;
    const std::size_t sv = axis == 2 ? nn : nn * nn;
    parallelFor(n, n < 17 ? 1 : nthreads, [&](int v0, int v1) {
        std::vector<glm::dvec3> slab(nn * nn), out(nn * nn);
        // Copies between d and a slab in d's memory order.
        auto transfer = [&](std::size_t base, std::vector<glm::dvec3>& s, bool toSlab) {
            auto one = [&](std::size_t i, std::size_t u) {
                glm::dvec3& x = d[base + i * si + u * su];
                if (toSlab)
                    s[i * nn + u] = x;
                else
                    x = s[i * nn + u];
            };
            if (si == 1) {
                for (std::size_t u = 0; u < nn; ++u)
                    for (std::size_t i = 0; i < nn; ++i)
                        one(i, u);
            } else {
                for (std::size_t i = 0; i < nn; ++i)
                    for (std::size_t u = 0; u < nn; ++u)
                        one(i, u);
            }
        };
        // Reflections repeat until the index is inside: a kernel wider than the lattice (sigma 2
        // on a 3^3 LUT) still sees a linear trend continued, not the far edge repeated.
        auto at = [&](int j, std::size_t u) {
            auto row = [&](int k) { return slab[static_cast<std::size_t>(k) * nn + u]; };
            glm::dvec3 sum(0.0);
            double sign = 1.0;
            for (;;) {
                if (j < 0) {
                    sum += sign * 2.0 * row(0);
                    sign = -sign;
                    j = -j;
                } else if (j > n - 1) {
                    sum += sign * 2.0 * row(n - 1);
                    sign = -sign;
                    j = 2 * (n - 1) - j;
                } else {
                    return sum + sign * row(j);
                }
            }
        };
        for (int v = v0; v < v1; ++v) {
            const std::size_t base = static_cast<std::size_t>(v) * sv;
            transfer(base, slab, true);
            for (int i = 0; i < n; ++i) {
                glm::dvec3* acc = &out[static_cast<std::size_t>(i) * nn];
                for (std::size_t u = 0; u < nn; ++u)
                    acc[u] = kernel[0] * slab[static_cast<std::size_t>(i) * nn + u];
                for (int k = 1; k <= radius; ++k) {
                    const double w = kernel[static_cast<std::size_t>(k)];
                    if (i - k >= 0 && i + k <= n - 1) {
                        const glm::dvec3* lo = &slab[static_cast<std::size_t>(i - k) * nn];
                        const glm::dvec3* hi = &slab[static_cast<std::size_t>(i + k) * nn];
                        for (std::size_t u = 0; u < nn; ++u)
                            acc[u] += w * (lo[u] + hi[u]);
                    } else {
                        for (std::size_t u = 0; u < nn; ++u)
                            acc[u] += w * (at(i - k, u) + at(i + k, u));
                    }
                }
            }
            transfer(base, out, false);
        }
    });
}

} // namespace

OpResult smooth(const Lut3D& lut, double sigma, int nthreads) {
    if (lut.empty())
        throw Error("smooth: the LUT has no entries");
    const long long t0 = detail::nowNanos();
    OpResult result;
    const Lut3D source = detail::sanitizedCopy(lut, result.sanitizedEntries);
    result.lut = source;
    if (std::isnan(sigma) || sigma <= 0.0) {
        result.error.count = source.entryCount() * 3;
        return result;
    }
    sigma = std::min(sigma, 8.0);
    const int radius = static_cast<int>(std::ceil(3.0 * sigma));
    std::vector<double> kernel(static_cast<std::size_t>(radius) + 1);
    double sum = 0.0;
    for (int k = 0; k <= radius; ++k) {
        kernel[static_cast<std::size_t>(k)] = lut::math::exp(-0.5 * k * k / (sigma * sigma));
        sum += (k == 0 ? 1.0 : 2.0) * kernel[static_cast<std::size_t>(k)];
    }
    for (double& k : kernel)
        k /= sum;
    const int n = source.size();
    std::vector<glm::dvec3> dev(source.entryCount());
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                dev[source.index(r, g, b)] =
                    glm::dvec3(source.at(r, g, b)) - glm::dvec3(source.latticeInput(r, g, b));
    for (int axis = 0; axis < 3; ++axis)
        blurAxis(dev, n, axis, kernel, nthreads);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::dvec3 v =
                    glm::dvec3(source.latticeInput(r, g, b)) + dev[source.index(r, g, b)];
                result.lut.at(r, g, b) = glm::vec3(detail::sanitizeValue(static_cast<float>(v.x)),
                                                   detail::sanitizeValue(static_cast<float>(v.y)),
                                                   detail::sanitizeValue(static_cast<float>(v.z)));
            }
    const double seconds = detail::secondsSince(t0);
    result.error =
        compareLuts(source, result.lut, Interpolation::Tetrahedral, detail::probeCount(n));
    result.error.seconds = seconds;
    return result;
}

} // namespace lut
