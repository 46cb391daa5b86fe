// SPDX-License-Identifier: Apache-2.0
// The LUT fingerprint of the patch header; see lut/roundtrip/LutDigest.h.
#include "lut/roundtrip/LutDigest.h"

#include "lut/Quantize.h"

#include <cstdio>

namespace lut {

namespace {
void crcByte(std::uint16_t& crc, std::uint8_t byte) {
    crc ^= static_cast<std::uint16_t>(byte << 8);
    for (int i = 0; i < 8; ++i)
        crc = (crc & 0x8000u) ? static_cast<std::uint16_t>((crc << 1) ^ 0x1021u)
                              : static_cast<std::uint16_t>(crc << 1);
}
} // namespace

std::uint16_t lutDigest(const Lut3D& lut) {
    std::uint16_t crc = 0xFFFFu;
    const int n = lut.size();
    crcByte(crc, static_cast<std::uint8_t>(n >> 8));
    crcByte(crc, static_cast<std::uint8_t>(n & 0xFF));
    for (const glm::vec3& e : lut.entries())
        for (int c = 0; c < 3; ++c)
            crcByte(crc, toUnorm8(e[c]));
    return crc;
}

std::string digestText(std::uint16_t digest) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "%04x", static_cast<unsigned>(digest));
    return buf;
}

} // namespace lut
