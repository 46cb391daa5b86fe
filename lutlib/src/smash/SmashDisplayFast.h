// SPDX-License-Identifier: Apache-2.0
#pragma once
// The game's display of a graded value in one power: the sRGB encode of r^2.2 (the game's decode
// then the display's encode, docs/specs/smash-pipeline.md), on core/FastMath.h's polynomials and
// with the same rules (two roundings per multiply-add, the same bits on every machine; the AVX2
// form in pipeline/ArrayKernels.cpp, the WebAssembly one in SmashDisplayWasm.h). Within 1e-6 of
// the float64 formula (tests/pipeline/test_stages.cpp).
#include "core/FastMath.h"

namespace lut::detail {

// r^2.2 <= 0.0031308 exactly when r <= kSmashDisplayLowR, and then the result is 12.92 * r^2.2,
// else 1.055 * r^(2.2 / 2.4) - 0.055. r <= 0, NaN and denormals -> 0.
constexpr float kSmashDisplayLowR = 0.0727212795f; // 0.0031308^(1 / 2.2)
constexpr float kSmashDisplayHighP = 2.2f / 2.4f;
inline float smashDisplayFast(float r) {
    if (!(r >= poly::kMinNormal))
        return 0.0f;
    float e;
    const float l = log2Mantissa(r, e);
    if (r <= kSmashDisplayLowR)
        return 12.92f * exp2Times(2.2f, e, l);
    return mulAdd(1.055f, exp2Times(kSmashDisplayHighP, e, l), -0.055f);
}

} // namespace lut::detail
