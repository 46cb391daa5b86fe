// SPDX-License-Identifier: Apache-2.0
#pragma once
// Polynomial pow() for the pipeline's hot loops: pow(x, p) = exp2(p * log2(x)) with log2 and exp2
// from Cephes-style minimax polynomials and the product p * log2(x) carried in two floats, so the
// result is within 4e-7 relative of the exact power for every normal x > 0 (tested against
// std::pow in tests/pipeline/test_stages.cpp). No tables: the grading pass runs six of these per
// pixel, and table lookups (gathers) cost more than the arithmetic on the cores we measured.
//
// These scalar functions are the definition. ArrayKernels.cpp has 8-lane AVX2 forms and
// FastMathWasm.h 4-lane WebAssembly forms that perform the same IEEE operations in the same
// order, and therefore give the same bits: the choice of path or edition never changes a frame,
// and a pixel's result never depends on its neighbours. Every multiply-add here is a multiply
// then an add, two roundings (mulAdd(); lutlib is compiled with -ffp-contract=off, so the
// compiler fuses nothing): every machine computes that the same way in one instruction each,
// WebAssembly included, which has no fused multiply-add. The one place the polynomials needed a
// fused one, the exact product p * e in exp2Times, is two exact products instead (splitHigh).
//
// The game's display curve in one power (the sRGB encode of r^2.2) is the game's:
// smash/SmashDisplayFast.h, built on these.
//
// Domain: x <= 0, NaN and denormals give 0; results are clamped below 2^127 * 1.42 (finite for
// any finite or infinite input); results below 2^-126 flush to 0.
#include <bit>
#include <cmath>
#include <cstdint>

namespace lut::detail {

// a * b + c with one rounding, as the FMA instruction computes it: the bits of the interpolation
// kernels (interp/PortableKernels.cpp and the AVX2 ones), on every machine and in every edition
// (docs/portable.md). Where the CPU has FMA it is
// that instruction (std::fma); elsewhere (an x86-64 without FMA, WebAssembly) it is computed here:
// the product of two floats is exact in double, the sum rounds once in double, and only a sum
// that lands exactly halfway between two floats (and is inexact) needs its last bit moved towards
// the error, so the float is the one a single rounding gives (musl's fmaf, inlined: a library
// call cost WebAssembly 41% of a preview).
inline float fmaEmulated(float a, float b, float c) {
    const double ab = static_cast<double>(a) * static_cast<double>(b);
    const double r = ab + static_cast<double>(c);
    std::uint64_t u = __builtin_bit_cast(std::uint64_t, r);
    const unsigned e = static_cast<unsigned>(u >> 52) & 0x7FFu;
    if ((u & 0x1FFFFFFFu) != 0x10000000u || e == 0x7FFu || (r - ab == c && r - c == ab))
        return static_cast<float>(r);
    const bool negative = (u >> 63) != 0;
    const double err = negative == (static_cast<double>(c) > ab) ? ab - r + c : c - r + ab;
    if (negative == (err < 0))
        ++u;
    else
        --u;
    return static_cast<float>(__builtin_bit_cast(double, u));
}

#if defined(__x86_64__) || defined(__i386__)
inline bool cpuHasFma() {
    static const bool yes = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("fma") != 0;
    }();
    return yes;
}
inline float madd(float a, float b, float c) {
    return cpuHasFma() ? std::fma(a, b, c) : fmaEmulated(a, b, c);
}
#else
inline float madd(float a, float b, float c) {
    return fmaEmulated(a, b, c);
}
#endif

// a * b + c as a multiply then an add (two roundings): the pow kernels' multiply-add, the same
// bits on every machine without a fused instruction (the header's comment).
inline float mulAdd(float a, float b, float c) {
    const float ab = a * b;
    return ab + c;
}

// p = splitHigh(p) + (p - splitHigh(p)): p's high 12 significant bits and the rest (at most 12
// bits), both exact. Times a whole number of at most 8 bits (a binary exponent, |e| <= 255), each
// part's product fits in 20 bits, so is exact: p * e = ph * e + pl * e with no rounding, what
// exp2Times needs without a fused multiply-add (Dekker's split, with e unsplit).
inline float splitHigh(float p) {
    return __builtin_bit_cast(float, __builtin_bit_cast(std::uint32_t, p) & 0xFFFFF000u);
}

