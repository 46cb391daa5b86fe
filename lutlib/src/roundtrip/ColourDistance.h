// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: "the same colour" in the round trip is judged per channel, by the largest
// channel difference (an edit may move one channel and not the others).
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace lut::detail {

inline float maxDiff(const float* a, const float* b) {
    return std::max({std::fabs(a[0] - b[0]), std::fabs(a[1] - b[1]), std::fabs(a[2] - b[2])});
}
inline float maxDiff(glm::vec3 a, glm::vec3 b) {
    return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}

} // namespace lut::detail
