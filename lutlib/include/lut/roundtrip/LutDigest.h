// SPDX-License-Identifier: Apache-2.0
#pragma once
// A short fingerprint of a LUT, recorded in a round-trip patch's header by `embed --original-lut`
// so `extract` can tell whether the stage LUT it is given is the one the patch was made for.
#include "lut/Lut3D.h"

#include <cstdint>
#include <string>

namespace lut {

// CRC-16 (CCITT, polynomial 0x1021, start 0xFFFF) over the size and the entries rounded to
// 8 bits (red fastest): LUTs that store the same 8-bit nutexb have the same digest.
std::uint16_t lutDigest(const Lut3D& lut);
// Four lower-case hex digits, e.g. "3fa2".
std::string digestText(std::uint16_t digest);

} // namespace lut
