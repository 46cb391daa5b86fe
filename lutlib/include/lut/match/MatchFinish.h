// SPDX-License-Identifier: Apache-2.0
#pragma once
// What `--strength`, `--luma-strength`, `--chroma-strength` and `--preserve` do to a matched
// colour: one function, applied per colour before the match is tabulated (the LUT holds a shaper
// and a table, so the blend cannot be done on the table's own lattice inputs afterwards).
//
//   amounts   luma = lumaStrength (else strength), chroma = chromaStrength (else strength)
//   luma      preserved: the luma amount is 0 (the source's Oklab L)
//   neutrals  preserved: the chroma amount is scaled by 1 - n(x), n = 1 for a source colour of
//             CIELAB chroma <= 6, 0 from chroma 18, smooth in between (greys stay grey; the
//             zone is wide because the table interpolates between lattice inputs that are not
//             grey)
//   skin      preserved: the chroma amount is scaled by 1 - s(x), s = 1 for CIELAB hue 30..70
//             degrees and chroma 10..45, falling smoothly to 0 at hue 15 and 85 degrees and at
//             chroma 5 and 60 (the hue and chroma of skin under daylight)
//   the blend lut::blendStrength (lut/ops/Strength.h, Oklab) of the source colour x and the
//             matched colour y with those amounts; y itself when both are 1.
// CIELAB and Oklab are taken of the colours as displayed: display-encoded values as they are,
// scene-linear values (`linear`) sRGB-encoded first (and decoded after the blend).
#include "lut/match/MatchOptions.h"

#include <glm/vec3.hpp>

namespace lut {

struct MatchFinish {
    double strength = 1.0;
    std::optional<double> lumaStrength, chromaStrength;
    std::vector<MatchPreserve> preserve;
    bool linear = false;

    static MatchFinish fromOptions(const MatchOptions& options, bool linear);
    // True when finish() returns the matched colour as it is.
    bool isIdentity() const;
    // True when it returns the source colour (both amounts 0): the neutral LUT.
    bool isNeutral() const;
    // Throws lut::Error naming the option when an amount is NaN or outside [0, 2].
    void check() const;
    glm::dvec3 operator()(const glm::dvec3& source, const glm::dvec3& matched) const;
};

// The weights above, for a source colour (display-encoded): 1 = kept entirely.
double neutralWeight(const glm::dvec3& displayColour);
double skinWeight(const glm::dvec3& displayColour);

} // namespace lut
