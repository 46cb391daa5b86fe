#include "lut/Quantize.h"

#include <cmath>

namespace lut {

std::uint8_t toUnorm8(float v) {
    if (!(v > 0.0f)) return 0; // NaN, negatives, -0
    if (v >= 1.0f) return 255;
    return static_cast<std::uint8_t>(std::lround(static_cast<double>(v) * 255.0));
}

std::uint16_t toUnorm16(float v) {
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 65535;
    return static_cast<std::uint16_t>(std::lround(static_cast<double>(v) * 65535.0));
}

} // namespace lut
