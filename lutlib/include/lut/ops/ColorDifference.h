// SPDX-License-Identifier: Apache-2.0
#pragma once
// Colour difference for LUT comparisons: CIEDE2000 on CIELAB computed from sRGB-encoded values.
//
// Assumption (documented for every ΔE lutkit reports): LUT entries and image values are
// sRGB-encoded display values, as the entries of an SDR grading LUT are. They are decoded with
// the piecewise sRGB curve (IEC 61966-2-1, mirrored for negatives, the power segment above 1),
// converted to CIE XYZ with the sRGB/Rec.709 primaries and D65 white (matrix from the primaries'
// chromaticities), and to CIELAB relative to that white (the matrix's image of RGB (1,1,1), so
// sRGB white has a* = b* = 0 and L* = 100). ΔE2000 follows Sharma, Wu and Dalal, "The CIEDE2000
// colour-difference formula: implementation notes, supplementary test data, and mathematical
// observations", Color Res. Appl. 30(1), 2005, with kL = kC = kH = 1.
//
// Non-finite inputs: NaN channels count as 0 and magnitudes are clamped to 65504 (the largest
// half float), so every result is finite.
#include <glm/vec3.hpp>

namespace lut {

glm::dvec3 srgbToLinear(glm::dvec3 encoded);
glm::dvec3 linearSrgbToXyz(glm::dvec3 linear);
glm::dvec3 xyzToLab(glm::dvec3 xyz); // D65 white as above
glm::dvec3 srgbToLab(glm::dvec3 encoded);

// CIEDE2000 between two CIELAB colours (L*, a*, b*).
double deltaE2000(glm::dvec3 lab1, glm::dvec3 lab2);

} // namespace lut
