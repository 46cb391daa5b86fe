// SPDX-License-Identifier: Apache-2.0
#pragma once
// smashDisplayFast (SmashDisplayFast.h) on four floats at once with WebAssembly SIMD, lane for
// lane the scalar definition's operations (core/FastMathWasm.h): the same bits.
#include "core/FastMathWasm.h"
#include "smash/SmashDisplayFast.h"

namespace lut::detail::wasm {

inline v128_t smashDisplay4(v128_t r) {
    const v128_t ok = wasm_f32x4_ge(r, splat(poly::kMinNormal));
    const v128_t safe = wasm_v128_bitselect(r, splat(1.0f), ok);
    v128_t e;
    const v128_t l = log2Mantissa4(safe, e);
    const v128_t low = wasm_f32x4_le(r, splat(kSmashDisplayLowR));
    const v128_t p = wasm_v128_bitselect(splat(2.2f), splat(kSmashDisplayHighP), low);
    const v128_t out = exp2Times4(p, e, l);
    const v128_t o = wasm_v128_bitselect(wasm_f32x4_mul(splat(12.92f), out),
                                         mulAdd4(splat(1.055f), out, splat(-0.055f)), low);
    return wasm_v128_and(o, ok);
}

} // namespace lut::detail::wasm