// The polynomials are evaluated in Estrin's scheme (pairs of terms, then pairs of pairs), not
// Horner's: the dependency chain is half as long, which a multiply then an add (two latencies per
// step where the fused instruction has one) needs for the AVX2 kernels to keep their speed.
namespace poly {
// log2(m) = u * (c0 + c1 u^2 + c2 u^4 + c3 u^6) with u = (m - 1) / (m + 1), the series of
// 2 atanh(u) / ln 2; for m in [sqrt(1/2), sqrt(2)), |u| <= 0.1716 and the dropped terms are
// below 5e-8.
constexpr float kLog[4] = {0.41219858311113244f, 0.5770780163555853f, 0.9617966939259757f,
                           2.8853900817779268f};
// 2^f - 1 = f P(f) for f in [-1/2, 1/2] (Cephes exp2f).
constexpr float kExp2[6] = {1.535336188319500E-4f, 1.339887440266574E-3f, 9.618437357674640E-3f,
                            5.550332471162809E-2f, 2.402264791363012E-1f, 6.931472028550421E-1f};
constexpr float kSqrt2 = 1.41421356237309504880f;
constexpr float kMinNormal = 1.17549435e-38f;
} // namespace poly

// x = 2^e * m with m in [sqrt(1/2), sqrt(2)); returns log2(m) and sets e. x must be > 0, normal.
inline float log2Mantissa(float x, float& e) {
    const std::uint32_t b = __builtin_bit_cast(std::uint32_t, x);
    int ei = static_cast<int>(b >> 23) - 127;
    float m = __builtin_bit_cast(float, (b & 0x7FFFFFu) | 0x3F800000u);
    if (m > poly::kSqrt2) {
        m = m * 0.5f;
        ei = ei + 1;
    }
    e = static_cast<float>(ei);
    const float u = (m - 1.0f) / (m + 1.0f);
    const float u2 = u * u;
    const float u4 = u2 * u2;
    return u * mulAdd(mulAdd(poly::kLog[0], u2, poly::kLog[1]), u4,
                      mulAdd(poly::kLog[2], u2, poly::kLog[3]));
}

// 2^(p * (e + l)) with log2(x) = e + l from log2Mantissa: p * e is carried exactly as hi + the
// low part's ph * e (splitHigh), so the fraction handed to the polynomial keeps its low bits
// whatever the size of e. The exponent n is clamped to [-127, 127] (2^-127 encodes as 0: results
// below 2^-126 flush to zero).
inline float exp2Times(float p, float e, float l) {
    const float ph = splitHigh(p);
    const float hi = ph * e;
    const float lo = mulAdd(p, l, (p - ph) * e);
    float n = std::nearbyint(hi + lo);
    const float f = (hi - n) + lo;
    n = n > 127.0f ? 127.0f : (n < -127.0f ? -127.0f : n);
    const float f2 = f * f;
    const float a = mulAdd(poly::kExp2[0], f, poly::kExp2[1]);
    const float b = mulAdd(poly::kExp2[2], f, poly::kExp2[3]);
    const float c = mulAdd(poly::kExp2[4], f, poly::kExp2[5]);
    const float q = mulAdd(mulAdd(mulAdd(a, f2, b), f2, c), f, 1.0f);
    const float scale =
        __builtin_bit_cast(float, static_cast<std::uint32_t>(static_cast<int>(n) + 127) << 23);
    return q * scale;
}

// pow(x, p); x <= 0, NaN and denormals give 0.
inline float powFast(float x, float p) {
    if (!(x >= poly::kMinNormal))
        return 0.0f;
    float e;
    const float l = log2Mantissa(x, e);
    return exp2Times(p, e, l);
}

// Piecewise sRGB encode, mirrored for negatives (-0 encodes to +0); finite input.
constexpr float kSrgbLinearLimit = 0.0031308f;
inline float srgbEncodeFast(float x) {
    const float a = std::fabs(x);
    const float e =
        a <= kSrgbLinearLimit ? 12.92f * a : mulAdd(1.055f, powFast(a, 1.0f / 2.4f), -0.055f);
    return x < 0.0f ? -e : e;
}

// NaN -> 0; clamps to [-lim, lim].
inline float sanitizeValue(float v, float lim) {
    if (!(v == v))
        return 0.0f;
    return v > lim ? lim : (v < -lim ? -lim : v);
}

inline float clamp01(float v) {
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
} // NaN -> 0

} // namespace lut::detail
