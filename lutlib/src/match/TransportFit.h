// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib's match: the regularised method's correction (lut/match/MatchOptions.h).
//
// 1. Sliced transport (F. Pitié, A. Kokaram, R. Dahyot, "N-dimensional probability density
//    function transfer and its application to colour transfer", ICCV 2005): the source samples,
//    already through the base map (HM-MKL-HM), are moved towards the reference distribution by
//    rounds of 1D histogram matching along the three axes of a rotated frame (fixed rotations,
//    no random numbers), `rounds` times.
// 2. A lattice fit of the displacement d_i each sample made, on a `size`^3 lattice over the base
//    map's input range, per output channel c, minimising
//        sum_i w_i (sum_k t_ik r_k - d_ic)^2  +  lambda * sum_axes |D2 r|^2  +  mu * |r|^2
//    (t_ik the trilinear weights; D2 the second difference along each lattice axis; the ridge mu
//    brings the correction back to 0 away from the data, where the base map extrapolates) under
//    monotonicity of base + r along the channel's own axis with a slope of at least minSlope:
//    violated lattice edges get a stiff penalty and the system is solved again (an active set,
//    at most 8 rounds), then any violation left is removed by isotonic regression of each lattice
//    line (pool adjacent violators). As in lattice regression (E. Garcia, R. Arora, M. Gupta,
//    "Optimized regression for efficient function evaluation", IEEE TIP 2012), with monotonicity
//    constraints along each axis.
#include "match/MatchSamples.h"

#include <glm/vec3.hpp>

#include <functional>
#include <vector>

namespace lut::detail {

struct TransportFitOptions {
    int size = 17;
    int rounds = 12;
    double smoothness = 1.0; // lambda, in units of the mean data weight per lattice node
    double ridge = 0.05;     // mu, relative to lambda
    double minSlope = 1.0 / 16.0;
    int nthreads = 0;
};

struct TransportFitResult {
    std::vector<glm::vec3> residual; // size^3, red fastest
    int size = 0;
    double movedRms = 0.0;         // rms displacement of the samples by the sliced transport
    int penaltyRounds = 0;         // solves with monotonicity penalties after the first
    std::size_t isotonicFixes = 0; // lattice values moved by the final isotonic pass
};

// u: the samples' lattice coordinates (in [uMin, uMax]); weights: theirs; start: base(u) for
// each sample (working encoding); reference: the reference samples; base: the base map.
TransportFitResult fitTransport(const std::vector<glm::vec3>& u, const std::vector<float>& weights,
                                const std::vector<glm::vec3>& start, const SampleSet& reference,
                                const glm::dvec3& uMin, const glm::dvec3& uMax,
                                const std::function<glm::dvec3(const glm::dvec3&)>& base,
                                const TransportFitOptions& options);

} // namespace lut::detail
