// SPDX-License-Identifier: Apache-2.0
#include "ArrayKernels.h"

#include "lut/smash/SmashGrading.h"
#include "smash/SmashDisplayFast.h"

#if defined(__x86_64__) || defined(__i386__)
#include "core/simd/Transpose.h"

#include <immintrin.h>
#define LUTKIT_X86 1
#elif defined(__wasm_simd128__)
#include "smash/SmashDisplayWasm.h"
#define LUTKIT_WASM_SIMD 1
#endif

namespace lut::detail {

namespace {

// Scalar forms: the definition, and the tails of the SIMD loops.

void smashFinishPixel(float* x, const float* s, const float* l, bool fused) {
    const float a = clamp01(x[3]);
    if (a <= 0.0f) {
        if (fused)
            for (int c = 0; c < 3; ++c)
                x[c] = srgbEncodeFast(x[c]);
        return;
    }
    for (int c = 0; c < 3; ++c) {
        const float r = mulAdd(l[c] - s[c], kSmashBrightenMix, s[c]) * kSmashBrightenScale;
        if (a >= 1.0f) {
            x[c] = fused ? smashDisplayFast(r) : powFast(r, kSmashDecodeExponent);
            continue;
        }
        const float g = powFast(r, kSmashDecodeExponent);
        const float m = mulAdd(g, a, x[c] * (1.0f - a));
        x[c] = fused ? srgbEncodeFast(m) : m;
    }
}

void smashEncodePixel(const float* x, float* s, float* l) {
    for (int c = 0; c < 3; ++c)
        s[c] = l[c] = powFast(x[c], kSmashEncodeExponent);
    s[3] = l[3] = x[3];
}

void addBloomPixel(float* p, const float* a, const float* b, float t) {
    for (int c = 0; c < 3; ++c) {
        const float v = a[c] + (b[c] - a[c]) * t;
        if (v != 0.0f)
            p[c] = p[c] + v;
    }
}

#ifdef LUTKIT_X86
#define LUTKIT_AVX2 __attribute__((target("avx2,fma")))

// 8-lane forms of FastMath.h, operation for operation (a multiply then an add where it has
// mulAdd; -ffp-contract=off keeps the compiler from fusing them).

LUTKIT_AVX2 inline __m256 splat(float v) {
    return _mm256_set1_ps(v);
}

LUTKIT_AVX2 inline __m256 mulAdd8(__m256 a, __m256 b, __m256 c) {
    return _mm256_add_ps(_mm256_mul_ps(a, b), c);
}

// splitHigh, 8 lanes.
LUTKIT_AVX2 inline __m256 splitHigh8(__m256 p) {
    return _mm256_and_ps(p, _mm256_castsi256_ps(_mm256_set1_epi32(-4096)));
}

// K independent 8-lane values computed step by step together, so the long dependency chains of
// the polynomials interleave (the kernels are latency-bound one value at a time).
template <int K> struct Vec { __m256 v[K]; };

template <int K> LUTKIT_AVX2 inline Vec<K> log2Mantissa8(const Vec<K>& x, Vec<K>& e) {
    Vec<K> u, u2, r;
    for (int k = 0; k < K; ++k) {
        const __m256i b = _mm256_castps_si256(x.v[k]);
        __m256i ei = _mm256_sub_epi32(_mm256_srli_epi32(b, 23), _mm256_set1_epi32(127));
        __m256 m = _mm256_castsi256_ps(_mm256_or_si256(
            _mm256_and_si256(b, _mm256_set1_epi32(0x7FFFFF)), _mm256_set1_epi32(0x3F800000)));
        const __m256 big = _mm256_cmp_ps(m, splat(poly::kSqrt2), _CMP_GT_OQ);
        m = _mm256_blendv_ps(m, _mm256_mul_ps(m, splat(0.5f)), big);
        ei = _mm256_sub_epi32(ei, _mm256_castps_si256(big)); // mask is -1: adds 1
        e.v[k] = _mm256_cvtepi32_ps(ei);
        u.v[k] = _mm256_div_ps(_mm256_sub_ps(m, splat(1.0f)), _mm256_add_ps(m, splat(1.0f)));
        u2.v[k] = _mm256_mul_ps(u.v[k], u.v[k]);
    }
    for (int k = 0; k < K; ++k) {
        const __m256 u4 = _mm256_mul_ps(u2.v[k], u2.v[k]);
        r.v[k] = _mm256_mul_ps(
            u.v[k], mulAdd8(mulAdd8(splat(poly::kLog[0]), u2.v[k], splat(poly::kLog[1])), u4,
                            mulAdd8(splat(poly::kLog[2]), u2.v[k], splat(poly::kLog[3]))));
    }
    return r;
}

// 2^(p * (e + l)), p * e carried exactly as hi + lo's ph * e (FastMath.h exp2Times).
template <int K>
LUTKIT_AVX2 inline Vec<K> exp2Times8(const Vec<K>& p, const Vec<K>& e, const Vec<K>& l) {
    constexpr int kNearest = _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC;
    Vec<K> f, n, q;
    for (int k = 0; k < K; ++k) {
        const __m256 ph = splitHigh8(p.v[k]);
        const __m256 hi = _mm256_mul_ps(ph, e.v[k]);
        const __m256 lo = mulAdd8(p.v[k], l.v[k], _mm256_mul_ps(_mm256_sub_ps(p.v[k], ph), e.v[k]));
        n.v[k] = _mm256_round_ps(_mm256_add_ps(hi, lo), kNearest);
        f.v[k] = _mm256_add_ps(_mm256_sub_ps(hi, n.v[k]), lo);
        n.v[k] = _mm256_min_ps(_mm256_max_ps(n.v[k], splat(-127.0f)), splat(127.0f));
    }
    for (int k = 0; k < K; ++k) {
        const __m256 f2 = _mm256_mul_ps(f.v[k], f.v[k]);
        const __m256 a = mulAdd8(splat(poly::kExp2[0]), f.v[k], splat(poly::kExp2[1]));
        const __m256 b = mulAdd8(splat(poly::kExp2[2]), f.v[k], splat(poly::kExp2[3]));
        const __m256 c = mulAdd8(splat(poly::kExp2[4]), f.v[k], splat(poly::kExp2[5]));
        q.v[k] = mulAdd8(mulAdd8(mulAdd8(a, f2, b), f2, c), f.v[k], splat(1.0f));
        const __m256i bits = _mm256_add_epi32(_mm256_cvttps_epi32(n.v[k]), _mm256_set1_epi32(127));
        q.v[k] = _mm256_mul_ps(q.v[k], _mm256_castsi256_ps(_mm256_slli_epi32(bits, 23)));
    }
    return q;
}

// pow(x, p) from log2(x) = e + l already taken (log2Mantissa8); lanes with x < 2^-126 give 0.
template <int K>
LUTKIT_AVX2 inline Vec<K> powFromLog8(const Vec<K>& x, const Vec<K>& e, const Vec<K>& l, float p) {
    Vec<K> pv;
    for (int k = 0; k < K; ++k)
        pv.v[k] = splat(p);
    Vec<K> out = exp2Times8(pv, e, l);
    for (int k = 0; k < K; ++k)
        out.v[k] =
            _mm256_and_ps(out.v[k], _mm256_cmp_ps(x.v[k], splat(poly::kMinNormal), _CMP_GE_OQ));
    return out;
}

template <int K> LUTKIT_AVX2 inline Vec<K> pow8(const Vec<K>& x, float p) {
    Vec<K> e;
    const Vec<K> l = log2Mantissa8(x, e);
    return powFromLog8(x, e, l, p);
}

template <int K> LUTKIT_AVX2 inline Vec<K> srgb8(const Vec<K>& x) {
    const __m256 sign = splat(-0.0f);
    Vec<K> a;
    for (int k = 0; k < K; ++k)
        a.v[k] = _mm256_andnot_ps(sign, x.v[k]);
    Vec<K> out = pow8(a, 1.0f / 2.4f);
    for (int k = 0; k < K; ++k) {
        const __m256 pw = mulAdd8(splat(1.055f), out.v[k], splat(-0.055f));
        const __m256 lin = _mm256_mul_ps(splat(12.92f), a.v[k]);
        const __m256 e =
            _mm256_blendv_ps(pw, lin, _mm256_cmp_ps(a.v[k], splat(kSrgbLinearLimit), _CMP_LE_OQ));
        const __m256 neg = _mm256_cmp_ps(x.v[k], _mm256_setzero_ps(), _CMP_LT_OQ);
        out.v[k] = _mm256_xor_ps(e, _mm256_and_ps(neg, sign));
    }
    return out;
}

// smashDisplayFast from log2(r) = e + l already taken.
template <int K>
LUTKIT_AVX2 inline Vec<K> displayFromLog8(const Vec<K>& r, const Vec<K>& e, const Vec<K>& l) {
    Vec<K> p, low;
    for (int k = 0; k < K; ++k) {
        low.v[k] = _mm256_cmp_ps(r.v[k], splat(kSmashDisplayLowR), _CMP_LE_OQ);
        p.v[k] = _mm256_blendv_ps(splat(kSmashDisplayHighP), splat(2.2f), low.v[k]);
    }
    Vec<K> out = exp2Times8(p, e, l);
    for (int k = 0; k < K; ++k) {
        const __m256 o = _mm256_blendv_ps(mulAdd8(splat(1.055f), out.v[k], splat(-0.055f)),
                                          _mm256_mul_ps(splat(12.92f), out.v[k]), low.v[k]);
        out.v[k] = _mm256_and_ps(o, _mm256_cmp_ps(r.v[k], splat(poly::kMinNormal), _CMP_GE_OQ));
    }
    return out;
}

template <int K> LUTKIT_AVX2 inline Vec<K> display8(const Vec<K>& r) {
    Vec<K> e;
    const Vec<K> l = log2Mantissa8(r, e);
    return displayFromLog8(r, e, l);
}

// Four registers of two RGBA pixels each, transposed to R, G, B, A planes (lane order
// 0 2 4 6 | 1 3 5 7) on load and back on store.
LUTKIT_AVX2 inline Vec<4> loadPlanes(const float* p) {
    Vec<4> q;
    for (int i = 0; i < 4; ++i)
        q.v[i] = _mm256_loadu_ps(p + 8 * i);
    transpose4(q.v[0], q.v[1], q.v[2], q.v[3]);
    return q;
}

LUTKIT_AVX2 inline void storePlanes(float* p, Vec<4> q) {
    transpose4(q.v[0], q.v[1], q.v[2], q.v[3]);
    for (int i = 0; i < 4; ++i)
        _mm256_storeu_ps(p + 8 * i, q.v[i]);
}

// Array loops.

LUTKIT_AVX2 void powAvx2(float p, const float* in, float* out, std::size_t n) {
    std::size_t i = 0;
    for (; i + 16 <= n; i += 16) {
        const Vec<2> o = pow8(Vec<2>{{_mm256_loadu_ps(in + i), _mm256_loadu_ps(in + i + 8)}}, p);
        _mm256_storeu_ps(out + i, o.v[0]);
        _mm256_storeu_ps(out + i + 8, o.v[1]);
    }
    for (; i + 8 <= n; i += 8)
        _mm256_storeu_ps(out + i, pow8(Vec<1>{{_mm256_loadu_ps(in + i)}}, p).v[0]);
    for (; i < n; ++i)
        out[i] = powFast(in[i], p);
}

LUTKIT_AVX2 void srgbAvx2(const float* in, float* out, std::size_t n) {
    std::size_t i = 0;
    for (; i + 16 <= n; i += 16) {
        const Vec<2> o = srgb8(Vec<2>{{_mm256_loadu_ps(in + i), _mm256_loadu_ps(in + i + 8)}});
        _mm256_storeu_ps(out + i, o.v[0]);
        _mm256_storeu_ps(out + i + 8, o.v[1]);
    }
    for (; i + 8 <= n; i += 8)
        _mm256_storeu_ps(out + i, srgb8(Vec<1>{{_mm256_loadu_ps(in + i)}}).v[0]);
    for (; i < n; ++i)
        out[i] = srgbEncodeFast(in[i]);
}

LUTKIT_AVX2 void smashEncodeAvx2(const float* x, float* s, float* l, std::size_t count) {
    std::size_t i = 0;
    for (; i + 8 <= count; i += 8) {
        Vec<4> q = loadPlanes(x + 4 * i);
        const Vec<3> sv = pow8(Vec<3>{{q.v[0], q.v[1], q.v[2]}}, kSmashEncodeExponent);
        for (int c = 0; c < 3; ++c)
            q.v[c] = sv.v[c];
        storePlanes(s + 4 * i, q);
        storePlanes(l + 4 * i, q);
    }
    for (; i < count; ++i)
        smashEncodePixel(x + 4 * i, s + 4 * i, l + 4 * i);
}

LUTKIT_AVX2 void smashFinishAvx2(float* x, const float* s, const float* l, std::size_t count,
                                 bool fused) {
    const __m256 one = splat(1.0f), zero = _mm256_setzero_ps();
    std::size_t i = 0;
    for (; i + 8 <= count; i += 8) {
        float* px = x + 4 * i;
        Vec<4> q = loadPlanes(px);
        const Vec<3> xv{{q.v[0], q.v[1], q.v[2]}};
        const __m256 a = _mm256_min_ps(_mm256_max_ps(q.v[3], zero), one); // NaN -> 0
        const __m256 none = _mm256_cmp_ps(a, zero, _CMP_LE_OQ);
        const __m256 full = _mm256_cmp_ps(a, one, _CMP_GE_OQ);
        const int noneBits = _mm256_movemask_ps(none), fullBits = _mm256_movemask_ps(full);
        Vec<3> out;
        if (noneBits == 0xFF) { // nothing graded: only the display encode
            if (!fused)
                continue;
            out = srgb8(xv);
        } else {
            const Vec<4> qs = loadPlanes(s + 4 * i), ql = loadPlanes(l + 4 * i);
            Vec<3> r;
            for (int c = 0; c < 3; ++c)
                r.v[c] = _mm256_mul_ps(
                    mulAdd8(_mm256_sub_ps(ql.v[c], qs.v[c]), splat(kSmashBrightenMix), qs.v[c]),
                    splat(kSmashBrightenScale));
            if (fullBits == 0xFF) { // fully graded: the common case
                out = fused ? display8(r) : pow8(r, kSmashDecodeExponent);
            } else {
                // A mixed group: each lane gets its own kind's result, and only the kinds
                // present are computed (partial alpha needs r^2.2 and, fused, the sRGB of the
                // mix; alpha 0 the sRGB of x, which shares that one encode).
                const __m256 partial = _mm256_andnot_ps(_mm256_or_ps(none, full),
                                                        _mm256_castsi256_ps(_mm256_set1_epi32(-1)));
                const bool anyPartial = _mm256_movemask_ps(partial) != 0;
                const bool anyFull = fullBits != 0;
                // log2(r) once for both r^2.2 and the fused display of the full lanes.
                Vec<3> re;
                const Vec<3> rl = log2Mantissa8(r, re);
                Vec<3> g{}, m = xv;
                if (anyPartial || (anyFull && !fused)) {
                    g = powFromLog8(r, re, rl, kSmashDecodeExponent);
                    const __m256 inv = _mm256_sub_ps(one, a);
                    for (int c = 0; c < 3; ++c)
                        m.v[c] = _mm256_blendv_ps(mulAdd8(g.v[c], a, _mm256_mul_ps(xv.v[c], inv)),
                                                  xv.v[c], none);
                }
                if (fused) {
                    out = srgb8(m); // alpha 0 lanes: srgb(x); partial lanes: srgb(mix)
                    if (anyFull) {
                        const Vec<3> d = displayFromLog8(r, re, rl);
                        for (int c = 0; c < 3; ++c)
                            out.v[c] = _mm256_blendv_ps(out.v[c], d.v[c], full);
                    }
                } else {
                    for (int c = 0; c < 3; ++c)
                        out.v[c] = _mm256_blendv_ps(m.v[c], g.v[c], full);
                }
            }
        }
        for (int c = 0; c < 3; ++c)
            q.v[c] = out.v[c];
        storePlanes(px, q);
    }
    for (; i < count; ++i)
        smashFinishPixel(x + 4 * i, s + 4 * i, l + 4 * i, fused);
}

// Two pixels per register: each half is one pixel's RGBA, the bloom texel's 4th float is 0.
LUTKIT_AVX2 void addBloomRowAvx2(float* rgba, int width, const float* row4, const int* i0,
                                 const int* i1, const float* t) {
    int k = 0;
    for (; k + 2 <= width; k += 2) {
        const __m256 a =
            _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(row4 + 4 * i0[k])),
                                 _mm_loadu_ps(row4 + 4 * i0[k + 1]), 1);
        const __m256 b =
            _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(row4 + 4 * i1[k])),
                                 _mm_loadu_ps(row4 + 4 * i1[k + 1]), 1);
        const __m256 tt = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_set1_ps(t[k])),
                                               _mm_set1_ps(t[k + 1]), 1);
        const __m256 v = _mm256_add_ps(a, _mm256_mul_ps(_mm256_sub_ps(b, a), tt));
        float* p = rgba + 4 * k;
        const __m256 px = _mm256_loadu_ps(p);
        const __m256 zero = _mm256_cmp_ps(v, _mm256_setzero_ps(), _CMP_EQ_OQ);
        _mm256_storeu_ps(p, _mm256_blendv_ps(_mm256_add_ps(px, v), px, zero));
    }
    for (; k < width; ++k)
        addBloomPixel(rgba + 4 * k, row4 + 4 * i0[k], row4 + 4 * i1[k], t[k]);
}

