// SPDX-License-Identifier: Apache-2.0
#pragma once
// How far apart two pictures' colour distributions are, in CIELAB (the measure `lutkit match`
// reports before and after, and by which `auto` chooses):
//   sliced Wasserstein   the 2-Wasserstein distance of the projections on 64 fixed directions
//                        (spread evenly over the sphere), root mean square over the directions:
//                        sqrt(mean_d integral_0^1 (Qa_d(p) - Qb_d(p))^2 dp), with the quantile
//                        functions Q sampled at 256 levels; CIELAB units (about a ΔE76 each);
//   quantile ΔE2000      the mean CIEDE2000 (lut/ops/ColorDifference.h) between the colours made
//                        of the L*, a*, b* quantiles of each distribution at the levels 1%..99%:
//                        a perceptual "how far are the histograms" in the unit colourists know.
// Quantiles come from weighted histograms of 4096 bins between each projection's extremes.
#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace lut {

struct DistributionDistance {
    double slicedWasserstein = 0.0;
    double quantileDeltaE = 0.0;
};

class ColourDistribution {
public:
    ColourDistribution() = default;
    // CIELAB colours and their weights (empty weights = all 1); non-finite colours are ignored.
    // nthreads 0 = all cores.
    ColourDistribution(const std::vector<glm::vec3>& lab, const std::vector<float>& weights = {},
                       int nthreads = 0);
    bool empty() const { return m_projections.empty(); }

    static constexpr int kDirections = 64;
    static constexpr int kLevels = 256;
    static constexpr int kChannelLevels = 99;
    // The unit directions (fixed; the same for every distribution).
    static const std::vector<glm::dvec3>& directions();

    const std::vector<double>& projectionQuantiles() const { return m_projections; }
    const std::vector<glm::dvec3>& channelQuantiles() const { return m_channels; }

private:
    std::vector<double> m_projections;  // kDirections x kLevels
    std::vector<glm::dvec3> m_channels; // kChannelLevels (L*, a*, b*) colours
};

// Both zero when either is empty.
DistributionDistance distributionDistance(const ColourDistribution& a, const ColourDistribution& b);

} // namespace lut
