// SPDX-License-Identifier: Apache-2.0
#pragma once
// LUTs and plain float64 references shared by the LUT-maths tests (tests/ops).
#include "lut/Lut3D.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
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

// ---- Float64 references of the three interpolations, written from their textbook definitions
// (independent of lutlib's samplers): the input is clamped to the domain and mapped to lattice
// coordinates t = (x - min) / (max - min) * (N - 1); cell i = min(floor(t), N - 2), f = t - i.

struct Cell {
    int i[3];
    double f[3];
};

inline Cell cellOf(const Lut3D& lut, glm::dvec3 x) {
    Cell c{};
    const int n = lut.size();
    for (int a = 0; a < 3; ++a) {
        const double lo = lut.domainMin()[a], hi = lut.domainMax()[a];
        const double t = (std::clamp(x[a], lo, hi) - lo) / (hi - lo) * (n - 1);
        c.i[a] = std::min(static_cast<int>(t), n - 2);
        c.f[a] = t - c.i[a];
    }
    return c;
}

inline glm::dvec3 entry64(const Lut3D& lut, int r, int g, int b) {
    return glm::dvec3(lut.at(r, g, b));
}

// Tetrahedral (Kasson et al.): the cell's diagonal path c000 -> c111 steps along the axes in
// order of decreasing fraction; the value is c000 + sum over the steps of fraction * step.
inline glm::dvec3 tetrahedral64(const Lut3D& lut, glm::dvec3 x) {
    const Cell c = cellOf(lut, x);
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int p, int q) { return c.f[p] > c.f[q]; });
    int at[3] = {c.i[0], c.i[1], c.i[2]};
    glm::dvec3 prev = entry64(lut, at[0], at[1], at[2]);
    glm::dvec3 value = prev;
    for (int k = 0; k < 3; ++k) {
        ++at[order[k]];
        const glm::dvec3 next = entry64(lut, at[0], at[1], at[2]);
        value += c.f[order[k]] * (next - prev);
        prev = next;
    }
    return value;
}

// Trilinear: the eight corners weighted by products of (1 - f) and f.
inline glm::dvec3 trilinear64(const Lut3D& lut, glm::dvec3 x) {
    const Cell c = cellOf(lut, x);
    glm::dvec3 v(0.0);
    for (int db = 0; db < 2; ++db)
        for (int dg = 0; dg < 2; ++dg)
            for (int dr = 0; dr < 2; ++dr) {
                const double w = (dr ? c.f[0] : 1 - c.f[0]) * (dg ? c.f[1] : 1 - c.f[1]) *
                                 (db ? c.f[2] : 1 - c.f[2]);
                v += w * entry64(lut, c.i[0] + dr, c.i[1] + dg, c.i[2] + db);
            }
    return v;
}

// Nearest: the closest lattice point per axis.
inline glm::dvec3 nearest64(const Lut3D& lut, glm::dvec3 x) {
    const Cell c = cellOf(lut, x);
    int at[3];
    for (int a = 0; a < 3; ++a)
        at[a] = c.i[a] + (c.f[a] >= 0.5 ? 1 : 0);
    return entry64(lut, at[0], at[1], at[2]);
}

inline glm::dvec3 interp64(const Lut3D& lut, glm::dvec3 x, int method) {
    return method == 0   ? nearest64(lut, x)
           : method == 1 ? trilinear64(lut, x)
                         : tetrahedral64(lut, x);
}

// The largest |f(x) - g(x)| over `count` uniformly random inputs in [lo, hi]^3 (fixed seed):
// the truth an error bound is checked against, on inputs no computation of lutkit chose.
inline double randomMax(const std::function<glm::dvec3(glm::dvec3)>& diff, glm::dvec3 lo,
                        glm::dvec3 hi, int count = 200000, unsigned seed = 2024) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double worst = 0.0;
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 x(lo.x + (hi.x - lo.x) * u(rng), lo.y + (hi.y - lo.y) * u(rng),
                           lo.z + (hi.z - lo.z) * u(rng));
        const glm::dvec3 d = diff(x);
        worst = std::max({worst, std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
    }
    return worst;
}

} // namespace lut::opstest
