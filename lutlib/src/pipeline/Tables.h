#pragma once
// The shared pow tables of the pipeline (built once, thread-safe statics).
#include "FastMath.h"

#include <cmath>

namespace lut::detail {

const PowTable& powSmashEncode(); // x^0.454545
const PowTable& powSmashDecode(); // x^2.2
const PowTable& powSrgbEncode();  // x^(1/2.4)

// Piecewise sRGB encode with the table pow, mirrored for negatives; the one form every fast path
// uses, so fused and unfused passes agree bit for bit. Input must be sanitized (finite).
inline float srgbEncodeFast(float x, const PowTable& p) {
    const float a = std::fabs(x); // -0 encodes to +0
    const float e = a <= 0.0031308f ? 12.92f * a : 1.055f * p(a) - 0.055f;
    return x < 0.0f ? -e : e;
}
inline float srgbEncodeFast(float x) {
    return srgbEncodeFast(x, powSrgbEncode());
}

// srgbEncode(pow(r, 2.2)) for r in [0, 2): the fused grading + display of a fully graded pixel in
// one lookup (absolute error < 2e-7); r outside needs the two-step form.
const UniformTable& smashDisplayFromBrightened();

} // namespace lut::detail
