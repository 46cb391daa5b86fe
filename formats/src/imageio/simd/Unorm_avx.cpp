// SPDX-License-Identifier: Apache-2.0
// 8-bit RGB(A) -> float RGBA and float RGBA -> 8/16-bit RGB(A) with AVX (compiled with -mavx,
// called only when the CPU has it). Reading: code / 255.0f, an IEEE division as the scalar
// table's own (PixelConvert.cpp), so the same bits; alpha 1 for RGB. Writing: the value
// lut::toUnorm8/toUnorm16 give (lut/Quantize.h), four channels at a time. The scalar
// form is `v > 0 ? (v >= 1 ? max : int(double(v) * max + 0.5)) : 0`; here v is first clamped to
// [0, 1] in float (maxps returns its second operand, 0, for NaN), which gives the same integer
// for every float: 0 * max + 0.5 and 1 * max + 0.5 truncate to 0 and max, and in between the
// double arithmetic is the scalar's own (exact: a float times a 16-bit integer fits a double).
#include <immintrin.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace lut::formats::detail {

namespace {

inline __m128i unorm4(const float* p, __m256d scale) {
    const __m128 c = _mm_min_ps(_mm_max_ps(_mm_loadu_ps(p), _mm_setzero_ps()), _mm_set1_ps(1.0f));
    const __m256d d = _mm256_add_pd(_mm256_mul_pd(_mm256_cvtps_pd(c), scale), _mm256_set1_pd(0.5));
    return _mm256_cvttpd_epi32(d);
}

} // namespace

// n pixels of 8-bit RGB (nch 3) or RGBA (nch 4) to float RGBA; returns how many were done (a
// multiple of 4; the caller converts the rest). RGB reads 16 bytes for 12: at least 2 pixels
// are left to the caller so that no read passes the end.
std::size_t unorm8ToRgbaAvx(const std::uint8_t* src, std::size_t n, float* rgba, int nch) {
    const __m256 scale = _mm256_set1_ps(255.0f);
    const __m256 one = _mm256_set1_ps(1.0f);
    // Pixel j's R, G, B into bytes 4j..4j+2, a zero into 4j+3.
    const __m128i spread = _mm_setr_epi8(0, 1, 2, -1, 3, 4, 5, -1, 6, 7, 8, -1, 9, 10, 11, -1);
    std::size_t i = 0;
    const std::size_t end = nch == 3 ? (n >= 6 ? n - 2 : 0) : n;
    for (; i + 4 <= end; i += 4) {
        __m128i b;
        if (nch == 3)
            b = _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(src + 3 * i)),
                                 spread);
        else
            b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + 4 * i));
        const __m256i p01 =
            _mm256_set_m128i(_mm_cvtepu8_epi32(_mm_srli_si128(b, 4)), _mm_cvtepu8_epi32(b));
        const __m256i p23 = _mm256_set_m128i(_mm_cvtepu8_epi32(_mm_srli_si128(b, 12)),
                                             _mm_cvtepu8_epi32(_mm_srli_si128(b, 8)));
        __m256 f01 = _mm256_div_ps(_mm256_cvtepi32_ps(p01), scale);
        __m256 f23 = _mm256_div_ps(_mm256_cvtepi32_ps(p23), scale);
        if (nch == 3) {
            f01 = _mm256_blend_ps(f01, one, 0x88);
            f23 = _mm256_blend_ps(f23, one, 0x88);
        }
        _mm256_storeu_ps(rgba + 4 * i, f01);
        _mm256_storeu_ps(rgba + 4 * i + 8, f23);
    }
    return i;
}

// n pixels of float RGBA to 8-bit RGB (nch 3) or RGBA (nch 4); returns how many were done
// (a multiple of 4; the caller converts the rest).
std::size_t rgbaToUnorm8Avx(const float* rgba, std::size_t n, std::uint8_t* dst, int nch) {
    const __m256d scale = _mm256_set1_pd(255.0);
    const __m128i dropAlpha = _mm_setr_epi8(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1);
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {
        const float* p = rgba + 4 * i;
        const __m128i w01 = _mm_packus_epi32(unorm4(p, scale), unorm4(p + 4, scale));
        const __m128i w23 = _mm_packus_epi32(unorm4(p + 8, scale), unorm4(p + 12, scale));
        const __m128i b = _mm_packus_epi16(w01, w23); // 4 pixels, RGBA bytes
        if (nch == 4) {
            _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + 4 * i), b);
        } else {
            alignas(16) std::uint8_t rgb[16];
            _mm_store_si128(reinterpret_cast<__m128i*>(rgb), _mm_shuffle_epi8(b, dropAlpha));
            std::memcpy(dst + 3 * i, rgb, 12);
        }
    }
    return i;
}

// The same to 16-bit samples (host order).
std::size_t rgbaToUnorm16Avx(const float* rgba, std::size_t n, std::uint16_t* dst, int nch) {
    const __m256d scale = _mm256_set1_pd(65535.0);
    const __m128i dropAlpha = _mm_setr_epi8(0, 1, 2, 3, 4, 5, 8, 9, 10, 11, 12, 13, -1, -1, -1, -1);
    std::size_t i = 0;
    for (; i + 2 <= n; i += 2) {
        const float* p = rgba + 4 * i;
        const __m128i w = _mm_packus_epi32(unorm4(p, scale), unorm4(p + 4, scale)); // 2 pixels
        if (nch == 4) {
            _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + 4 * i), w);
        } else {
            alignas(16) std::uint16_t rgb[8];
            _mm_store_si128(reinterpret_cast<__m128i*>(rgb), _mm_shuffle_epi8(w, dropAlpha));
            std::memcpy(dst + 3 * i, rgb, 12);
        }
    }
    return i;
}

} // namespace lut::formats::detail
