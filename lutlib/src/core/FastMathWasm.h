// SPDX-License-Identifier: Apache-2.0
#pragma once
// FastMath.h's functions on four floats at once with WebAssembly SIMD (the browser edition),
// lane for lane the scalar definition's IEEE operations in the same order, so the bits are those
// of the scalar forms and of the native AVX2 kernels (docs/portable.md). The multiply-add is
// FastMath.h's exact emulation of the fused one, four lanes at a time: the products are exact in
// double, the sums round once in double, and only when a lane lands exactly halfway between two
// floats (rare) are the four recomputed by the scalar fmaEmulated.
#include "core/FastMath.h"

#include <wasm_simd128.h>

namespace lut::detail::wasm {

inline v128_t splat(float v) {
    return wasm_f32x4_splat(v);
}

// The scalar form lane by lane, for the rare sums that land halfway between two floats.
__attribute__((noinline)) inline v128_t madd4Scalar(v128_t a, v128_t b, v128_t c) {
    float fa[4], fb[4], fc[4], out[4];
    wasm_v128_store(fa, a);
    wasm_v128_store(fb, b);
    wasm_v128_store(fc, c);
    for (int i = 0; i < 4; ++i)
        out[i] = fmaEmulated(fa[i], fb[i], fc[i]);
    return wasm_v128_load(out);
}

__attribute__((always_inline)) inline v128_t madd4(v128_t a, v128_t b, v128_t c) {
    const v128_t ahi = wasm_i32x4_shuffle(a, a, 2, 3, 0, 1);
    const v128_t bhi = wasm_i32x4_shuffle(b, b, 2, 3, 0, 1);
    const v128_t chi = wasm_i32x4_shuffle(c, c, 2, 3, 0, 1);
    const v128_t abLo =
        wasm_f64x2_mul(wasm_f64x2_promote_low_f32x4(a), wasm_f64x2_promote_low_f32x4(b));
    const v128_t abHi =
        wasm_f64x2_mul(wasm_f64x2_promote_low_f32x4(ahi), wasm_f64x2_promote_low_f32x4(bhi));
    const v128_t rLo = wasm_f64x2_add(abLo, wasm_f64x2_promote_low_f32x4(c));
    const v128_t rHi = wasm_f64x2_add(abHi, wasm_f64x2_promote_low_f32x4(chi));
    const v128_t mask = wasm_i64x2_splat(0x1FFFFFFF), half = wasm_i64x2_splat(0x10000000);
    const v128_t tie = wasm_v128_or(wasm_i64x2_eq(wasm_v128_and(rLo, mask), half),
                                    wasm_i64x2_eq(wasm_v128_and(rHi, mask), half));
    if (wasm_v128_any_true(tie)) [[unlikely]] // a lane may need its last bit moved
        return madd4Scalar(a, b, c);
    return wasm_i32x4_shuffle(wasm_f32x4_demote_f64x2_zero(rLo), wasm_f32x4_demote_f64x2_zero(rHi),
                              0, 1, 4, 5);
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
    v128_t r = splat(poly::kLog[0]);
    for (int i = 1; i < 4; ++i)
        r = madd4(r, u2, splat(poly::kLog[i]));
    return wasm_f32x4_mul(u, r);
}

// exp2Times, four lanes.
inline v128_t exp2Times4(v128_t p, v128_t e, v128_t l) {
    const v128_t hi = wasm_f32x4_mul(p, e);
    const v128_t lo = madd4(p, l, madd4(p, e, wasm_f32x4_neg(hi)));
    v128_t n = wasm_f32x4_nearest(wasm_f32x4_add(hi, lo));
    const v128_t f = wasm_f32x4_add(wasm_f32x4_sub(hi, n), lo);
    // n > 127 ? 127 : (n < -127 ? -127 : n), as the scalar form (NaN stays)
    n = wasm_v128_bitselect(splat(127.0f), n, wasm_f32x4_gt(n, splat(127.0f)));
    n = wasm_v128_bitselect(splat(-127.0f), n, wasm_f32x4_lt(n, splat(-127.0f)));
    v128_t q = splat(poly::kExp2[0]);
    for (int i = 1; i < 6; ++i)
        q = madd4(q, f, splat(poly::kExp2[i]));
    q = madd4(q, f, splat(1.0f));
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
    const v128_t pw = madd4(splat(1.055f), powFast4(a, 1.0f / 2.4f), splat(-0.055f));
    const v128_t lin = wasm_f32x4_mul(splat(12.92f), a);
    const v128_t e = wasm_v128_bitselect(lin, pw, wasm_f32x4_le(a, splat(kSrgbLinearLimit)));
    return wasm_v128_bitselect(wasm_f32x4_neg(e), e, wasm_f32x4_lt(x, splat(0.0f)));
}

// smashDisplayFast, four lanes.
inline v128_t smashDisplay4(v128_t r) {
    const v128_t ok = wasm_f32x4_ge(r, splat(poly::kMinNormal));
    const v128_t safe = wasm_v128_bitselect(r, splat(1.0f), ok);
    v128_t e;
    const v128_t l = log2Mantissa4(safe, e);
    const v128_t low = wasm_f32x4_le(r, splat(kSmashDisplayLowR));
    const v128_t p = wasm_v128_bitselect(splat(2.2f), splat(kSmashDisplayHighP), low);
    const v128_t out = exp2Times4(p, e, l);
    const v128_t o = wasm_v128_bitselect(wasm_f32x4_mul(splat(12.92f), out),
                                         madd4(splat(1.055f), out, splat(-0.055f)), low);
    return wasm_v128_and(o, ok);
}

} // namespace lut::detail::wasm
