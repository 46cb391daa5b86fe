// SPDX-License-Identifier: Apache-2.0
#pragma once
// FastMath.h's functions on four floats at once with WebAssembly SIMD (the browser edition),
// lane for lane the scalar definition's IEEE operations in the same order, so the bits are those
// of the scalar forms and of the native AVX2 kernels (docs/portable.md): a multiply-add is a
// multiply then an add, as in the definition, and exp2Times' p * e two exact products. Tested
// against the native CLI's bytes in tests/web/test_same_bytes.py.
#include "core/FastMath.h"

#include <wasm_simd128.h>

namespace lut::detail::wasm {

inline v128_t splat(float v) {
    return wasm_f32x4_splat(v);
}

// mulAdd, four lanes: a * b rounded, then + c rounded.
__attribute__((always_inline)) inline v128_t mulAdd4(v128_t a, v128_t b, v128_t c) {
    return wasm_f32x4_add(wasm_f32x4_mul(a, b), c);
}

// splitHigh, four lanes.
__attribute__((always_inline)) inline v128_t splitHigh4(v128_t p) {
    return wasm_v128_and(p, wasm_i32x4_splat(-4096));
}

// Four RGBA pixels <-> the R, G, B and A of the four (its own inverse).
inline void transpose4(v128_t& a, v128_t& b, v128_t& c, v128_t& d) {
    const v128_t t0 = wasm_i32x4_shuffle(a, b, 0, 4, 1, 5),
                 t1 = wasm_i32x4_shuffle(c, d, 0, 4, 1, 5);
    const v128_t t2 = wasm_i32x4_shuffle(a, b, 2, 6, 3, 7),
                 t3 = wasm_i32x4_shuffle(c, d, 2, 6, 3, 7);
    a = wasm_i32x4_shuffle(t0, t1, 0, 1, 4, 5);
    b = wasm_i32x4_shuffle(t0, t1, 2, 3, 6, 7);
    c = wasm_i32x4_shuffle(t2, t3, 0, 1, 4, 5);
    d = wasm_i32x4_shuffle(t2, t3, 2, 3, 6, 7);
}

// log2Mantissa, four lanes (x must be > 0 and normal in the lanes that are used).
inline v128_t log2Mantissa4(v128_t x, v128_t& e) {
    v128_t ei = wasm_i32x4_sub(wasm_u32x4_shr(x, 23), wasm_i32x4_splat(127));
    v128_t m =
        wasm_v128_or(wasm_v128_and(x, wasm_i32x4_splat(0x7FFFFF)), wasm_i32x4_splat(0x3F800000));
    const v128_t big = wasm_f32x4_gt(m, splat(poly::kSqrt2));
    m = wasm_v128_bitselect(wasm_f32x4_mul(m, splat(0.5f)), m, big);
    ei = wasm_i32x4_sub(ei, big); // the mask is -1: adds 1
    e = wasm_f32x4_convert_i32x4(ei);
    const v128_t u = wasm_f32x4_div(wasm_f32x4_sub(m, splat(1.0f)), wasm_f32x4_add(m, splat(1.0f)));
    const v128_t u2 = wasm_f32x4_mul(u, u);
    const v128_t u4 = wasm_f32x4_mul(u2, u2);
    return wasm_f32x4_mul(u, mulAdd4(mulAdd4(splat(poly::kLog[0]), u2, splat(poly::kLog[1])), u4,
                                     mulAdd4(splat(poly::kLog[2]), u2, splat(poly::kLog[3]))));
}

// exp2Times, four lanes.
inline v128_t exp2Times4(v128_t p, v128_t e, v128_t l) {
    const v128_t ph = splitHigh4(p);
    const v128_t hi = wasm_f32x4_mul(ph, e);
    const v128_t lo = mulAdd4(p, l, wasm_f32x4_mul(wasm_f32x4_sub(p, ph), e));
    v128_t n = wasm_f32x4_nearest(wasm_f32x4_add(hi, lo));
    const v128_t f = wasm_f32x4_add(wasm_f32x4_sub(hi, n), lo);
    // n > 127 ? 127 : (n < -127 ? -127 : n), as the scalar form (NaN stays)
    n = wasm_v128_bitselect(splat(127.0f), n, wasm_f32x4_gt(n, splat(127.0f)));
    n = wasm_v128_bitselect(splat(-127.0f), n, wasm_f32x4_lt(n, splat(-127.0f)));
    const v128_t f2 = wasm_f32x4_mul(f, f);
    const v128_t a = mulAdd4(splat(poly::kExp2[0]), f, splat(poly::kExp2[1]));
    const v128_t b = mulAdd4(splat(poly::kExp2[2]), f, splat(poly::kExp2[3]));
    const v128_t c = mulAdd4(splat(poly::kExp2[4]), f, splat(poly::kExp2[5]));
    const v128_t q = mulAdd4(mulAdd4(mulAdd4(a, f2, b), f2, c), f, splat(1.0f));
    const v128_t bits =
        wasm_i32x4_shl(wasm_i32x4_add(wasm_i32x4_trunc_sat_f32x4(n), wasm_i32x4_splat(127)), 23);
    return wasm_f32x4_mul(q, bits);
}

// powFast, four lanes: lanes with !(x >= 2^-126) give 0.
inline v128_t powFast4(v128_t x, float p) {
    const v128_t ok = wasm_f32x4_ge(x, splat(poly::kMinNormal));
    const v128_t safe = wasm_v128_bitselect(x, splat(1.0f), ok);
    v128_t e;
    const v128_t l = log2Mantissa4(safe, e);
    return wasm_v128_and(exp2Times4(splat(p), e, l), ok);
}

// srgbEncodeFast, four lanes.
inline v128_t srgbEncode4(v128_t x) {
    const v128_t a = wasm_f32x4_abs(x);
    const v128_t pw = mulAdd4(splat(1.055f), powFast4(a, 1.0f / 2.4f), splat(-0.055f));
    const v128_t lin = wasm_f32x4_mul(splat(12.92f), a);
    const v128_t e = wasm_v128_bitselect(lin, pw, wasm_f32x4_le(a, splat(kSrgbLinearLimit)));
    return wasm_v128_bitselect(wasm_f32x4_neg(e), e, wasm_f32x4_lt(x, splat(0.0f)));
}

} // namespace lut::detail::wasm
