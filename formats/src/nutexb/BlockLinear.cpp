// SPDX-License-Identifier: Apache-2.0
// Tegra X1 block-linear tiling (nutexb.md, "Tiling"); the layout is described in BlockLinear.h.
#include "nutexb/BlockLinear.h"

#include "lut/Error.h"

#include <string>

namespace lut::formats::nutexb {

int blockDepthFor(int depth) {
    const long long d = static_cast<long long>(depth) + depth / 2;
    if (d >= 16)
        return 16;
    if (d >= 8)
        return 8;
    if (d >= 4)
        return 4;
    if (d >= 2)
        return 2;
    return 1;
}

TileGeometry tileGeometry(int width, int height, int depth, int bpp) {
    if (width < 1 || height < 1 || depth < 1 || bpp < 1)
        throw Error("tiling: sizes must be >= 1 (width " + std::to_string(width) + ", height " +
                    std::to_string(height) + ", depth " + std::to_string(depth) + ", bpp " +
                    std::to_string(bpp) + ")");
    TileGeometry g;
    g.width = width;
    g.height = height;
    g.depth = depth;
    g.bpp = bpp;
    g.blockHeight = 1;
    g.blockDepth = blockDepthFor(depth);
    g.gobsAcross = (static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(bpp) + 63) / 64;
    return g;
}

std::uint32_t gobOffset(std::uint32_t xb, std::uint32_t yg) {
    return (xb / 32) * 256 + (yg / 2) * 64 + ((xb % 32) / 16) * 32 + (yg % 2) * 16 + (xb % 16);
}

static std::uint64_t ceilDiv(std::uint64_t a, std::uint64_t b) {
    return (a + b - 1) / b;
}

std::uint64_t tiledSize(const TileGeometry& g) {
    const std::uint64_t bh = static_cast<std::uint64_t>(g.blockHeight);
    const std::uint64_t bd = static_cast<std::uint64_t>(g.blockDepth);
    const std::uint64_t blockRows = ceilDiv(static_cast<std::uint64_t>(g.height), 8 * bh);
    const std::uint64_t depthUp = ceilDiv(static_cast<std::uint64_t>(g.depth), bd) * bd;
    return g.gobsAcross * blockRows * bh * depthUp * 512;
}

std::uint64_t tiledOffset(const TileGeometry& g, int x, int y, int z) {
    const std::uint64_t bh = static_cast<std::uint64_t>(g.blockHeight);
    const std::uint64_t bd = static_cast<std::uint64_t>(g.blockDepth);
    const std::uint64_t W = g.gobsAcross;
    const std::uint64_t xb = static_cast<std::uint64_t>(x) * static_cast<std::uint64_t>(g.bpp);
    const std::uint64_t uy = static_cast<std::uint64_t>(y), uz = static_cast<std::uint64_t>(z);
    const std::uint64_t block = 512 * bh * bd;
    const std::uint64_t slice = ceilDiv(static_cast<std::uint64_t>(g.height), 8 * bh) * W * block;
    return (uz / bd) * slice + (uz % bd) * 512 * bh + (uy / (8 * bh)) * W * block +
           ((uy % (8 * bh)) / 8) * 512 + (xb / 64) * block +
           gobOffset(static_cast<std::uint32_t>(xb % 64), static_cast<std::uint32_t>(uy % 8));
}

// Both directions walk texels in linear order and copy bpp bytes. A texel stays contiguous when
// 16 % bpp == 0 (the GOB swizzle moves 16-byte runs); otherwise each byte is placed on its own.
template <bool ToTiled>
static void copyTexels(const TileGeometry& g, const std::uint8_t* src, std::uint8_t* dst) {
    const std::size_t bpp = static_cast<std::size_t>(g.bpp);
    const bool whole = 16 % bpp == 0;
    std::size_t lin = 0;
    for (int z = 0; z < g.depth; ++z)
        for (int y = 0; y < g.height; ++y)
            for (int x = 0; x < g.width; ++x, lin += bpp) {
                if (whole) {
                    const std::uint64_t t = tiledOffset(g, x, y, z);
                    for (std::size_t k = 0; k < bpp; ++k) {
                        if (ToTiled)
                            dst[t + k] = src[lin + k];
                        else
                            dst[lin + k] = src[t + k];
                    }
                } else {
                    // Byte-wise: address of byte column xb = x*bpp + k computed directly.
                    for (std::size_t k = 0; k < bpp; ++k) {
                        TileGeometry one = g;
                        one.bpp = 1;
                        const int xb = static_cast<int>(static_cast<std::uint64_t>(x) * bpp + k);
                        const std::uint64_t t = tiledOffset(one, xb, y, z);
                        if (ToTiled)
                            dst[t] = src[lin + k];
                        else
                            dst[lin + k] = src[t];
                    }
                }
            }
}

std::vector<std::uint8_t> tile(const TileGeometry& g, const std::uint8_t* linear) {
    std::vector<std::uint8_t> out(static_cast<std::size_t>(tiledSize(g)), 0);
    copyTexels<true>(g, linear, out.data());
    return out;
}

std::vector<std::uint8_t> untile(const TileGeometry& g, const std::uint8_t* tiled) {
    std::vector<std::uint8_t> out(static_cast<std::size_t>(g.width) * g.height * g.depth * g.bpp,
                                  0);
    copyTexels<false>(g, tiled, out.data());
    return out;
}

} // namespace lut::formats::nutexb
