// SPDX-License-Identifier: Apache-2.0
// Sliced Wasserstein and quantile ΔE2000 between colour distributions: see
// lut/match/DistributionDistance.h.
#include "lut/match/DistributionDistance.h"

#include "lut/Math.h"
#include "lut/Parallel.h"
#include "lut/ops/ColorDifference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace lut {

namespace {

constexpr int kBins = 4096;

// Quantiles at the levels (i + 0.5) / count (or `levels`) of weighted values.
void quantiles(const std::vector<double>& values, const std::vector<float>& weights,
               const std::vector<double>& levels, double* out) {
    double lo = INFINITY, hi = -INFINITY;
    for (double v : values) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    if (!(hi > lo)) {
        for (std::size_t i = 0; i < levels.size(); ++i)
            out[i] = std::isfinite(lo) ? lo : 0.0;
        return;
    }
    std::vector<double> counts(kBins, 0.0);
    const double scale = kBins / (hi - lo);
    double total = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double w = weights.empty() ? 1.0 : weights[i];
        const int k = std::min(kBins - 1, static_cast<int>((values[i] - lo) * scale));
        counts[static_cast<std::size_t>(k)] += w;
        total += w;
    }
    double cum = 0.0;
    int k = 0;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const double target = levels[i] * total;
        while (k < kBins - 1 && cum + counts[static_cast<std::size_t>(k)] < target) {
            cum += counts[static_cast<std::size_t>(k)];
            ++k;
        }
        const double c = counts[static_cast<std::size_t>(k)];
        const double t = c > 0.0 ? std::clamp((target - cum) / c, 0.0, 1.0) : 0.0;
        out[i] = lo + (k + t) / scale;
    }
}

std::vector<double> uniformLevels(int count, double first, double last) {
    std::vector<double> l(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i)
        l[static_cast<std::size_t>(i)] =
            count == 1 ? first : first + (last - first) * i / (count - 1);
    return l;
}

} // namespace

const std::vector<glm::dvec3>& ColourDistribution::directions() {
    // A Fibonacci lattice on the half sphere (a direction and its opposite give the same
    // distance): even coverage, no random numbers.
    static const std::vector<glm::dvec3> dirs = [] {
        std::vector<glm::dvec3> d;
        const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
        for (int i = 0; i < kDirections; ++i) {
            const double z = 1.0 - (i + 0.5) / kDirections; // (0, 1]
            const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
            d.emplace_back(r * lut::math::cos(golden * i), r * lut::math::sin(golden * i), z);
        }
        return d;
    }();
    return dirs;
}

ColourDistribution::ColourDistribution(const std::vector<glm::vec3>& lab,
                                       const std::vector<float>& weights, int nthreads) {
    std::vector<glm::dvec3> colours;
    std::vector<float> w;
    colours.reserve(lab.size());
    for (std::size_t i = 0; i < lab.size(); ++i) {
        const glm::vec3& c = lab[i];
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
            continue;
        if (!weights.empty() && !(weights[i] > 0.0f))
            continue;
        colours.emplace_back(c);
        if (!weights.empty())
            w.push_back(weights[i]);
    }
    if (colours.empty())
        return;
    const auto levels = uniformLevels(kLevels, 0.5 / kLevels, 1.0 - 0.5 / kLevels);
    m_projections.assign(static_cast<std::size_t>(kDirections) * kLevels, 0.0);
    const auto& dirs = directions();
    parallelFor(kDirections, nthreads, [&](int begin, int end) {
        std::vector<double> values(colours.size());
        for (int d = begin; d < end; ++d) {
            for (std::size_t i = 0; i < colours.size(); ++i)
                values[i] = glm::dot(colours[i], dirs[static_cast<std::size_t>(d)]);
            quantiles(values, w, levels, &m_projections[static_cast<std::size_t>(d) * kLevels]);
        }
    });
    m_channels.assign(kChannelLevels, glm::dvec3(0.0));
    const auto channelLevels = uniformLevels(kChannelLevels, 0.01, 0.99);
    std::vector<double> values(colours.size()), out(kChannelLevels);
    for (int c = 0; c < 3; ++c) {
        for (std::size_t i = 0; i < colours.size(); ++i)
            values[i] = colours[i][c];
        quantiles(values, w, channelLevels, out.data());
        for (int i = 0; i < kChannelLevels; ++i)
            m_channels[static_cast<std::size_t>(i)][c] = out[static_cast<std::size_t>(i)];
    }
}

DistributionDistance distributionDistance(const ColourDistribution& a,
                                          const ColourDistribution& b) {
    DistributionDistance d;
    if (a.empty() || b.empty())
        return d;
    const auto& pa = a.projectionQuantiles();
    const auto& pb = b.projectionQuantiles();
    double sum = 0.0;
    for (std::size_t i = 0; i < pa.size(); ++i)
        sum += (pa[i] - pb[i]) * (pa[i] - pb[i]);
    d.slicedWasserstein = std::sqrt(sum / static_cast<double>(pa.size()));
    const auto& ca = a.channelQuantiles();
    const auto& cb = b.channelQuantiles();
    double de = 0.0;
    for (std::size_t i = 0; i < ca.size(); ++i)
        de += deltaE2000(ca[i], cb[i]);
    d.quantileDeltaE = de / static_cast<double>(ca.size());
    return d;
}

} // namespace lut