bool haveAvx2() {
    static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    return yes;
}
#else
[[maybe_unused]] bool haveAvx2() {
    return false;
}
#endif

#ifdef LUTKIT_WASM_SIMD
// WebAssembly SIMD (FastMathWasm.h): the scalar definitions four lanes at a time; a pixel's R, G,
// B (and A, computed and not kept) are one vector, so the per-pixel branches are the scalar ones.

void powWasm(float p, const float* in, float* out, std::size_t n) {
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4)
        wasm_v128_store(out + i, wasm::powFast4(wasm_v128_load(in + i), p));
    for (; i < n; ++i)
        out[i] = powFast(in[i], p);
}

void srgbWasm(const float* in, float* out, std::size_t n) {
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4)
        wasm_v128_store(out + i, wasm::srgbEncode4(wasm_v128_load(in + i)));
    for (; i < n; ++i)
        out[i] = srgbEncodeFast(in[i]);
}

// lanes 0-2 of v, lane 3 of keep
inline v128_t rgbOf(v128_t v, v128_t keep) {
    return wasm_i32x4_shuffle(v, keep, 0, 1, 2, 7);
}

// One pixel as one vector: the tails, and groups of four with mixed alpha.
void smashFinishWasmPixel(float* p, const float* s, const float* l, bool fused) {
    const v128_t px = wasm_v128_load(p);
    const float a = clamp01(p[3]);
    if (a <= 0.0f) {
        if (fused)
            wasm_v128_store(p, rgbOf(wasm::srgbEncode4(px), px));
        return;
    }
    const v128_t sv = wasm_v128_load(s), lv = wasm_v128_load(l);
    const v128_t r =
        wasm_f32x4_mul(wasm::mulAdd4(wasm_f32x4_sub(lv, sv), wasm::splat(kSmashBrightenMix), sv),
                       wasm::splat(kSmashBrightenScale));
    v128_t out;
    if (a >= 1.0f) {
        out = fused ? wasm::smashDisplay4(r) : wasm::powFast4(r, kSmashDecodeExponent);
    } else {
        const v128_t g = wasm::powFast4(r, kSmashDecodeExponent);
        const v128_t m =
            wasm::mulAdd4(g, wasm::splat(a), wasm_f32x4_mul(px, wasm::splat(1.0f - a)));
        out = fused ? wasm::srgbEncode4(m) : m;
    }
    wasm_v128_store(p, rgbOf(out, px));
}

