// SPDX-License-Identifier: Apache-2.0
#include "lut/bench/KernelBench.h"

#include "lut/Parallel.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <mutex>

namespace lut {

glm::dvec3 analyticGrade(glm::dvec3 c) {
    // Filmic S-curve: a logistic contrast around mid grey, renormalised so 0 -> 0 and 1 -> 1.
    auto curve = [](double x) {
        auto s = [](double v) { return 1.0 / (1.0 + std::exp(-6.0 * (v - 0.42))); };
        const double lo = s(0.0), hi = s(1.0);
        return (s(x) - lo) / (hi - lo);
    };
    glm::dvec3 o(curve(c.r), curve(c.g), curve(c.b));
    const double y = 0.2126 * o.r + 0.7152 * o.g + 0.0722 * o.b;
    // Saturation that rolls off in the highlights: the product makes the grade non-separable,
    // so trilinear and tetrahedral interpolation really differ on it (a sum of per-channel curves
    // and a matrix would be interpolated identically by both).
    o = y + (1.4 - 0.6 * y) * (o - y);
    // Warm channel mix (rows sum to 1, so greys stay grey).
    return glm::dvec3(0.92 * o.r + 0.06 * o.g + 0.02 * o.b, 0.04 * o.r + 0.93 * o.g + 0.03 * o.b,
                      0.01 * o.r + 0.09 * o.g + 0.90 * o.b);
}

Lut3D sampleAnalyticGrade(int size) {
    Lut3D lut(size);
    lut.setTitle("lutkit bench analytic grade");
    parallelFor(size, 0, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b)
            for (int g = 0; g < size; ++g)
                for (int r = 0; r < size; ++r)
                    lut.at(r, g, b) =
                        glm::vec3(analyticGrade(glm::dvec3(lut.latticeInput(r, g, b))));
    });
    return lut;
}

namespace {

// A small integer hash (no global RNG state, so frames are reproducible on any thread count).
float grain(std::uint32_t x, std::uint32_t y, std::uint32_t c) {
    std::uint32_t h = x * 0x9E3779B1u ^ (y + 0x7F4A7C15u) * 0x85EBCA77u ^ c * 0xC2B2AE3Du;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    h *= 0x297A2D39u;
    h ^= h >> 15;
    return static_cast<float>(h & 0xFFFFu) / 65535.0f - 0.5f;
}

float clamp01(float v) {
    return std::min(1.0f, std::max(0.0f, v));
}

} // namespace

Image makeBenchFrame(int width, int height, int nthreads) {
    Image img(width, height);
    const float w = static_cast<float>(std::max(1, width)),
                h = static_cast<float>(std::max(1, height));
    parallelFor(height, nthreads, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const float v = static_cast<float>(y) / h;
            for (int x = 0; x < width; ++x) {
                const float u = static_cast<float>(x) / w;
                float r, g, b;
                if (v < 0.45f) { // sky: blue to pale towards the horizon
                    const float t = v / 0.45f;
                    r = 0.25f + 0.5f * t;
                    g = 0.45f + 0.4f * t;
                    b = 0.85f + 0.1f * t;
                } else { // ground: warm gradient
                    const float t = (v - 0.45f) / 0.55f;
                    r = 0.35f - 0.2f * t + 0.1f * u;
                    g = 0.3f - 0.15f * t;
                    b = 0.2f - 0.1f * t;
                }
                // Saturated discs, a skin-toned ellipse and a highlight.
                auto disc = [&](float cx, float cy, float rad) {
                    const float dx = (u - cx) * w / h, dy = v - cy;
                    return dx * dx + dy * dy < rad * rad;
                };
                if (disc(0.2f, 0.65f, 0.12f))
                    r = 0.9f, g = 0.1f, b = 0.12f;
                if (disc(0.45f, 0.7f, 0.1f))
                    r = 0.1f, g = 0.75f, b = 0.2f;
                if (disc(0.8f, 0.62f, 0.15f))
                    r = 0.85f - 0.3f * v, g = 0.6f - 0.2f * v, b = 0.48f - 0.15f * v;
                if (disc(0.65f, 0.15f, 0.05f))
                    r = g = b = 0.99f;
                const float n = 0.02f;
                float* p = img.pixel(x, y);
                p[0] = clamp01(
                    r + n * grain(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 0));
                p[1] = clamp01(
                    g + n * grain(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 1));
                p[2] = clamp01(
                    b + n * grain(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 2));
                p[3] = 1.0f;
            }
        }
    });
    return img;
}

Image analyticReference(const Image& frame, int nthreads) {
    Image out(frame.width(), frame.height());
    parallelFor(frame.height(), nthreads, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < frame.width(); ++x) {
                const float* p = frame.pixel(x, y);
                const glm::dvec3 o = analyticGrade(glm::dvec3(p[0], p[1], p[2]));
                float* q = out.pixel(x, y);
                q[0] = static_cast<float>(o.r);
                q[1] = static_cast<float>(o.g);
                q[2] = static_cast<float>(o.b);
                q[3] = p[3];
            }
    });
    return out;
}

ErrorStats frameError(const Image& graded, const Image& reference, int nthreads) {
    std::mutex m;
    ErrorAccumulator total;
    parallelFor(graded.height(), nthreads, [&](int y0, int y1) {
        ErrorAccumulator acc;
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < graded.width(); ++x)
                for (int c = 0; c < 3; ++c)
                    acc.add(graded.pixel(x, y)[c], reference.pixel(x, y)[c]);
        std::lock_guard lock(m);
        total.merge(acc);
    });
    return total.result();
}

void parallelCopy(const Image& src, Image& dst, int nthreads) {
    const std::size_t rowBytes = 4 * sizeof(float) * static_cast<std::size_t>(src.width());
    parallelFor(src.height(), nthreads, [&](int y0, int y1) {
        std::memcpy(dst.pixel(0, y0), src.pixel(0, y0),
                    rowBytes * static_cast<std::size_t>(y1 - y0));
    });
}

double bestSeconds(int reps, const std::function<void()>& prepare,
                   const std::function<void()>& run) {
    double best = INFINITY;
    for (int i = 0; i < std::max(1, reps); ++i) {
        if (prepare)
            prepare();
        const auto t0 = std::chrono::steady_clock::now();
        run();
        best = std::min(
            best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    return best;
}

} // namespace lut
