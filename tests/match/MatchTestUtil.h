// SPDX-License-Identifier: Apache-2.0
#pragma once
// Pictures and plain float64 grades shared by the match tests (tests/match). The grades are the
// oracles: a look written as a formula here, never a map built by lutlib's match.
#include "TestPaths.h"
#include "lut/Image.h"
#include "lut/formats/ImageIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace lut::matchtest {

inline std::string samplePath(const char* name) {
    return std::string(LUTKIT_SAMPLES_DIR) + "/" + name;
}

inline double q8(double v) { // 8-bit storage: round to nearest, clamp
    return std::round(std::clamp(v, 0.0, 1.0) * 255.0) / 255.0;
}

// A known global grade on display values: channel mix, then per-channel curves (a lift and gamma
// on red, an S-curve on green, a gain on blue), then saturation 1.25 about Rec.709 luma.
inline void knownGrade(const double in[3], double out[3]) {
    const double m[3][3] = {{0.86, 0.10, 0.04}, {0.06, 0.84, 0.10}, {0.02, 0.14, 0.84}};
    double mixed[3];
    for (int i = 0; i < 3; ++i)
        mixed[i] = m[i][0] * in[0] + m[i][1] * in[1] + m[i][2] * in[2];
    double c[3];
    c[0] = 0.04 + 0.96 * std::pow(std::max(mixed[0], 0.0), 0.85);
    c[1] = 0.5 + 0.5 * std::tanh(2.4 * (mixed[1] - 0.5)) / std::tanh(1.2);
    c[2] = 0.92 * mixed[2] + 0.02;
    const double luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    for (int i = 0; i < 3; ++i)
        out[i] = luma + 1.25 * (c[i] - luma);
}

// A deterministic photo-like landscape, display-encoded (8-bit values): a sky gradient with
// clouds, hills, a meadow of fractal-noise greens, yellows and browns and
// flowers and stones scattered over the whole width, so its left and right halves are different
// pixels of the same kind of scene (as the halves of a photo are).
inline double valueNoise(double x, double y, unsigned seed) {
    auto hash = [seed](int i, int j) {
        std::uint32_t h = static_cast<std::uint32_t>(i) * 374761393u +
                          static_cast<std::uint32_t>(j) * 668265263u + seed * 2246822519u;
        h = (h ^ (h >> 13)) * 1274126177u;
        return static_cast<double>((h ^ (h >> 16)) & 0xffffu) / 65535.0;
    };
    const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
    const double fx = x - i, fy = y - j;
    const double sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
    const double a = hash(i, j) + (hash(i + 1, j) - hash(i, j)) * sx;
    const double b = hash(i, j + 1) + (hash(i + 1, j + 1) - hash(i, j + 1)) * sx;
    return a + (b - a) * sy;
}
inline double fractal(double x, double y, unsigned seed) {
    double v = 0, amp = 0.5, f = 1;
    for (int o = 0; o < 5; ++o, amp *= 0.5, f *= 2)
        v += amp * valueNoise(x * f, y * f, seed + static_cast<unsigned>(o) * 17u);
    return v;
}
inline Image landscape(int w, int h) {
    Image img(w, h, 1.0f);
    auto mix = [](const double* a, const double* b, double t, double* o) {
        for (int c = 0; c < 3; ++c)
            o[c] = a[c] + (b[c] - a[c]) * t;
    };
    const double skyTop[3] = {0.20, 0.38, 0.70}, skyLow[3] = {0.72, 0.80, 0.88};
    const double hill[3] = {0.30, 0.40, 0.45}, grass1[3] = {0.22, 0.42, 0.12};
    const double grass2[3] = {0.55, 0.58, 0.20}, soil[3] = {0.42, 0.30, 0.18};
    const double flowers[4][3] = {
        {0.85, 0.20, 0.25}, {0.95, 0.85, 0.30}, {0.60, 0.40, 0.80}, {0.92, 0.92, 0.90}};
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<std::array<double, 4>> spots; // x, y, r, kind
    for (int k = 0; k < 400; ++k)
        spots.push_back({u(rng) * w, (0.5 + 0.5 * u(rng)) * h, (0.003 + 0.006 * u(rng)) * h,
                         std::floor(u(rng) * 5)});
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double X = static_cast<double>(x) / h, Y = static_cast<double>(y) / h;
            const double horizon = 0.42 + 0.05 * fractal(X * 5, 0.5, 3);
            double c[3];
            if (Y < horizon - 0.08 * fractal(X * 3, 1.5, 5)) {
                mix(skyTop, skyLow, std::pow(Y / horizon, 1.3), c);
                const double cloud = std::max(0.0, fractal(X * 8, Y * 12, 7) - 0.55) * 2.2;
                const double white[3] = {0.96, 0.96, 0.97};
                mix(c, white, std::min(1.0, cloud), c);
            } else if (Y < horizon) {
                const double t = fractal(X * 8, Y * 8, 9);
                for (int k = 0; k < 3; ++k)
                    c[k] = hill[k] * (0.8 + 0.4 * t);
            } else {
                const double t = fractal(X * 12, Y * 16, 13), v = fractal(X * 24, Y * 30, 17);
                mix(grass1, grass2, std::clamp((t - 0.3) * 2.0, 0.0, 1.0), c);
                mix(c, soil, std::clamp((v - 0.62) * 4.0, 0.0, 1.0), c);
                const double light = 0.8 + 0.5 * (Y - horizon);
                for (int k = 0; k < 3; ++k)
                    c[k] *= light;
                for (const auto& s : spots) {
                    const double dx = x - s[0], dy = y - s[1];
                    if (dx * dx + dy * dy < s[2] * s[2]) {
                        const int kind = static_cast<int>(s[3]);
                        if (kind < 4)
                            for (int k = 0; k < 3; ++k)
                                c[k] = flowers[kind][k] * (0.85 + 0.15 * v);
                        else
                            for (int k = 0; k < 3; ++k)
                                c[k] = 0.45 + 0.2 * v;
                    }
                }
            }
            for (int k = 0; k < 3; ++k)
                img.pixel(x, y)[k] =
                    static_cast<float>(q8(c[k] + (valueNoise(x * 0.9, y * 0.9, 23) - 0.5) * 0.012));
        }
    return img;
}

