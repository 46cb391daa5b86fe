// SPDX-License-Identifier: Apache-2.0
#pragma once
// FastMath.h's functions on four floats at once with WebAssembly SIMD (the browser edition),
// lane for lane the scalar definition's IEEE operations in the same order, so the bits are those
// of the scalar forms and of the native AVX2 kernels (docs/portable.md). The multiply-add is
// FastMath.h's exact emulation of the fused one, four lanes at a time: the products are exact in
// double, the sums round once in double, and only when a lane lands exactly halfway between two
// floats (rare) are the four recomputed by the scalar definition: madd4 redoes that multiply-add
// with fmaEmulated; the polynomial functions below (madd4Deferred) test once at their end and redo
// the whole function lane by lane with FastMath.h's scalar form. No native code changes: the bits
// are the same by construction, tested against the native CLI's in tests/web/test_same_bytes.py.
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
    // The four doubles' low 32-bit words (little-endian), where the 29 bits a float drops end.
    const v128_t low = wasm_i32x4_shuffle(rLo, rHi, 0, 2, 4, 6);
    const v128_t tie = wasm_i32x4_eq(wasm_v128_and(low, wasm_i32x4_splat(0x1FFFFFFF)),
                                     wasm_i32x4_splat(0x10000000));
    if (wasm_v128_any_true(tie)) [[unlikely]] // a lane may need its last bit moved
        return madd4Scalar(a, b, c);
    return wasm_i32x4_shuffle(wasm_f32x4_demote_f64x2_zero(rLo), wasm_f32x4_demote_f64x2_zero(rHi),
                              0, 1, 4, 5);
}

// madd4 with its halfway test deferred: the lanes that landed halfway are or-ed into `ties`
// and the result is the double's rounding. A caller whose every step saw no tie has the fused
// bits in every lane (the one rounding and the double's agree off the halfway points); one that
// saw a tie recomputes its four lanes with the scalar definition. One test per function instead
// of a branch per multiply-add: the polynomials are a third faster.
__attribute__((always_inline)) inline v128_t madd4Deferred(v128_t a, v128_t b, v128_t c,
                                                           v128_t& ties) {
    const v128_t ahi = wasm_i32x4_shuffle(a, a, 2, 3, 0, 1);
    const v128_t bhi = wasm_i32x4_shuffle(b, b, 2, 3, 0, 1);
    const v128_t chi = wasm_i32x4_shuffle(c, c, 2, 3, 0, 1);
    const v128_t abLo =
        wasm_f64x2_mul(wasm_f64x2_promote_low_f32x4(a), wasm_f64x2_promote_low_f32x4(b));
    const v128_t abHi =
        wasm_f64x2_mul(wasm_f64x2_promote_low_f32x4(ahi), wasm_f64x2_promote_low_f32x4(bhi));
    const v128_t rLo = wasm_f64x2_add(abLo, wasm_f64x2_promote_low_f32x4(c));
    const v128_t rHi = wasm_f64x2_add(abHi, wasm_f64x2_promote_low_f32x4(chi));
    const v128_t low = wasm_i32x4_shuffle(rLo, rHi, 0, 2, 4, 6);
    ties = wasm_v128_or(ties, wasm_i32x4_eq(wasm_v128_and(low, wasm_i32x4_splat(0x1FFFFFFF)),
                                            wasm_i32x4_splat(0x10000000)));
    return wasm_i32x4_shuffle(wasm_f32x4_demote_f64x2_zero(rLo), wasm_f32x4_demote_f64x2_zero(rHi),
                              0, 1, 4, 5);
}

