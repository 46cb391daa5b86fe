// SPDX-License-Identifier: Apache-2.0
// half <-> float with F16C (compiled with -mf16c -mavx, called only when the CPU has it), and
// half RGB <-> float RGBA in one pass (the same conversions, so the same bits as converting and
// then moving channels).
#include <immintrin.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace lut::formats::detail {

void halfToFloatF16c(const std::uint16_t* src, float* dst, std::size_t n) {
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8)
        _mm256_storeu_ps(
            dst + i, _mm256_cvtph_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(src + i))));
    for (; i < n; ++i)
        dst[i] = _cvtsh_ss(src[i]);
}

void floatToHalfF16c(const float* src, std::uint16_t* dst, std::size_t n) {
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8)
        _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + i),
                         _mm256_cvtps_ph(_mm256_loadu_ps(src + i), _MM_FROUND_TO_NEAREST_INT));
    for (; i < n; ++i)
        dst[i] = _cvtss_sh(src[i], _MM_FROUND_TO_NEAREST_INT);
}

// n pixels of half RGB to float RGBA (alpha 1); returns how many were done (the caller converts
// the rest). Two pixels per step from 16 bytes read for 12: the last pixel is left to the
// caller so that no read passes the end.
std::size_t halfRgbToRgbaF16c(const std::uint16_t* src, std::size_t n, float* rgba) {
    // Halves 0-2 and 3-5 to lanes 0-2 and 4-6; lanes 3 and 7 zero, then half 1.0 (0x3C00).
    const __m128i spread = _mm_setr_epi8(0, 1, 2, 3, 4, 5, -1, -1, 6, 7, 8, 9, 10, 11, -1, -1);
    const __m128i alphaOne = _mm_setr_epi16(0, 0, 0, 0x3C00, 0, 0, 0, 0x3C00);
    std::size_t i = 0;
    for (; i + 3 <= n; i += 2) {
        const __m128i h = _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + 3 * i));
        const __m128i two = _mm_or_si128(_mm_shuffle_epi8(h, spread), alphaOne);
        _mm256_storeu_ps(rgba + 4 * i, _mm256_cvtph_ps(two));
    }
    return i;
}

// n pixels of float RGBA to half RGB (alpha dropped); returns how many were done.
std::size_t rgbaToHalfRgbF16c(const float* rgba, std::size_t n, std::uint16_t* dst) {
    const __m128i dropAlpha = _mm_setr_epi8(0, 1, 2, 3, 4, 5, 8, 9, 10, 11, 12, 13, -1, -1, -1, -1);
    std::size_t i = 0;
    for (; i + 2 <= n; i += 2) {
        const __m128i h = _mm256_cvtps_ph(_mm256_loadu_ps(rgba + 4 * i), _MM_FROUND_TO_NEAREST_INT);
        alignas(16) std::uint16_t rgb[8];
        _mm_store_si128(reinterpret_cast<__m128i*>(rgb), _mm_shuffle_epi8(h, dropAlpha));
        std::memcpy(dst + 3 * i, rgb, 12);
    }
    return i;
}

} // namespace lut::formats::detail