// Four pixels at a time as R, G, B and A planes (transposed), so no lane computes an alpha that is
// not kept: the same lane operations, a quarter fewer of them.
struct Planes {
    v128_t v[4];
};

inline Planes loadPlanes(const float* p) {
    Planes q{
        {wasm_v128_load(p), wasm_v128_load(p + 4), wasm_v128_load(p + 8), wasm_v128_load(p + 12)}};
    wasm::transpose4(q.v[0], q.v[1], q.v[2], q.v[3]);
    return q;
}

inline void storePlanes(float* p, Planes q) {
    wasm::transpose4(q.v[0], q.v[1], q.v[2], q.v[3]);
    for (int i = 0; i < 4; ++i)
        wasm_v128_store(p + 4 * i, q.v[i]);
}

void smashEncodeWasm(const float* x, float* s, float* l, std::size_t count) {
    std::size_t i = 0;
    for (; i + 4 <= count; i += 4) {
        Planes q = loadPlanes(x + 4 * i);
        for (int c = 0; c < 3; ++c)
            q.v[c] = wasm::powFast4(q.v[c], kSmashEncodeExponent);
        storePlanes(s + 4 * i, q);
        storePlanes(l + 4 * i, q);
    }
    for (; i < count; ++i) {
        const v128_t px = wasm_v128_load(x + 4 * i);
        const v128_t v = rgbOf(wasm::powFast4(px, kSmashEncodeExponent), px);
        wasm_v128_store(s + 4 * i, v);
        wasm_v128_store(l + 4 * i, v);
    }
}