// a * b - c where c is the float nearest a * b: the product's rounding error, which a float holds
// exactly (no underflow below 2^-149 matters: the one rounding happens in the demotion). In double
// the product is exact and so is the difference, so the float is the fused multiply-add's without
// madd4's halfway test (exp2Times' split of p * e; FastMath.h).
__attribute__((always_inline)) inline v128_t productError4(v128_t a, v128_t b, v128_t c) {
    const v128_t ahi = wasm_i32x4_shuffle(a, a, 2, 3, 0, 1);
    const v128_t bhi = wasm_i32x4_shuffle(b, b, 2, 3, 0, 1);
    const v128_t chi = wasm_i32x4_shuffle(c, c, 2, 3, 0, 1);
    const v128_t rLo = wasm_f64x2_sub(
        wasm_f64x2_mul(wasm_f64x2_promote_low_f32x4(a), wasm_f64x2_promote_low_f32x4(b)),
        wasm_f64x2_promote_low_f32x4(c));
    const v128_t rHi = wasm_f64x2_sub(
        wasm_f64x2_mul(wasm_f64x2_promote_low_f32x4(ahi), wasm_f64x2_promote_low_f32x4(bhi)),
        wasm_f64x2_promote_low_f32x4(chi));
    return wasm_i32x4_shuffle(wasm_f32x4_demote_f64x2_zero(rLo), wasm_f32x4_demote_f64x2_zero(rHi),
                              0, 1, 4, 5);
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

// f's scalar definition lane by lane: where a deferred halfway test fired.
template <class F> __attribute__((noinline)) v128_t scalarLanes(v128_t x, F f) {
    float in[4], out[4];
    wasm_v128_store(in, x);
    for (int i = 0; i < 4; ++i)
        out[i] = f(in[i]);
    return wasm_v128_load(out);
}

// log2Mantissa, four lanes (x must be > 0 and normal in the lanes that are used).
inline v128_t log2Mantissa4(v128_t x, v128_t& e, v128_t& ties) {
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
        r = madd4Deferred(r, u2, splat(poly::kLog[i]), ties);
    return wasm_f32x4_mul(u, r);
}

// exp2Times, four lanes.
inline v128_t exp2Times4(v128_t p, v128_t e, v128_t l, v128_t& ties) {
    const v128_t hi = wasm_f32x4_mul(p, e);
    const v128_t lo = madd4Deferred(p, l, productError4(p, e, hi), ties);
    v128_t n = wasm_f32x4_nearest(wasm_f32x4_add(hi, lo));
    const v128_t f = wasm_f32x4_add(wasm_f32x4_sub(hi, n), lo);
    // n > 127 ? 127 : (n < -127 ? -127 : n), as the scalar form (NaN stays)
    n = wasm_v128_bitselect(splat(127.0f), n, wasm_f32x4_gt(n, splat(127.0f)));
    n = wasm_v128_bitselect(splat(-127.0f), n, wasm_f32x4_lt(n, splat(-127.0f)));
    v128_t q = splat(poly::kExp2[0]);
    for (int i = 1; i < 6; ++i)
        q = madd4Deferred(q, f, splat(poly::kExp2[i]), ties);
    q = madd4Deferred(q, f, splat(1.0f), ties);
    const v128_t bits =
        wasm_i32x4_shl(wasm_i32x4_add(wasm_i32x4_trunc_sat_f32x4(n), wasm_i32x4_splat(127)), 23);
    return wasm_f32x4_mul(q, bits);
}

// powFast, four lanes: lanes with !(x >= 2^-126) give 0.
inline v128_t powFast4(v128_t x, float p) {
    const v128_t ok = wasm_f32x4_ge(x, splat(poly::kMinNormal));
    const v128_t safe = wasm_v128_bitselect(x, splat(1.0f), ok);
    v128_t e, ties = wasm_i32x4_splat(0);
    const v128_t l = log2Mantissa4(safe, e, ties);
    const v128_t out = wasm_v128_and(exp2Times4(splat(p), e, l, ties), ok);
    if (wasm_v128_any_true(ties)) [[unlikely]]
        return scalarLanes(x, [p](float v) { return powFast(v, p); });
    return out;
}

// srgbEncodeFast, four lanes.
inline v128_t srgbEncode4(v128_t x) {
    const v128_t a = wasm_f32x4_abs(x);
    v128_t ties = wasm_i32x4_splat(0);
    const v128_t pw = madd4Deferred(splat(1.055f), powFast4(a, 1.0f / 2.4f), splat(-0.055f), ties);
    const v128_t lin = wasm_f32x4_mul(splat(12.92f), a);
    const v128_t e = wasm_v128_bitselect(lin, pw, wasm_f32x4_le(a, splat(kSrgbLinearLimit)));
    const v128_t out = wasm_v128_bitselect(wasm_f32x4_neg(e), e, wasm_f32x4_lt(x, splat(0.0f)));
    if (wasm_v128_any_true(ties)) [[unlikely]]
        return scalarLanes(x, [](float v) { return srgbEncodeFast(v); });
    return out;
}

// smashDisplayFast, four lanes.
inline v128_t smashDisplay4(v128_t r) {
    const v128_t ok = wasm_f32x4_ge(r, splat(poly::kMinNormal));
    const v128_t safe = wasm_v128_bitselect(r, splat(1.0f), ok);
    v128_t e, ties = wasm_i32x4_splat(0);
    const v128_t l = log2Mantissa4(safe, e, ties);
    const v128_t low = wasm_f32x4_le(r, splat(kSmashDisplayLowR));
    const v128_t p = wasm_v128_bitselect(splat(2.2f), splat(kSmashDisplayHighP), low);
    const v128_t out = exp2Times4(p, e, l, ties);
    const v128_t o =
        wasm_v128_bitselect(wasm_f32x4_mul(splat(12.92f), out),
                            madd4Deferred(splat(1.055f), out, splat(-0.055f), ties), low);
    if (wasm_v128_any_true(ties)) [[unlikely]]
        return scalarLanes(r, [](float v) { return smashDisplayFast(v); });
    return wasm_v128_and(o, ok);
}

} // namespace lut::detail::wasm
