#include "ArrayKernels.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define LUTKIT_X86 1
#endif

namespace lut::detail {

namespace {

void powScalar(const PowTable& t, const float* in, float* out, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) out[i] = t(in[i]);
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
__attribute__((target("avx2"))) void powAvx2(const PowTable& t, const float* in, float* out, std::size_t n) {
    constexpr int kShift = 23 - PowTable::kBits;
    const float* mant = t.mantissaTable();
    const float* ex = t.exponentTable();
    const __m256i mantMask = _mm256_set1_epi32(0x7FFFFF);
    const __m256i fracMask = _mm256_set1_epi32((1 << kShift) - 1);
    const __m256 fracScale = _mm256_set1_ps(1.0f / (1 << kShift));
    const __m256i e255 = _mm256_set1_epi32(255);
    const __m256 topV = _mm256_set1_ps(t.top());
    const __m256 zero = _mm256_setzero_ps();
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256 x = _mm256_loadu_ps(in + i);
        const __m256 pos = _mm256_cmp_ps(x, zero, _CMP_GT_OQ); // NaN and <= 0 -> 0
        const __m256i b = _mm256_castps_si256(x);
        const __m256i e = _mm256_min_epu32(_mm256_srli_epi32(b, 23), e255);
        const __m256i m = _mm256_and_si256(b, mantMask);
        const __m256i idx = _mm256_srli_epi32(m, kShift);
        const __m256 frac = _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_and_si256(m, fracMask)), fracScale);
        const __m256 a = _mm256_i32gather_ps(mant, idx, 4);
        const __m256 c = _mm256_i32gather_ps(mant + 1, idx, 4);
        const __m256 s = _mm256_i32gather_ps(ex, e, 4);
        __m256 r = _mm256_mul_ps(s, _mm256_add_ps(a, _mm256_mul_ps(_mm256_sub_ps(c, a), frac)));
        const __m256 isInf = _mm256_castsi256_ps(_mm256_cmpeq_epi32(e, e255));
        r = _mm256_blendv_ps(r, topV, isInf);
        _mm256_storeu_ps(out + i, _mm256_and_ps(r, pos));
    }
    powScalar(t, in + i, out + i, n - i);
}

__attribute__((target("avx2"))) void uniformAvx2(const UniformTable& t, const float* in, float* out, std::size_t n) {
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
bool haveAvx2() { return false; }
#endif

} // namespace

void powArray(const PowTable& t, const float* in, float* out, std::size_t n) {
#ifdef LUTKIT_X86
    if (haveAvx2()) return powAvx2(t, in, out, n);
#endif
    powScalar(t, in, out, n);
}

void uniformArray(const UniformTable& t, const float* in, float* out, std::size_t n) {
#ifdef LUTKIT_X86
    if (haveAvx2()) return uniformAvx2(t, in, out, n);
#endif
    uniformScalar(t, in, out, n);
}

const char* arrayKernelIsa() { return haveAvx2() ? "avx2" : "scalar"; }

} // namespace lut::detail
