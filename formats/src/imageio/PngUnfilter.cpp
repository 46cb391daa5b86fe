// SPDX-License-Identifier: Apache-2.0
// PNG row unfiltering: the five filters of the PNG specification, section 9.
#include "imageio/PngUnfilter.h"

#include <cstdlib>
#include <cstring>

namespace lut::formats {

namespace {

inline unsigned char paeth(int a, int b, int c) {
    const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
    return static_cast<unsigned char>(pa <= pb && pa <= pc ? a : pb <= pc ? b : c);
}

// Average and Paeth for a fixed pixel size, so the compiler keeps a pixel's bytes in registers.
template <std::size_t Bpp>
void averageFixed(const unsigned char* f, const unsigned char* up, unsigned char* o,
                  std::size_t n) {
    for (std::size_t i = 0; i < Bpp; ++i)
        o[i] = static_cast<unsigned char>(f[i] + (up[i] >> 1));
    for (std::size_t i = Bpp; i < n; i += Bpp)
        for (std::size_t k = 0; k < Bpp; ++k)
            o[i + k] = static_cast<unsigned char>(f[i + k] + ((o[i + k - Bpp] + up[i + k]) >> 1));
}

template <std::size_t Bpp>
void paethFixed(const unsigned char* f, const unsigned char* up, unsigned char* o, std::size_t n) {
    for (std::size_t i = 0; i < Bpp; ++i)
        o[i] = static_cast<unsigned char>(f[i] + up[i]); // Paeth(0, b, 0) = b
    for (std::size_t i = Bpp; i < n; i += Bpp)
        for (std::size_t k = 0; k < Bpp; ++k)
            o[i + k] = static_cast<unsigned char>(
                f[i + k] + paeth(o[i + k - Bpp], up[i + k], up[i + k - Bpp]));
}

} // namespace

bool unfilterRow(unsigned type, const unsigned char* f, const unsigned char* up, unsigned char* o,
                 std::size_t n, std::size_t bpp) {
    switch (type) {
    case 0:
        std::memcpy(o, f, n);
        return true;
    case 1:
        for (std::size_t i = 0; i < bpp && i < n; ++i)
            o[i] = f[i];
        for (std::size_t i = bpp; i < n; ++i)
            o[i] = static_cast<unsigned char>(f[i] + o[i - bpp]);
        return true;
    case 2:
        for (std::size_t i = 0; i < n; ++i)
            o[i] = static_cast<unsigned char>(f[i] + up[i]);
        return true;
    case 3:
        // n is a whole number of pixels, so the fixed-size loops never run past it.
        switch (bpp) {
        case 3:
            averageFixed<3>(f, up, o, n);
            return true;
        case 4:
            averageFixed<4>(f, up, o, n);
            return true;
        default:
            for (std::size_t i = 0; i < bpp && i < n; ++i)
                o[i] = static_cast<unsigned char>(f[i] + (up[i] >> 1));
            for (std::size_t i = bpp; i < n; ++i)
                o[i] = static_cast<unsigned char>(f[i] + ((o[i - bpp] + up[i]) >> 1));
            return true;
        }
    case 4:
        switch (bpp) {
        case 3:
            paethFixed<3>(f, up, o, n);
            return true;
        case 4:
            paethFixed<4>(f, up, o, n);
            return true;
        default:
            for (std::size_t i = 0; i < bpp && i < n; ++i)
                o[i] = static_cast<unsigned char>(f[i] + up[i]);
            for (std::size_t i = bpp; i < n; ++i)
                o[i] = static_cast<unsigned char>(f[i] + paeth(o[i - bpp], up[i], up[i - bpp]));
            return true;
        }
    default:
        return false;
    }
}

} // namespace lut::formats
