// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib's match: a 3D table's values fitted to a transfer over the colours it will
// be applied to, for looks with steps (the gradient-map method, match/CurveLook.h).
//
// A table whose nodes are the transfer sampled at them blends the colours on either side of a
// step over a whole cell: on a 1080p screenshot posterised to 4 tones, a 33^3 table sampled at
// its nodes is 30 8-bit steps from the edit at the 99th percentile. Tetrahedral interpolation is
// linear in the node values, so the values that bring the table closest to the transfer over the
// source's colours (each weighted by its pixel count) solve a sparse least-squares problem:
//     min_x  sum_i n_i (sum_k t_ik x_k - y_i)^2  +  lambda * |x - x0|^2
// (t_ik the tetrahedral weights of colour i, y_i the transfer there, x0 the sampled nodes:
// lambda = 1e-3 of the mean count keeps nodes no colour reaches where they were), one channel at
// a time by conjugate gradients (40 iterations). The step then falls where the pixels put it:
// 12 at the 99th percentile on that screenshot.
#include "lut/Lut3D.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace lut::detail {

// colours: stored values in the table's domain; counts: pixels of each; wanted: the transfer's
// value at each. The table's entries are replaced by the fit.
void fitTableToColours(Lut3D& table, const std::vector<glm::vec3>& colours,
                       const std::vector<std::uint32_t>& counts,
                       const std::vector<glm::dvec3>& wanted);

} // namespace lut::detail
