// SPDX-License-Identifier: Apache-2.0
#pragma once
// Smash Ultimate nutexb volumes: the game's 3D colour-grading LUT (color_grading_lut.nutexb), an
// RGBA8 N^3 texture, block-linear tiled (Tegra X1) or in linear rows. The byte contract is
// docs/specs/nutexb.md. The format is registered in the FormatRegistry as "nutexb" (extension
// ".nutexb"); read and write it with lut::formats::readLut / writeLut. What a caller can set:
namespace lut::formats::nutexb {

// FormatOptions::size 0 writes lut::kSmashLutSize (lut/smash/SmashConstants.h): every stage
// LUT of the game is 16^3.
// The texture name written in the footer when none is given.
constexpr const char* kDefaultName = "color_grading_lut";

// FormatOptions attributes the nutexb writer reads: the name field ("" = kDefaultName, at most 63
// bytes) and the tiling, "block-linear" (the default, what the game ships) or "linear" rows.
constexpr const char* kNameAttribute = "nutexb:name";
constexpr const char* kTilingAttribute = "nutexb:tiling";

} // namespace lut::formats::nutexb
