// SPDX-License-Identifier: Apache-2.0
#pragma once
// Oklab (Björn Ottosson, "A perceptual color space for image processing", 2020,
// https://bottosson.github.io/posts/oklab/), the perceptual space lutkit's check measures hue in.
// srgbToOklab takes sRGB-encoded display values, as elsewhere in lutkit's colour maths
// (lut/ops/ColorDifference.h): decoded with the sRGB curve (mirrored for negatives), then linear
// sRGB -> LMS -> cube root -> Lab with Ottosson's published matrices (back with their exact
// inverses, so a round trip is exact to double rounding); linearSrgbToOklab takes
// linear values. Hue is atan2(b, a) in
// degrees, in [0, 360); chroma is hypot(a, b).
#include <glm/vec3.hpp>

namespace lut {

glm::dvec3 linearSrgbToOklab(glm::dvec3 linear);
glm::dvec3 oklabToLinearSrgb(glm::dvec3 lab);
glm::dvec3 srgbToOklab(glm::dvec3 encoded);
glm::dvec3 oklabToSrgb(glm::dvec3 lab); // encoded with the sRGB curve (mirrored for negatives)

// Hue in degrees [0, 360) and chroma of an Oklab colour.
double oklabHue(glm::dvec3 lab);
double oklabChroma(glm::dvec3 lab);
// An Oklab colour from lightness, chroma and hue in degrees.
glm::dvec3 oklabFromLch(double lightness, double chroma, double hueDegrees);

// The signed difference to - from of two hues in degrees, in (-180, 180].
double hueDifference(double from, double to);

} // namespace lut
