// SPDX-License-Identifier: Apache-2.0
#pragma once
// LUTs with known defects and their plain float64 oracles, for the LUT check's tests
// (tests/ops/test_check_*.cpp). Everything here is written from formulas, independently of the
// code under test: Oklab from Björn Ottosson's published matrices, the sRGB curve from
// IEC 61966-2-1.
#include "OpsTestUtil.h"

#include "lut/check/CheckLut.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace lut::checktest {

inline double decode(double v) {
    const double a = std::fabs(v);
    const double l = a <= 0.04045 ? a / 12.92 : std::pow((a + 0.055) / 1.055, 2.4);
    return v < 0 ? -l : l;
}
inline double encode(double v) {
    const double a = std::fabs(v);
    const double e = a <= 0.0031308 ? 12.92 * a : 1.055 * std::pow(a, 1 / 2.4) - 0.055;
    return v < 0 ? -e : e;
}

// sRGB-encoded -> Oklab (L, a, b).
inline glm::dvec3 oklab(glm::dvec3 srgb) {
    const double r = decode(srgb.x), g = decode(srgb.y), b = decode(srgb.z);
    const double l = std::cbrt(0.4122214708 * r + 0.5363325363 * g + 0.0514459929 * b);
    const double m = std::cbrt(0.2119034982 * r + 0.6806995451 * g + 0.1073969566 * b);
    const double s = std::cbrt(0.0883024619 * r + 0.2817188376 * g + 0.6299787005 * b);
    return {0.2104542553 * l + 0.7936177850 * m - 0.0040720468 * s,
            1.9779984951 * l - 2.4285922050 * m + 0.4505937099 * s,
            0.0259040371 * l + 0.7827717662 * m - 0.8086757660 * s};
}

// Oklab -> linear sRGB (unclamped).
inline glm::dvec3 oklabToLinear(glm::dvec3 lab) {
    const double l = std::pow(lab.x + 0.3963377774 * lab.y + 0.2158037573 * lab.z, 3.0);
    const double m = std::pow(lab.x - 0.1055613458 * lab.y - 0.0638541728 * lab.z, 3.0);
    const double s = std::pow(lab.x - 0.0894841775 * lab.y - 1.2914855480 * lab.z, 3.0);
    return {4.0767416621 * l - 3.3077115913 * m + 0.2309699292 * s,
            -1.2684380046 * l + 2.6097574011 * m - 0.3413193965 * s,
            -0.0041960863 * l - 0.7034186147 * m + 1.7076147010 * s};
}

inline double hueOf(glm::dvec3 lab) {
    const double h = std::atan2(lab.z, lab.y) * 180.0 / std::numbers::pi;
    return h < 0 ? h + 360 : h;
}

inline double hueDistance(double a, double b) {
    const double d = std::fmod(std::fabs(a - b), 360.0);
    return std::min(d, 360.0 - d);
}

inline double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

// Fold-over on the red axis only: R = r - 0.25 w(g, b) S(r), S a smoothstep from 0.45 to 0.65
// (slope up to 7.5), w = (1 - g)(1 - b). dR/dr < 0 needs w > 1 / 1.875 = 0.533: near the red
// axis; on the grey axis w <= 0.2 there, so grey stays monotone.
inline double foldRed(double r, double g, double b) {
    return r - 0.25 * (1 - g) * (1 - b) * smoothstep(0.45, 0.65, r);
}
inline glm::vec3 foldGrade(glm::vec3 x) {
    return {static_cast<float>(foldRed(x.r, x.g, x.b)), x.g, x.b};
}

// A posterised band in the blues: output blue floored to levels 0.1 apart (25.5 8-bit steps) for
// blue in [0.5, 0.9), fully where red and green are both under 0.2, fading out (smoothstep) until
// either reaches 0.4. Levels start at 0.5, so output blue never falls as blue rises.
inline double blueness(double r, double g) {
    return 1.0 - smoothstep(0.2, 0.4, std::max(r, g));
}
inline glm::vec3 posteriseGrade(glm::vec3 x) {
    double b = x.b;
    if (x.b >= 0.5 && x.b < 0.9) {
        const double level = 0.5 + 0.1 * std::floor((x.b - 0.5) / 0.1 + 1e-9);
        b = x.b + blueness(x.r, x.g) * (level - x.b);
    }
    return {x.r, x.g, static_cast<float>(b)};
}

