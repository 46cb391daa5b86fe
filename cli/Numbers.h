// SPDX-License-Identifier: Apache-2.0
#pragma once
// How lutkit writes numbers in its reports, once for every command: significant digits, times,
// colour triples (JSON arrays are json::vec3 in Json.h).
#include <glm/vec3.hpp>

#include <cstdio>
#include <string>

namespace lut::cli {

// v with `digits` significant digits ("%.3g": 0.00196, 1.23e+03).
inline std::string significant(double v, int digits = 3) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

// "12.3 ms"
inline std::string milliseconds(double seconds) {
    return significant(seconds * 1e3) + " ms";
}

// "0.5 0.25 1" (3 significant digits each)
inline std::string triple(const glm::dvec3& v) {
    return significant(v.x) + " " + significant(v.y) + " " + significant(v.z);
}

} // namespace lut::cli
