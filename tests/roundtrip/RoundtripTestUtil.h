// SPDX-License-Identifier: Apache-2.0
#pragma once
// Shared helpers of the round-trip tests: known global edits written out in plain double
// precision (the oracles), image quantisation, a synthetic screenshot, a private temp folder.
#include "TestPaths.h"
#include "lut/Image.h"
#include "lut/Quantize.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace lut::rt {

using Edit = std::function<glm::dvec3(glm::dvec3)>;

inline double clamp01(double v) {
    return std::clamp(v, 0.0, 1.0);
}

// Monotone cubic (Fritsch-Carlson) through control points: what a "curves" dialog draws.
class MonotoneCurve {
public:
    MonotoneCurve(std::vector<double> x, std::vector<double> y)
        : m_x(std::move(x)), m_y(std::move(y)) {
        const std::size_t n = m_x.size();
        std::vector<double> d(n - 1);
        for (std::size_t i = 0; i + 1 < n; ++i)
            d[i] = (m_y[i + 1] - m_y[i]) / (m_x[i + 1] - m_x[i]);
        m_m.resize(n);
        m_m[0] = d[0];
        m_m[n - 1] = d[n - 2];
        for (std::size_t i = 1; i + 1 < n; ++i)
            m_m[i] = d[i - 1] * d[i] <= 0 ? 0.0 : (d[i - 1] + d[i]) / 2;
        for (std::size_t i = 0; i + 1 < n; ++i) {
            if (d[i] == 0) {
                m_m[i] = m_m[i + 1] = 0;
                continue;
            }
            const double a = m_m[i] / d[i], b = m_m[i + 1] / d[i];
            const double s = a * a + b * b;
            if (s > 9) {
                const double t = 3 / std::sqrt(s);
                m_m[i] = t * a * d[i];
                m_m[i + 1] = t * b * d[i];
            }
        }
    }
    double operator()(double v) const {
        v = clamp01(v);
        std::size_t i = 0;
        while (i + 2 < m_x.size() && v > m_x[i + 1])
            ++i;
        const double h = m_x[i + 1] - m_x[i], t = (v - m_x[i]) / h;
        const double t2 = t * t, t3 = t2 * t;
        return (2 * t3 - 3 * t2 + 1) * m_y[i] + (t3 - 2 * t2 + t) * h * m_m[i] +
               (-2 * t3 + 3 * t2) * m_y[i + 1] + (t3 - t2) * h * m_m[i + 1];
    }

private:
    std::vector<double> m_x, m_y, m_m;
};

// Per-channel curves (a different curve per channel, as a colour-balance curves edit).
inline Edit curvesEdit() {
    const MonotoneCurve r({0, 0.25, 0.5, 0.75, 1}, {0.0, 0.2, 0.56, 0.84, 1.0});
    const MonotoneCurve g({0, 0.3, 0.6, 1}, {0.02, 0.27, 0.63, 0.97});
    const MonotoneCurve b({0, 0.5, 1}, {0.05, 0.45, 0.93});
    return [=](glm::dvec3 c) { return glm::dvec3(r(c.x), g(c.y), b(c.z)); };
}
// Levels: input black/white, midtone gamma, output range.
inline Edit levelsEdit(double black = 0.06, double white = 0.92, double gamma = 1.2,
                       double outLo = 0.02, double outHi = 0.98) {
    return [=](glm::dvec3 c) {
        glm::dvec3 o;
        for (int i = 0; i < 3; ++i) {
            const double v = clamp01((c[i] - black) / (white - black));
            o[i] = outLo + (outHi - outLo) * std::pow(v, 1.0 / gamma);
        }
        return o;
    };
}
inline double luma(glm::dvec3 c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}
inline Edit saturationEdit(double amount = 1.4) {
    return [=](glm::dvec3 c) {
        const double l = luma(c);
        return glm::dvec3(clamp01(l + amount * (c.x - l)), clamp01(l + amount * (c.y - l)),
                          clamp01(l + amount * (c.z - l)));
    };
}
// A gradient map: luminance through a piecewise-linear gradient (may invert).
inline Edit gradientMapEdit(std::vector<double> stops, std::vector<glm::dvec3> colours) {
    return [=](glm::dvec3 c) {
        const double l = clamp01(luma(c));
        std::size_t i = 0;
        while (i + 2 < stops.size() && l > stops[i + 1])
            ++i;
        const double t = clamp01((l - stops[i]) / (stops[i + 1] - stops[i]));
        return colours[i] * (1.0 - t) + colours[i + 1] * t;
    };
}
inline Edit warmGradientMap() {
    return gradientMapEdit({0.0, 0.5, 1.0}, {{0.1, 0.0, 0.3}, {0.9, 0.4, 0.2}, {1.0, 1.0, 0.8}});
}
inline Edit invertingGradientMap() {
    return gradientMapEdit({0.0, 1.0}, {{1.0, 0.95, 0.9}, {0.0, 0.05, 0.1}});
}