// A 20-degree hue twist in the yellows: Oklab hue turned by 20 cos^2 over +-45 degrees around
// 110 (sRGB yellow's hue is 109.8), chroma then reduced (hue and lightness kept) until the colour
// fits in the sRGB cube.
constexpr double kTwistCentre = 110.0, kTwistDegrees = 20.0, kTwistHalfWidth = 45.0;
inline double twistAt(double hue) {
    const double d = hueDistance(hue, kTwistCentre);
    if (d >= kTwistHalfWidth)
        return 0.0;
    const double c = std::cos(0.5 * std::numbers::pi * d / kTwistHalfWidth);
    return kTwistDegrees * c * c;
}
inline glm::vec3 twistGrade(glm::vec3 x) {
    const glm::dvec3 lab = oklab(glm::dvec3(x));
    const double chroma = std::hypot(lab.y, lab.z);
    const double hue = hueOf(lab) + twistAt(hueOf(lab));
    const double h = hue * std::numbers::pi / 180.0;
    auto at = [&](double c) { return glm::dvec3(lab.x, c * std::cos(h), c * std::sin(h)); };
    auto fits = [&](double c) {
        const glm::dvec3 l = oklabToLinear(at(c));
        return l.x >= 0 && l.y >= 0 && l.z >= 0 && l.x <= 1 && l.y <= 1 && l.z <= 1;
    };
    double c = chroma;
    if (!fits(c)) {
        double lo = 0.0, hi = chroma;
        for (int i = 0; i < 50; ++i)
            (fits(0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
        c = lo;
    }
    const glm::dvec3 l = oklabToLinear(at(c));
    return {static_cast<float>(encode(std::clamp(l.x, 0.0, 1.0))),
            static_cast<float>(encode(std::clamp(l.y, 0.0, 1.0))),
            static_cast<float>(encode(std::clamp(l.z, 0.0, 1.0)))};
}

// A clip of 5% of the cube: red x 1/0.95, held at 1 above r = 0.95 (13.4 8-bit steps cut off).
inline glm::vec3 clipGrade(glm::vec3 x) {
    return {std::min(1.0f, static_cast<float>(x.r / 0.95)), x.g, x.b};
}

// A steep but smooth gamma: every channel to the power 1/2.4.
inline glm::vec3 gammaGrade(glm::vec3 x) {
    return {static_cast<float>(std::pow(x.r, 1 / 2.4)), static_cast<float>(std::pow(x.g, 1 / 2.4)),
            static_cast<float>(std::pow(x.b, 1 / 2.4))};
}

// A smooth filmic grade: a gentle S-shaped tone curve with lifted blacks and rolled-off whites
// (slope 0.55..1.35), per channel, then 10% less saturation towards Rec.709 luma and a slight
// warm tint.
inline double filmicCurve(double x) {
    const double s = x + 0.35 * x * (1 - x) * (2 * x - 1); // S around 0.5
    return 0.02 + 0.95 * s;
}
inline glm::vec3 filmicGrade(glm::vec3 x) {
    double c[3] = {filmicCurve(x.r), filmicCurve(x.g), filmicCurve(x.b)};
    const double luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    const double tint[3] = {1.01, 1.0, 0.98};
    glm::vec3 out;
    for (int i = 0; i < 3; ++i)
        out[i] = static_cast<float>(std::clamp((luma + 0.9 * (c[i] - luma)) * tint[i], 0.0, 1.0));
    return out;
}

inline std::string describe(const CheckReport& r) {
    std::string s;
    for (const CheckSummary& c : r.checks)
        s += std::string(toString(c.kind)) + " " + toString(c.status) + ": " + c.text + "\n";
    for (const CheckFinding& f : r.findings)
        s += std::string("  ") + toString(f.severity) + " " + f.text() + "\n";
    return s;
}

} // namespace lut::checktest
