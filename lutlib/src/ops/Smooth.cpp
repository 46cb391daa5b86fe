#include "lut/ops/Smooth.h"

#include "lut/Error.h"
#include "lut/Parallel.h"
#include "lut/ops/Resample.h"
#include "ops/OpsDetail.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lut {

namespace {

// One pass of the kernel along axis `axis` (0 = red, 1 = green, 2 = blue) of an n^3 grid of
// deviations. Past an edge the deviation is extended by point reflection about the edge entry
// (d(-k) = 2 d(0) - d(k)), which keeps linear trends, so nothing is pulled towards the middle.
void blurAxis(std::vector<glm::dvec3>& d, int n, int axis, const std::vector<double>& kernel,
              int nthreads) {
    const int radius = static_cast<int>(kernel.size()) - 1;
    const std::size_t stride = axis == 0   ? 1
                               : axis == 1 ? static_cast<std::size_t>(n)
                                           : static_cast<std::size_t>(n) * n;
    std::vector<glm::dvec3> out(d.size());
    // Lines along the axis are indexed by the other two coordinates (u, v).
    parallelFor(n, n < 17 ? 1 : nthreads, [&](int v0, int v1) {
        std::vector<glm::dvec3> line(static_cast<std::size_t>(n));
        for (int v = v0; v < v1; ++v)
            for (int u = 0; u < n; ++u) {
                std::size_t base;
                if (axis == 0)
                    base = static_cast<std::size_t>(n) * (u + static_cast<std::size_t>(n) * v);
                else if (axis == 1)
                    base = u + static_cast<std::size_t>(n) * n * v;
                else
                    base = u + static_cast<std::size_t>(n) * v;
                for (int i = 0; i < n; ++i)
                    line[static_cast<std::size_t>(i)] = d[base + stride * i];
                auto at = [&](int i) {
                    if (i < 0)
                        return 2.0 * line[0] - line[static_cast<std::size_t>(std::min(-i, n - 1))];
                    if (i > n - 1)
                        return 2.0 * line[static_cast<std::size_t>(n - 1)] -
                               line[static_cast<std::size_t>(std::max(2 * (n - 1) - i, 0))];
                    return line[static_cast<std::size_t>(i)];
                };
                for (int i = 0; i < n; ++i) {
                    glm::dvec3 acc = kernel[0] * line[static_cast<std::size_t>(i)];
                    for (int k = 1; k <= radius; ++k)
                        acc += kernel[static_cast<std::size_t>(k)] * (at(i - k) + at(i + k));
                    out[base + stride * i] = acc;
                }
            }
    });
    d.swap(out);
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
        kernel[static_cast<std::size_t>(k)] = std::exp(-0.5 * k * k / (sigma * sigma));
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