// The picture graded with `grade` and stored as 8 bits.
inline Image graded(const Image& in, const std::function<void(const double*, double*)>& grade) {
    Image out(in.width(), in.height(), 1.0f);
    for (int y = 0; y < in.height(); ++y)
        for (int x = 0; x < in.width(); ++x) {
            const float* p = in.pixel(x, y);
            const double v[3] = {p[0], p[1], p[2]};
            double g[3];
            grade(v, g);
            for (int c = 0; c < 3; ++c)
                out.pixel(x, y)[c] = static_cast<float>(q8(g[c]));
        }
    return out;
}

// The picture flipped upside down and its pixels shuffled: no correspondence left.
inline Image flippedAndShuffled(const Image& in, unsigned seed = 7) {
    std::vector<std::size_t> order(static_cast<std::size_t>(in.width()) * in.height());
    std::iota(order.begin(), order.end(), 0);
    std::mt19937 rng(seed);
    std::shuffle(order.begin(), order.end(), rng);
    Image out(in.width(), in.height(), 1.0f);
    for (std::size_t i = 0; i < order.size(); ++i) {
        const std::size_t src = order[i];
        const int sx = static_cast<int>(src % in.width());
        const int sy = in.height() - 1 - static_cast<int>(src / in.width());
        const int dx = static_cast<int>(i % in.width()), dy = static_cast<int>(i / in.width());
        for (int c = 0; c < 4; ++c)
            out.pixel(dx, dy)[c] = in.pixel(sx, sy)[c];
    }
    return out;
}

// Absolute differences in 8-bit steps over every channel value.
struct Steps {
    double mean = 0, p99 = 0, max = 0;
};
inline Steps stepsBetween(const Image& a, const Image& b, bool round8 = true) {
    std::vector<double> d;
    d.reserve(static_cast<std::size_t>(a.width()) * a.height() * 3);
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                const double u = round8 ? q8(a.pixel(x, y)[c]) : a.pixel(x, y)[c];
                const double v = round8 ? q8(b.pixel(x, y)[c]) : b.pixel(x, y)[c];
                d.push_back(std::fabs(u - v) * 255.0);
            }
    Steps s;
    for (double v : d)
        s.mean += v;
    s.mean /= static_cast<double>(d.size());
    std::sort(d.begin(), d.end());
    s.p99 = d[static_cast<std::size_t>(0.99 * static_cast<double>(d.size() - 1))];
    s.max = d.back();
    return s;
}

} // namespace lut::matchtest
