#include "ArrayKernels.h"

#include "Tables.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define LUTKIT_X86 1
#endif

namespace lut::detail {

namespace {

void powScalar(const PowTable& t, const float* in, float* out, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        out[i] = t(in[i]);
}

void uniformScalar(const UniformTable& t, const float* in, float* out, std::size_t n) {
    const float* v = t.values();
    const float scale = t.scale();
    const int top = t.intervals() - 1;
    for (std::size_t i = 0; i < n; ++i) {
        const float x = in[i];
        int k = static_cast<int>(x * scale);
        k = k > top ? top : (k < 0 ? 0 : k);
        const float f = x * scale - static_cast<float>(k);
        out[i] = v[k] + (v[k + 1] - v[k]) * f;
    }
}

#ifdef LUTKIT_X86
struct PowConsts {
    const float* mant;
    const float* ex;
    float top;
};

__attribute__((target("avx2"))) inline __m256 pow8(const PowConsts& k, __m256 x) {
    constexpr int kShift = 23 - PowTable::kBits;
    const __m256i b = _mm256_castps_si256(x);
    const __m256i e255 = _mm256_set1_epi32(255);
    const __m256 pos = _mm256_cmp_ps(x, _mm256_setzero_ps(), _CMP_GT_OQ); // NaN and <= 0 -> 0
    const __m256i e = _mm256_min_epu32(_mm256_srli_epi32(b, 23), e255);
    const __m256i m = _mm256_and_si256(b, _mm256_set1_epi32(0x7FFFFF));
    const __m256i idx = _mm256_srli_epi32(m, kShift);
    const __m256 frac =
        _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_and_si256(m, _mm256_set1_epi32((1 << kShift) - 1))),
                      _mm256_set1_ps(1.0f / (1 << kShift)));
    const __m256 a = _mm256_i32gather_ps(k.mant, idx, 4);
    const __m256 c = _mm256_i32gather_ps(k.mant + 1, idx, 4);
    const __m256 s = _mm256_i32gather_ps(k.ex, e, 4);
    __m256 r = _mm256_mul_ps(s, _mm256_add_ps(a, _mm256_mul_ps(_mm256_sub_ps(c, a), frac)));
    const __m256 isInf = _mm256_castsi256_ps(_mm256_cmpeq_epi32(e, e255));
    r = _mm256_blendv_ps(r, _mm256_set1_ps(k.top), isInf);
    return _mm256_and_ps(r, pos);
}

__attribute__((target("avx2"))) void powAvx2(const PowTable& t, const float* in, float* out,
                                             std::size_t n) {
    const PowConsts k{t.mantissaTable(), t.exponentTable(), t.top()};
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8)
        _mm256_storeu_ps(out + i, pow8(k, _mm256_loadu_ps(in + i)));
    powScalar(t, in + i, out + i, n - i);
}

// srgbEncodeFast, 8 at a time, same operations: e = a <= 0.0031308 ? 12.92 a : 1.055 pow(a) -
// 0.055, negated for x < 0 (so -0 stays +0 as in the scalar form).
__attribute__((target("avx2"))) void srgbAvx2(const PowTable& t, const float* in, float* out,
                                              std::size_t n) {
    const PowConsts k{t.mantissaTable(), t.exponentTable(), t.top()};
    const __m256 signMask = _mm256_set1_ps(-0.0f);
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256 x = _mm256_loadu_ps(in + i);
        const __m256 a = _mm256_andnot_ps(signMask, x);
        const __m256 pw = _mm256_sub_ps(_mm256_mul_ps(_mm256_set1_ps(1.055f), pow8(k, a)),
                                        _mm256_set1_ps(0.055f));
        const __m256 lin = _mm256_mul_ps(_mm256_set1_ps(12.92f), a);
        const __m256 e =
            _mm256_blendv_ps(pw, lin, _mm256_cmp_ps(a, _mm256_set1_ps(0.0031308f), _CMP_LE_OQ));
        const __m256 neg = _mm256_cmp_ps(x, _mm256_setzero_ps(), _CMP_LT_OQ);
        _mm256_storeu_ps(out + i, _mm256_xor_ps(e, _mm256_and_ps(neg, signMask)));
    }
    for (; i < n; ++i)
        out[i] = srgbEncodeFast(in[i], t);
}

__attribute__((target("avx2"))) void uniformAvx2(const UniformTable& t, const float* in, float* out,
                                                 std::size_t n) {
    const float* v = t.values();
    const __m256 scale = _mm256_set1_ps(t.scale());
    const __m256i top = _mm256_set1_epi32(t.intervals() - 1);
    const __m256i zero = _mm256_setzero_si256();
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256 x = _mm256_mul_ps(_mm256_loadu_ps(in + i), scale);
        // cvtt of NaN / huge gives INT_MIN: clamped to 0 like the scalar form.
        __m256i k = _mm256_cvttps_epi32(x);
        k = _mm256_max_epi32(_mm256_min_epi32(k, top), zero);
        const __m256 f = _mm256_sub_ps(x, _mm256_cvtepi32_ps(k));
        const __m256 a = _mm256_i32gather_ps(v, k, 4);
        const __m256 c = _mm256_i32gather_ps(v + 1, k, 4);
        _mm256_storeu_ps(out + i, _mm256_add_ps(a, _mm256_mul_ps(_mm256_sub_ps(c, a), f)));
    }
    uniformScalar(t, in + i, out + i, n - i);
}

bool haveAvx2() {
    static const bool yes = __builtin_cpu_supports("avx2");
    return yes;
}
#else
bool haveAvx2() {
    return false;
}
#endif

} // namespace

void powArray(const PowTable& t, const float* in, float* out, std::size_t n) {
#ifdef LUTKIT_X86
    if (haveAvx2())
        return powAvx2(t, in, out, n);
#endif
    powScalar(t, in, out, n);
}

void uniformArray(const UniformTable& t, const float* in, float* out, std::size_t n) {
#ifdef LUTKIT_X86
    if (haveAvx2())
        return uniformAvx2(t, in, out, n);
#endif
    uniformScalar(t, in, out, n);
}

void srgbEncodeArray(const PowTable& t, const float* in, float* out, std::size_t n) {
#ifdef LUTKIT_X86
    if (haveAvx2())
        return srgbAvx2(t, in, out, n);
#endif
    for (std::size_t i = 0; i < n; ++i)
        out[i] = srgbEncodeFast(in[i], t);
}

const char* arrayKernelIsa() {
    return haveAvx2() ? "avx2" : "scalar";
}

} // namespace lut::detail