void smashFinishWasm(float* x, const float* s, const float* l, std::size_t count, bool fused) {
    std::size_t i = 0;
    for (; i + 4 <= count; i += 4) {
        float* p = x + 4 * i;
        // clamp01(alpha) >= 1 in all four (NaN fails the test): the common, fully graded case.
        const v128_t alpha =
            wasm_i32x4_shuffle(wasm_v128_load(p), wasm_v128_load(p + 8), 3, 3, 7, 7);
        const v128_t alpha2 =
            wasm_i32x4_shuffle(wasm_v128_load(p + 4), wasm_v128_load(p + 12), 3, 3, 7, 7);
        if (!wasm_i32x4_all_true(wasm_v128_and(wasm_f32x4_ge(alpha, wasm::splat(1.0f)),
                                               wasm_f32x4_ge(alpha2, wasm::splat(1.0f))))) {
            for (std::size_t k = 0; k < 4; ++k)
                smashFinishWasmPixel(p + 4 * k, s + 4 * (i + k), l + 4 * (i + k), fused);
            continue;
        }
        Planes q = loadPlanes(p);
        const Planes qs = loadPlanes(s + 4 * i), ql = loadPlanes(l + 4 * i);
        for (int c = 0; c < 3; ++c) {
            const v128_t r = wasm_f32x4_mul(wasm::mulAdd4(wasm_f32x4_sub(ql.v[c], qs.v[c]),
                                                          wasm::splat(kSmashBrightenMix), qs.v[c]),
                                            wasm::splat(kSmashBrightenScale));
            q.v[c] = fused ? wasm::smashDisplay4(r) : wasm::powFast4(r, kSmashDecodeExponent);
        }
        storePlanes(p, q);
    }
    for (; i < count; ++i)
        smashFinishWasmPixel(x + 4 * i, s + 4 * i, l + 4 * i, fused);
}
#endif

} // namespace

