// SPDX-License-Identifier: Apache-2.0
#pragma once
// LUTs and inputs shared by the lutlib tests.
#include "lut/Lut3D.h"

#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace lut::test {

// A smooth, non-trivial grade: contrast curve, saturation and a little channel crosstalk.
inline glm::vec3 smoothGrade(glm::vec3 c) {
    glm::vec3 o;
    for (int i = 0; i < 3; ++i)
        o[i] = 0.5f + 0.6f * std::tanh(1.8f * (c[i] - 0.45f));
    const float y = 0.2126f * o.r + 0.7152f * o.g + 0.0722f * o.b;
    o = y + 1.25f * (o - y);
    return glm::vec3(0.9f * o.r + 0.1f * o.g, 0.05f * o.r + 0.9f * o.g + 0.05f * o.b,
                     0.1f * o.g + 0.9f * o.b);
}

inline Lut3D smoothLut(int n) {
    Lut3D l(n);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                l.at(r, g, b) = smoothGrade(l.latticeInput(r, g, b));
    return l;
}

inline Lut3D randomLut(int n, unsigned seed = 7) {
    Lut3D l(n);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (auto& e : l.entries())
        e = glm::vec3(u(rng), u(rng), u(rng));
    return l;
}

// Values that stress the extreme-input policy, plus a few ordinary ones.
inline std::vector<float> extremeValues() {
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    return {nan,
            -nan,
            inf,
            -inf,
            -0.0f,
            0.0f,
            1.0f,
            -1.0f,
            1e30f,
            -1e30f,
            1e-40f,
            -1e-40f,
            std::numeric_limits<float>::denorm_min(),
            std::numeric_limits<float>::min(),
            std::numeric_limits<float>::max(),
            -std::numeric_limits<float>::max(),
            std::nextafter(1.0f, 2.0f),
            std::nextafter(1.0f, 0.0f),
            0.5f,
            0.25f,
            1.0f / 3.0f,
            0.999999f,
            1e-7f,
            2.0f};
}

// Every combination of extremeValues() as RGB, plus random in-domain and out-of-domain colours.
inline std::vector<glm::vec3> stressInputs(std::size_t randomCount = 4000, unsigned seed = 11) {
    std::vector<glm::vec3> v;
    const auto ex = extremeValues();
    for (float r : ex)
        for (float g : ex)
            for (float b : ex)
                v.emplace_back(r, g, b);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> in(0.0f, 1.0f), wide(-0.5f, 1.5f);
    for (std::size_t i = 0; i < randomCount; ++i)
        v.emplace_back(in(rng), in(rng), in(rng));
    for (std::size_t i = 0; i < randomCount / 4; ++i)
        v.emplace_back(wide(rng), wide(rng), wide(rng));
    return v;
}

inline bool finite3(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace lut::test
