// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib's match: CIELAB of stored or working-space values (display-encoded values
// through the sRGB curve, scene-linear ones as linear Rec.709/sRGB), for the distances.
#include <glm/vec3.hpp>

#include <vector>

namespace lut::detail {

glm::dvec3 labOfStored(const glm::dvec3& stored, bool linear);
std::vector<glm::vec3> labOfWorking(const std::vector<glm::vec3>& working, bool linear,
                                    int nthreads);
std::vector<glm::vec3> labOfStored(const std::vector<glm::vec3>& stored, bool linear, int nthreads);

} // namespace lut::detail
