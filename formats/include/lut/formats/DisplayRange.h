// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one rule for a 1D shaper + 3D table that becomes one table over a range (a format or
// dialect without a shaper, a bake, a command that works on one lattice: diff, compose, mix ...):
// where the shaper's domain holds 0..1, the table is sampled over 0..1, where display pictures
// live, never over the shaper's own range (over a log shaper's 0..64 every input in 0..1 falls in
// the first cells: off by mean 85 8-bit steps, issue 40). A domain that does not hold 0..1 keeps
// its own range. Inputs outside 0..1 then take the edge value, and the note says so.
#include <glm/vec3.hpp>

namespace lut::formats {

inline bool samplesDisplayRange(glm::vec3 shaperMin, glm::vec3 shaperMax) {
    return shaperMin.x <= 0 && shaperMin.y <= 0 && shaperMin.z <= 0 && shaperMax.x >= 1 &&
           shaperMax.y >= 1 && shaperMax.z >= 1;
}

// What the rule's notes say.
inline constexpr const char* kDisplayRangeWords = "over 0..1, where display pictures live";

} // namespace lut::formats
