// SPDX-License-Identifier: Apache-2.0
#pragma once
// Named regions of the RGB cube, for saying *where* two LUTs differ or a LUT cannot be inverted.
//
// Every input colour (sRGB-encoded, clamped to [0, 1]) lies in one tone band and in one hue
// sector or the neutrals:
//  - tone by Rec.709 luma Y' = 0.2126 R + 0.7152 G + 0.0722 B: shadows Y' < 1/3, midtones,
//    highlights Y' >= 2/3;
//  - neutrals: chroma max(R,G,B) - min(R,G,B) < 0.1 (near the grey axis, where hue means little);
//  - otherwise the HSV hue's 60-degree sector centred on red (0), yellow (60), green (120), cyan
//    (180), blue (240) or magenta (300), e.g. red is hue in [330, 30).
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>

namespace lut {

enum class Region {
    Shadows,
    Midtones,
    Highlights,
    Neutrals,
    Red,
    Yellow,
    Green,
    Cyan,
    Blue,
    Magenta
};
constexpr int kRegionCount = 10;

// "shadows", "midtones", "highlights", "neutrals", "red", ... "magenta".
const char* toString(Region region);

struct RegionOf {
    Region tone; // Shadows, Midtones or Highlights
    Region hue;  // Neutrals or one of the six hue sectors
};
RegionOf classifyRegion(glm::vec3 input);

// Per-region counts, indexed by static_cast<int>(Region).
using RegionCounts = std::array<std::size_t, kRegionCount>;

} // namespace lut