void powArray(float p, const float* in, float* out, std::size_t n) {
#ifdef LUTKIT_X86
    if (haveAvx2())
        return powAvx2(p, in, out, n);
#elif defined(LUTKIT_WASM_SIMD)
    return powWasm(p, in, out, n);
#endif
    for (std::size_t i = 0; i < n; ++i)
        out[i] = powFast(in[i], p);
}

void srgbEncodeArray(const float* in, float* out, std::size_t n) {
#ifdef LUTKIT_X86
    if (haveAvx2())
        return srgbAvx2(in, out, n);
#elif defined(LUTKIT_WASM_SIMD)
    return srgbWasm(in, out, n);
#endif
    for (std::size_t i = 0; i < n; ++i)
        out[i] = srgbEncodeFast(in[i]);
}

void smashEncodePixels(const float* x, float* s, float* l, std::size_t count) {
#ifdef LUTKIT_X86
    if (haveAvx2())
        return smashEncodeAvx2(x, s, l, count);
#elif defined(LUTKIT_WASM_SIMD)
    return smashEncodeWasm(x, s, l, count);
#endif
    for (std::size_t i = 0; i < count; ++i)
        smashEncodePixel(x + 4 * i, s + 4 * i, l + 4 * i);
}

void smashFinishPixels(float* x, const float* s, const float* l, std::size_t count,
                       bool fusedDisplay) {
#ifdef LUTKIT_X86
    if (haveAvx2())
        return smashFinishAvx2(x, s, l, count, fusedDisplay);
#elif defined(LUTKIT_WASM_SIMD)
    return smashFinishWasm(x, s, l, count, fusedDisplay);
#endif
    for (std::size_t i = 0; i < count; ++i)
        smashFinishPixel(x + 4 * i, s + 4 * i, l + 4 * i, fusedDisplay);
}

void addBloomRow(float* rgba, int width, const float* row4, const int* i0, const int* i1,
                 const float* t) {
#ifdef LUTKIT_X86
    if (haveAvx2())
        return addBloomRowAvx2(rgba, width, row4, i0, i1, t);
#endif
    for (int k = 0; k < width; ++k)
        addBloomPixel(rgba + 4 * k, row4 + 4 * i0[k], row4 + 4 * i1[k], t[k]);
}

const char* arrayKernelIsa() {
#ifdef LUTKIT_WASM_SIMD
    return "wasm-simd128";
#else
    return haveAvx2() ? "avx2" : "scalar";
#endif
}

} // namespace lut::detail
