// SPDX-License-Identifier: Apache-2.0
// Strength and preserve for a matched colour: see lut/match/MatchFinish.h.
#include "lut/match/MatchFinish.h"

#include "lut/Math.h"
#include "lut/match/WorkingSpace.h"
#include "lut/ops/ColorDifference.h"
#include "lut/ops/Strength.h"

#include <algorithm>
#include <cmath>

namespace lut {

namespace {

// 0 at a, 1 at b (a < b), smooth (C1) in between.
double smoothstep(double a, double b, double x) {
    const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

bool has(const std::vector<MatchPreserve>& v, MatchPreserve p) {
    return std::find(v.begin(), v.end(), p) != v.end();
}

glm::dvec3 display(const glm::dvec3& c, bool linear) {
    if (!linear)
        return c;
    return {srgbEncodeExtended(c.x), srgbEncodeExtended(c.y), srgbEncodeExtended(c.z)};
}

} // namespace

double neutralWeight(const glm::dvec3& c) {
    const glm::dvec3 lab = srgbToLab(c);
    const double chroma = lut::math::hypot(lab.y, lab.z);
    return 1.0 - smoothstep(6.0, 18.0, chroma);
}

double skinWeight(const glm::dvec3& c) {
    const glm::dvec3 lab = srgbToLab(c);
    const double chroma = lut::math::hypot(lab.y, lab.z);
    if (chroma < 5.0)
        return 0.0;
    double hue = lut::math::atan2(lab.z, lab.y) * 180.0 / 3.14159265358979323846;
    if (hue < 0.0)
        hue += 360.0;
    const double h = smoothstep(15.0, 30.0, hue) * (1.0 - smoothstep(70.0, 85.0, hue));
    const double k = smoothstep(5.0, 10.0, chroma) * (1.0 - smoothstep(45.0, 60.0, chroma));
    return h * k;
}

MatchFinish MatchFinish::fromOptions(const MatchOptions& o, bool linear) {
    MatchFinish f;
    f.strength = o.strength;
    f.lumaStrength = o.lumaStrength;
    f.chromaStrength = o.chromaStrength;
    f.preserve = o.preserve;
    f.linear = linear;
    return f;
}

void MatchFinish::check() const {
    StrengthOptions s;
    s.strength = strength;
    s.luma = lumaStrength;
    s.chroma = chromaStrength;
    (void)strengthAmounts(s);
}

bool MatchFinish::isIdentity() const {
    return preserve.empty() && lumaStrength.value_or(strength) == 1.0 &&
           chromaStrength.value_or(strength) == 1.0;
}

bool MatchFinish::isNeutral() const {
    return lumaStrength.value_or(strength) == 0.0 && chromaStrength.value_or(strength) == 0.0;
}

glm::dvec3 MatchFinish::operator()(const glm::dvec3& source, const glm::dvec3& matched) const {
    if (isIdentity())
        return matched;
    StrengthAmounts a{lumaStrength.value_or(strength), chromaStrength.value_or(strength)};
    const glm::dvec3 x = display(source, linear);
    if (has(preserve, MatchPreserve::Luma))
        a.luma = 0.0;
    if (has(preserve, MatchPreserve::Neutrals))
        a.chroma *= 1.0 - neutralWeight(x);
    if (has(preserve, MatchPreserve::Skin))
        a.chroma *= 1.0 - skinWeight(x);
    if (a.luma == 1.0 && a.chroma == 1.0)
        return matched;
    const glm::dvec3 e = blendStrength(x, display(matched, linear), a);
    if (!linear)
        return e;
    return {srgbDecodeExtended(e.x), srgbDecodeExtended(e.y), srgbDecodeExtended(e.z)};
}

} // namespace lut
