// SPDX-License-Identifier: Apache-2.0
#pragma once
// The in-lane 4x4 transpose both AVX2 code paths use (simd/SamplerKernels_avx2.cpp and
// pipeline/ArrayKernels.cpp). Only <immintrin.h> is included (see the note in SimdKernels.h);
// the function is static and carries its own target attribute, so each translation unit keeps
// a private AVX2 copy and no copy can be shared with code that runs on CPUs without AVX2.
#include <immintrin.h>

namespace lut::detail {

// Four registers holding two RGBA pixels each:
// a=[p0|p1] b=[p2|p3] c=[p4|p5] d=[p6|p7]  ->  a=[r0 r2 r4 r6|r1 r3 r5 r7], b=G, c=B, d=A.
// It is its own inverse, so applying it to four per-lane planes gives one pixel per half again.
__attribute__((target("avx2"))) static inline void transpose4(__m256& a, __m256& b, __m256& c,
                                                              __m256& d) {
    const __m256 t0 = _mm256_unpacklo_ps(a, b);
    const __m256 t1 = _mm256_unpackhi_ps(a, b);
    const __m256 t2 = _mm256_unpacklo_ps(c, d);
    const __m256 t3 = _mm256_unpackhi_ps(c, d);
    a = _mm256_shuffle_ps(t0, t2, 0x44);
    b = _mm256_shuffle_ps(t0, t2, 0xEE);
    c = _mm256_shuffle_ps(t1, t3, 0x44);
    d = _mm256_shuffle_ps(t1, t3, 0xEE);
}

} // namespace lut::detail
