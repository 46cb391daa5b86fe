// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Oklab.h"

#include "lut/Math.h"
#include "lut/ops/ColorDifference.h"

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <numbers>

namespace lut {

namespace {

// Ottosson's matrices: linear sRGB -> LMS (M1), cube root, -> Lab (M2). glm matrices are
// column-major: each row of the published matrices is written as a column and transposed.
const glm::dmat3 kM1 = glm::transpose(glm::dmat3(0.4122214708, 0.5363325363, 0.0514459929, //
                                                 0.2119034982, 0.6806995451, 0.1073969566, //
                                                 0.0883024619, 0.2817188376, 0.6299787005));
const glm::dmat3 kM2 = glm::transpose(glm::dmat3(0.2104542553, 0.7936177850, -0.0040720468, //
                                                 1.9779984951, -2.4285922050, 0.4505937099, //
                                                 0.0259040371, 0.7827717662, -0.8086757660));
// The exact inverses, not the published rounded ones: Lab -> RGB undoes RGB -> Lab to double
// rounding (a strength blend with amounts (1, 0) keeps the other component to float rounding).
const glm::dmat3 kM1Inv = glm::inverse(kM1);
const glm::dmat3 kM2Inv = glm::inverse(kM2);

double encode(double v) {
    const double a = std::fabs(v);
    const double e = a <= 0.0031308 ? 12.92 * a : 1.055 * lut::math::pow(a, 1.0 / 2.4) - 0.055;
    return v < 0.0 ? -e : e;
}

} // namespace

glm::dvec3 linearSrgbToOklab(glm::dvec3 c) {
    const glm::dvec3 lms = kM1 * c;
    return kM2 * glm::dvec3(lut::math::cbrt(lms.x), lut::math::cbrt(lms.y), lut::math::cbrt(lms.z));
}

glm::dvec3 oklabToLinearSrgb(glm::dvec3 lab) {
    glm::dvec3 lms = kM2Inv * lab;
    lms *= lms * lms;
    return kM1Inv * lms;
}

glm::dvec3 srgbToOklab(glm::dvec3 encoded) {
    return linearSrgbToOklab(srgbToLinear(encoded));
}

glm::dvec3 oklabToSrgb(glm::dvec3 lab) {
    const glm::dvec3 l = oklabToLinearSrgb(lab);
    return {encode(l.x), encode(l.y), encode(l.z)};
}

double oklabHue(glm::dvec3 lab) {
    const double h = lut::math::atan2(lab.z, lab.y) * 180.0 / std::numbers::pi;
    return h < 0.0 ? h + 360.0 : (h >= 360.0 ? h - 360.0 : h);
}

double oklabChroma(glm::dvec3 lab) {
    return lut::math::hypot(lab.y, lab.z);
}

glm::dvec3 oklabFromLch(double lightness, double chroma, double hueDegrees) {
    const double h = hueDegrees * std::numbers::pi / 180.0;
    return {lightness, chroma * lut::math::cos(h), chroma * lut::math::sin(h)};
}

double hueDifference(double from, double to) {
    double d = std::fmod(to - from, 360.0);
    if (d <= -180.0)
        d += 360.0;
    else if (d > 180.0)
        d -= 360.0;
    return d;
}

} // namespace lut
