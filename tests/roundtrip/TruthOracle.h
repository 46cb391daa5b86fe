// SPDX-License-Identifier: Apache-2.0
#pragma once
// The truth a round-trip test compares extract's output and report with, written plainly in
// float64 from docs/specs/smash-pipeline.md: what the game shows with an 8-bit LUT against the
// edit of what it showed unedited (smash), or the LUT applied trilinearly against the edit (raw).
#include "RoundtripTestUtil.h"

#include "lut/Lut3D.h"
#include "lut/Quantize.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace lut::rt {

struct Summary {
    double max = 0.0, mean = 0.0, p99 = 0.0;
};
inline Summary summarise(std::vector<double> v) {
    Summary s;
    if (v.empty())
        return s;
    double sum = 0.0;
    for (double x : v) {
        s.max = std::max(s.max, x);
        sum += x;
    }
    s.mean = sum / double(v.size());
    std::sort(v.begin(), v.end());
    s.p99 = v[static_cast<std::size_t>(std::ceil(0.99 * double(v.size()))) - 1];
    return s;
}
struct Truth {
    Summary lattice, overall;
};

// A plain trilinear lookup of an N^3 LUT over [0,1], in double.
inline glm::dvec3 trilinear(const Lut3D& lut, glm::dvec3 in) {
    const int n = lut.size();
    int i[3];
    double f[3];
    for (int c = 0; c < 3; ++c) {
        const double x = clamp01(in[c]) * (n - 1);
        i[c] = std::min(static_cast<int>(x), n - 2);
        f[c] = x - i[c];
    }
    glm::dvec3 acc(0.0);
    for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                const double w =
                    (dx ? f[0] : 1 - f[0]) * (dy ? f[1] : 1 - f[1]) * (dz ? f[2] : 1 - f[2]);
                acc += w * glm::dvec3(lut.at(i[0] + dx, i[1] + dy, i[2] + dz));
            }
    return acc;
}

// A plain tetrahedral lookup of an N^3 LUT over [0,1], in double: the cell's diagonal path
// steps along the axes in order of decreasing fraction (Kasson et al.).
inline glm::dvec3 tetrahedral(const Lut3D& lut, glm::dvec3 in) {
    const int n = lut.size();
    int i[3];
    double f[3];
    for (int c = 0; c < 3; ++c) {
        const double x = clamp01(in[c]) * (n - 1);
        i[c] = std::min(static_cast<int>(x), n - 2);
        f[c] = x - i[c];
    }
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int a, int b) { return f[a] > f[b]; });
    glm::dvec3 prev(lut.at(i[0], i[1], i[2])), value = prev;
    for (int k = 0; k < 3; ++k) {
        ++i[order[k]];
        const glm::dvec3 next(lut.at(i[0], i[1], i[2]));
        value += f[order[k]] * (next - prev);
        prev = next;
    }
    return value;
}

inline Lut3D rounded8(const Lut3D& lut) {
    Lut3D out = lut;
    for (auto& e : out.entries())
        for (int c = 0; c < 3; ++c)
            e[c] = fromUnorm8(toUnorm8(e[c]));
    return out;
}

// Smash: what the game shows with the 8-bit LUT vs the edit of what the unedited game showed,
// over inputs s on the 61^3 grid (the lattice points are every fourth).
inline Truth smashTruth(const Lut3D& lut, const Edit& edit) {
    const Lut3D shipped = rounded8(lut);
    std::vector<double> lattice, all;
    const int m = 61;
    for (int b = 0; b < m; ++b)
        for (int g = 0; g < m; ++g)
            for (int r = 0; r < m; ++r) {
                const glm::dvec3 s = glm::dvec3(r, g, b) / double(m - 1);
                glm::dvec3 before;
                for (int c = 0; c < 3; ++c)
                    before[c] = srgbEnc(clamp01(std::pow(s[c] * 1.3703, 2.2)));
                const glm::dvec3 want = edit(before);
                const glm::dvec3 l = trilinear(shipped, s);
                for (int c = 0; c < 3; ++c) {
                    const double rr = ((l[c] - s[c]) * 0.99961 + s[c]) * 1.3703;
                    const double shown = srgbEnc(clamp01(std::pow(std::max(rr, 0.0), 2.2)));
                    const double e = std::fabs(shown - clamp01(want[c])) * 255.0;
                    all.push_back(e);
                    if (r % 4 == 0 && g % 4 == 0 && b % 4 == 0)
                        lattice.push_back(e);
                }
            }
    return {summarise(lattice), summarise(all)};
}

// Raw: the LUT applied with trilinear interpolation vs the edit, over colours on a grid four
// times finer than the LUT's lattice.
inline Truth rawTruth(const Lut3D& lut, const Edit& edit) {
    std::vector<double> lattice, all;
    const int n = lut.size(), k = 4, m = (n - 1) * k + 1;
    for (int b = 0; b < m; ++b)
        for (int g = 0; g < m; ++g)
            for (int r = 0; r < m; ++r) {
                const glm::dvec3 y = glm::dvec3(r, g, b) / double(m - 1);
                const glm::dvec3 got = trilinear(lut, y), want = edit(y);
                for (int c = 0; c < 3; ++c) {
                    const double e = std::fabs(got[c] - want[c]) * 255.0;
                    all.push_back(e);
                    if (r % k == 0 && g % k == 0 && b % k == 0)
                        lattice.push_back(e);
                }
            }
    return {summarise(lattice), summarise(all)};
}

// The display the game shows (float64) for its input s when its LUT returned l.
inline double gameShown(double l, double s) {
    const double r = ((l - s) * 0.99961 + s) * 1.3703;
    return srgbEnc(clamp01(std::pow(std::max(r, 0.0), 2.2)));
}

// The same truths over `count` random inputs (uniform in [0,1]^3, fixed seed), so between the
// points of every grid: what a printed maximum must bound. Smash: what the game shows with the
// 8-bit LUT vs the edit of what it showed with `stage` (null: neutral); raw: the LUT applied
// trilinearly vs the edit.
inline Summary smashTruthRandom(const Lut3D& lut, const Edit& edit, const Lut3D* stage = nullptr,
                                int count = 200000, unsigned seed = 22) {
    const Lut3D shipped = rounded8(lut);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> all;
    all.reserve(3 * static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 s(u(rng), u(rng), u(rng));
        const glm::dvec3 l0 = stage ? trilinear(*stage, s) : s, l = trilinear(shipped, s);
        glm::dvec3 before;
        for (int c = 0; c < 3; ++c)
            before[c] = gameShown(l0[c], s[c]);
        const glm::dvec3 want = edit(before);
        for (int c = 0; c < 3; ++c)
            all.push_back(std::fabs(gameShown(l[c], s[c]) - clamp01(want[c])) * 255.0);
    }
    return summarise(all);
}

inline Summary rawTruthRandom(const Lut3D& lut, const Edit& edit, int count = 200000,
                              unsigned seed = 22) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> all;
    all.reserve(3 * static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 y(u(rng), u(rng), u(rng));
        const glm::dvec3 got = trilinear(lut, y), want = edit(y);
        for (int c = 0; c < 3; ++c)
            all.push_back(std::fabs(got[c] - want[c]) * 255.0);
    }
    return summarise(all);
}

} // namespace lut::rt
