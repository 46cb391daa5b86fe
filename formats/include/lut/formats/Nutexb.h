#pragma once
// Smash Ultimate nutexb volumes (color_grading_lut.nutexb) and the Tegra X1 block-linear tiling
// they are stored in. The byte contract is docs/specs/nutexb.md; this header exposes the
// pieces to tests and fuzzers: the tiling maths and reading/writing from bytes in memory.
#include "lut/Lut3D.h"
#include "lut/io/Format.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lut::formats::nutexb {

// Format constants, in one place.
constexpr std::size_t kFooterSize = 0x70;
constexpr std::size_t kMipTableSize = 0x40;                       // per layer
constexpr std::size_t kMinFileSize = kMipTableSize + kFooterSize; // 0xB0
constexpr std::size_t kNameSize = 64;
constexpr std::uint32_t kFormatRgba8 = 0x0400;
constexpr std::uint32_t kFormatRgba8Srgb = 0x0405;
constexpr std::uint32_t kTextureType3D = 8;
constexpr std::uint32_t kTilingBlockLinear = 0x1000;
constexpr std::uint32_t kTilingLinear = 0;
constexpr std::uint16_t kVersionMajor = 1;
constexpr std::uint16_t kVersionMinor = 2;
constexpr const char* kDefaultName = "color_grading_lut";
constexpr int kDefaultSize = 16;  // every stage LUT of the game is 16^3
constexpr int kBytesPerTexel = 4; // RGBA8

// FormatOptions attributes the nutexb writer reads: the name field ("" = color_grading_lut) and
// the tiling, "block-linear" (the default, what the game ships) or "linear" rows.
constexpr const char* kNameAttribute = "nutexb:name";
constexpr const char* kTilingAttribute = "nutexb:tiling";

// Tegra X1 block-linear tiling of one mip of a width x height x depth texture with `bpp` bytes
// per texel, block height 1 GOB (3D textures). General: any size, any bpp >= 1.
struct TileGeometry {
    int width = 0, height = 0, depth = 0, bpp = 0;
    int blockHeight = 1;          // GOBs per block in y (bh)
    int blockDepth = 1;           // GOBs per block in z (bd), from blockDepthFor(depth)
    std::uint64_t gobsAcross = 0; // W = ceil(width*bpp/64)
};
// bd: d' = d + d/2; d' >= 16 -> 16, >= 8 -> 8, >= 4 -> 4, >= 2 -> 2, else 1.
int blockDepthFor(int depth);
// Throws lut::Error unless all sizes are >= 1 (and bpp >= 1).
TileGeometry tileGeometry(int width, int height, int depth, int bpp);
// Byte offset of byte `xb` (0..63) of row `yg` (0..7) inside one 512-byte GOB.
std::uint32_t gobOffset(std::uint32_t xb, std::uint32_t yg);
// Size of the tiled mip in bytes, padding included.
std::uint64_t tiledSize(const TileGeometry& g);
// Byte address of texel (x, y, z) in the tiled data.
std::uint64_t tiledOffset(const TileGeometry& g, int x, int y, int z);
// Linear rows (x fastest, then y, then z; bpp bytes per texel) -> tiled bytes (padding zero),
// and back. linear must hold width*height*depth*bpp bytes, tiled tiledSize(g) bytes.
std::vector<std::uint8_t> tile(const TileGeometry& g, const std::uint8_t* linear);
std::vector<std::uint8_t> untile(const TileGeometry& g, const std::uint8_t* tiled);

// What the footer says.
struct Header {
    std::string name;
    std::uint32_t width = 0, height = 0, depth = 0;
    std::uint32_t imageFormat = 0, textureType = 0, mipCount = 0, tiling = 0, layerCount = 0;
    std::uint32_t dataSize = 0;
    std::uint16_t versionMajor = 0, versionMinor = 0;
};
// Parses and checks the footer and mip table of a whole file's bytes; throws lut::Error naming
// `path` and the field (value found and expected) for any departure nutexb.md forbids.
Header parseHeader(std::string_view bytes, const std::string& path);
// Reads a whole file held in memory. Entry = byte/255, alpha ignored (diagnostic if not 255).
LutFile readBytes(std::string_view bytes, const std::string& path);
// Writes an RGBA8 volume of lut's own size (the caller resamples); name "" = color_grading_lut.
// tiled = block-linear (0x1000), else linear rows. clampedCount (optional) receives the number
// of channel values outside [0,1] that were clamped.
std::string writeBytes(const Lut3D& lut, const std::string& name, bool tiled,
                       std::size_t* clampedCount = nullptr);

} // namespace lut::formats::nutexb