// A hue rotation in HSV (what an editor's Hue/Saturation dialog does): piecewise linear in RGB,
// with kinks where the largest or smallest channel changes.
inline Edit hueShiftEdit(double degrees = 40.0) {
    return [=](glm::dvec3 c) {
        const double mx = std::max({c.x, c.y, c.z}), mn = std::min({c.x, c.y, c.z});
        const double d = mx - mn;
        if (d <= 0.0)
            return c;
        double h = mx == c.x   ? std::fmod((c.y - c.z) / d + 6.0, 6.0)
                   : mx == c.y ? (c.z - c.x) / d + 2.0
                               : (c.x - c.y) / d + 4.0;
        h = std::fmod(h + degrees / 60.0 + 6.0, 6.0);
        const double x = d * (1.0 - std::fabs(std::fmod(h, 2.0) - 1.0));
        glm::dvec3 o;
        switch (static_cast<int>(h)) {
        case 0:
            o = {d, x, 0};
            break;
        case 1:
            o = {x, d, 0};
            break;
        case 2:
            o = {0, d, x};
            break;
        case 3:
            o = {0, x, d};
            break;
        case 4:
            o = {x, 0, d};
            break;
        default:
            o = {d, 0, x};
            break;
        }
        return o + glm::dvec3(mn);
    };
}

inline double srgbEnc(double x) {
    x = clamp01(x);
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}
inline double srgbDec(double v) {
    v = clamp01(v);
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// Applies an edit to every pixel's RGB, then stores at bitDepth (8, 16: rounded; 32: as is).
inline void applyEdit(Image& img, const Edit& f, int bitDepth) {
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            float* p = img.pixel(x, y);
            const glm::dvec3 o = f(glm::dvec3(p[0], p[1], p[2]));
            for (int c = 0; c < 3; ++c) {
                const float v = static_cast<float>(o[c]);
                p[c] = bitDepth == 8    ? fromUnorm8(toUnorm8(v))
                       : bitDepth == 16 ? fromUnorm16(toUnorm16(v))
                                        : v;
            }
        }
}
inline void quantize(Image& img, int bitDepth) {
    applyEdit(
        img, [](glm::dvec3 c) { return c; }, bitDepth);
}

// The smallest screenshot the default patches fit at the default scale 8 (the 12^3 game-display
// strip is 1184 pixels wide, the 16^3 Hald patches 544 high), smaller than a Switch capture
// (1280x720) so the tests stay quick.
constexpr int kShotWidth = 1216;
constexpr int kShotHeight = 560;

// A screenshot-like image: smooth gradients, some saturated shapes, deterministic noise.
inline Image syntheticScreenshot(int w = 400, int h = 260, int bitDepth = 8) {
    Image img(w, h, 1.0f);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-0.02f, 0.02f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img.pixel(x, y);
            const float fx = float(x) / float(w), fy = float(y) / float(h);
            p[0] = 0.2f + 0.6f * fx + u(rng);
            p[1] = 0.3f + 0.5f * fy + u(rng);
            p[2] = 0.5f + 0.4f * std::sin(6.0f * fx + 3.0f * fy) * 0.5f + u(rng);
            if ((x / 40 + y / 40) % 5 == 0)
                p[0] = 0.9f, p[1] = 0.1f, p[2] = 0.15f;
            for (int c = 0; c < 3; ++c)
                p[c] = std::clamp(p[c], 0.0f, 1.0f);
            p[3] = 1.0f;
        }
    quantize(img, bitDepth);
    return img;
}

// A copy of the rectangle (x0, y0, w, h) of src; pixels outside src are `fill`.
inline Image cropOrPad(const Image& src, int x0, int y0, int w, int h, float fill = 0.5f) {
    Image out(w, h, fill);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int sx = x0 + x, sy = y0 + y;
            float* d = out.pixel(x, y);
            d[3] = 1.0f;
            if (sx < 0 || sy < 0 || sx >= src.width() || sy >= src.height())
                continue;
            const float* s = src.pixel(sx, sy);
            std::copy(s, s + 4, d);
        }
    return out;
}

// Bilinear resize by a factor (what an editor's "image size" does).
inline Image resizeBilinear(const Image& src, double factor) {
    const int w = static_cast<int>(std::lround(src.width() * factor));
    const int h = static_cast<int>(std::lround(src.height() * factor));
    Image out(w, h, 1.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double sx = std::clamp((x + 0.5) / factor - 0.5, 0.0, src.width() - 1.0);
            const double sy = std::clamp((y + 0.5) / factor - 0.5, 0.0, src.height() - 1.0);
            const int x0 = std::min(static_cast<int>(sx), src.width() - 2),
                      y0 = std::min(static_cast<int>(sy), src.height() - 2);
            const double fx = sx - x0, fy = sy - y0;
            for (int c = 0; c < 4; ++c)
                out.pixel(x, y)[c] = static_cast<float>(
                    (1 - fy) * ((1 - fx) * src.pixel(x0, y0)[c] + fx * src.pixel(x0 + 1, y0)[c]) +
                    fy * ((1 - fx) * src.pixel(x0, y0 + 1)[c] + fx * src.pixel(x0 + 1, y0 + 1)[c]));
        }
    return out;
}
inline Image resizeNearest(const Image& src, int factor) {
    Image out(src.width() * factor, src.height() * factor);
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x) {
            const float* s = src.pixel(x / factor, y / factor);
            std::copy(s, s + 4, out.pixel(x, y));
        }
    return out;
}

// A folder of our own for files (runCli's tempDir() wipes the test's folder on every call).
inline std::string rtDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name = std::string("rt-") + info->test_suite_name() + "." + info->name();
    const auto dir = std::filesystem::path(LUTKIT_BINARY_DIR) / "test-tmp" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

} // namespace lut::rt
