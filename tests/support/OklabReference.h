// SPDX-License-Identifier: Apache-2.0
#pragma once
// A float64 Oklab written plainly from Björn Ottosson's definition
// (https://bottosson.github.io/posts/oklab/, his published matrices both ways) over the sRGB
// transfer curve of IEC 61966-2-1 (continued above 1, mirrored below 0): the oracle of the
// strength tests (lut/ops/Strength.h), independent of lutlib's code.
#include <glm/vec3.hpp>

#include <array>
#include <cmath>

namespace lut::test {

using Lab = std::array<double, 3>;

inline double srgbToLinear(double v) {
    const double a = std::fabs(v);
    return std::copysign(a <= 0.04045 ? a / 12.92 : std::pow((a + 0.055) / 1.055, 2.4), v);
}

inline double linearToSrgb(double v) {
    const double a = std::fabs(v);
    return std::copysign(a <= 0.0031308 ? 12.92 * a : 1.055 * std::pow(a, 1 / 2.4) - 0.055, v);
}

inline Lab oklab(glm::dvec3 c) {
    const double r = srgbToLinear(c.x), g = srgbToLinear(c.y), b = srgbToLinear(c.z);
    const double l = std::cbrt(0.4122214708 * r + 0.5363325363 * g + 0.0514459929 * b);
    const double m = std::cbrt(0.2119034982 * r + 0.6806995451 * g + 0.1073969566 * b);
    const double s = std::cbrt(0.0883024619 * r + 0.2817188376 * g + 0.6299787005 * b);
    return {0.2104542553 * l + 0.7936177850 * m - 0.0040720468 * s,
            1.9779984951 * l - 2.4285922050 * m + 0.4505937099 * s,
            0.0259040371 * l + 0.7827717662 * m - 0.8086757660 * s};
}

inline glm::dvec3 oklabToSrgb(Lab lab) {
    const double L = lab[0], a = lab[1], b = lab[2];
    const double l = std::pow(L + 0.3963377774 * a + 0.2158037573 * b, 3);
    const double m = std::pow(L - 0.1055613458 * a - 0.0638541728 * b, 3);
    const double s = std::pow(L - 0.0894841775 * a - 1.2914855480 * b, 3);
    return {linearToSrgb(4.0767416621 * l - 3.3077115913 * m + 0.2309699292 * s),
            linearToSrgb(-1.2684380046 * l + 2.6097574011 * m - 0.3413193965 * s),
            linearToSrgb(-0.0041960863 * l - 0.7034186147 * m + 1.7076147010 * s)};
}

// What a strength blend gives: lightness moved from `from` towards `to` by tl, a and b by tc.
inline glm::dvec3 strengthBlend(glm::dvec3 from, glm::dvec3 to, double tl, double tc) {
    const Lab x = oklab(from), y = oklab(to);
    return oklabToSrgb(
        {x[0] + tl * (y[0] - x[0]), x[1] + tc * (y[1] - x[1]), x[2] + tc * (y[2] - x[2])});
}

} // namespace lut::test
