// SPDX-License-Identifier: Apache-2.0
#pragma once
// Tegra X1 block-linear tiling (the "swizzle" of Switch textures; nutexb.md, "Tiling"), the
// general 3D algorithm: any size, any bytes per texel >= 1. Internal to formats/; tests and
// fuzzers reach it through the lutkit::formats_internal CMake target.
//
// Bytes are grouped in GOBs of 64 bytes x 8 rows (512 contiguous bytes). GOBs form blocks of
// 1 x bh x bd GOBs (y first, then z inside the block); blocks run x fastest, then y, then
// z-slab. A 3D texture has bh = 1 and bd from its depth. Partial GOBs and partial blocks are
// padding, which tile() leaves zero.
#include <cstdint>
#include <vector>

namespace lut::formats::nutexb {

// The tiling of one mip of a width x height x depth texture with `bpp` bytes per texel, block
// height 1 GOB (3D textures).
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

} // namespace lut::formats::nutexb
