#pragma once
#include <cstdint>

namespace lut {

// The one float -> integer conversion: round to nearest, clamp to [0, 1]; NaN -> 0.
std::uint8_t toUnorm8(float v);
std::uint16_t toUnorm16(float v);
inline float fromUnorm8(std::uint8_t v) { return static_cast<float>(v) / 255.0f; }
inline float fromUnorm16(std::uint16_t v) { return static_cast<float>(v) / 65535.0f; }

} // namespace lut
