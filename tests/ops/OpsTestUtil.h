#pragma once
// LUTs and plain float64 references shared by the LUT-maths tests (tests/ops).
#include "lut/Lut3D.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <random>

namespace lut::opstest {

// A LUT whose entry at lattice input x is f(x).
inline Lut3D lutFrom(int n, const std::function<glm::vec3(glm::vec3)>& f) {
    Lut3D l(n);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                l.at(r, g, b) = f(l.latticeInput(r, g, b));
    return l;
}

// A smooth, invertible grade: per-channel tone curve, then mild channel crosstalk.
inline glm::vec3 smoothGrade(glm::vec3 c) {
    glm::vec3 t;
    for (int i = 0; i < 3; ++i)
        t[i] = 0.05f + 0.9f * std::pow(c[i], 0.8f);
    return {0.9f * t.r + 0.06f * t.g + 0.04f * t.b, 0.05f * t.r + 0.9f * t.g + 0.05f * t.b,
            0.03f * t.r + 0.07f * t.g + 0.9f * t.b};
}

inline Lut3D randomLut(int n, unsigned seed = 3) {
    Lut3D l(n);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (auto& e : l.entries())
        e = glm::vec3(u(rng), u(rng), u(rng));
    return l;
}

// Puts NaN, +-Inf and a huge value into a copy of lut.
inline Lut3D withNonFinite(Lut3D l) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    auto& e = l.entries();
    e[0] = glm::vec3(nan, 0.5f, 0.5f);
    e[e.size() / 2] = glm::vec3(inf, -inf, 0.25f);
    e[e.size() - 1] = glm::vec3(1e30f, nan, -1e30f);
    return l;
}

inline bool finite3(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline bool allFinite(const Lut3D& l) {
    for (const auto& e : l.entries())
        if (!finite3(e))
            return false;
    return true;
}

inline bool sameBits(const Lut3D& a, const Lut3D& b) {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), a.entryCount() * sizeof(glm::vec3)) == 0;
}

// Standard HSV -> RGB in the "alternative" closed form (f(n) = V - V S max(0, min(k, 4 - k, 1)),
// k = (n + H / 60) mod 6), independent of the sector switch lutlib uses.
inline glm::dvec3 hsvToRgb(double h, double s, double v) {
    auto f = [&](double n) {
        const double k = std::fmod(n + h / 60.0, 6.0);
        return v - v * s * std::max(0.0, std::min({k, 4.0 - k, 1.0}));
    };
    return {f(5.0), f(3.0), f(1.0)};
}

// HSV hue in degrees (the textbook piecewise definition), saturation
// and value, for colours with chroma > 0.
inline glm::dvec3 rgbToHsv(glm::dvec3 c) {
    const double mx = std::max({c.x, c.y, c.z}), mn = std::min({c.x, c.y, c.z});
    const double ch = mx - mn;
    double h = 0.0;
    if (ch > 0.0) {
        if (mx == c.x)
            h = 60.0 * std::fmod((c.y - c.z) / ch + 6.0, 6.0);
        else if (mx == c.y)
            h = 60.0 * ((c.z - c.x) / ch + 2.0);
        else
            h = 60.0 * ((c.x - c.y) / ch + 4.0);
    }
    return {h, mx > 0.0 ? ch / mx : 0.0, mx};
}

} // namespace lut::opstest
