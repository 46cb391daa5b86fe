// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <cstdint>

namespace lut {

// The one float -> integer conversion: round to nearest (halves away from zero), clamp to [0, 1];
// NaN -> 0. Inline and branch-light so pixel loops vectorize: v * 255 (or 65535) in double is
// exact for a float v, and so is adding 0.5, so the truncation below is exactly std::lround.
inline std::uint8_t toUnorm8(float v) {
    if (!(v > 0.0f))
        return 0; // NaN, negatives, -0
    if (v >= 1.0f)
        return 255;
    return static_cast<std::uint8_t>(static_cast<int>(static_cast<double>(v) * 255.0 + 0.5));
}
inline std::uint16_t toUnorm16(float v) {
    if (!(v > 0.0f))
        return 0;
    if (v >= 1.0f)
        return 65535;
    return static_cast<std::uint16_t>(static_cast<int>(static_cast<double>(v) * 65535.0 + 0.5));
}
inline float fromUnorm8(std::uint8_t v) {
    return static_cast<float>(v) / 255.0f;
}
inline float fromUnorm16(std::uint16_t v) {
    return static_cast<float>(v) / 65535.0f;
}

} // namespace lut
