// SPDX-License-Identifier: Apache-2.0
// Tegra X1 block-linear tiling: the offsets and sizes nutexb.md states, and properties of the
// general algorithm (a bijection into the tiled size, padding untouched) for odd sizes.
#include "lut/Error.h"
#include "nutexb/BlockLinear.h"

#include <gtest/gtest.h>

#include <numeric>
#include <set>

namespace nx = lut::formats::nutexb;

TEST(BlockLinear, BlockDepthRule) {
    // d' = d + d/2; >= 16 -> 16, >= 8 -> 8, >= 4 -> 4, >= 2 -> 2, else 1.
    EXPECT_EQ(nx::blockDepthFor(1), 1);
    EXPECT_EQ(nx::blockDepthFor(2), 2);  // 3
    EXPECT_EQ(nx::blockDepthFor(3), 4);  // 4
    EXPECT_EQ(nx::blockDepthFor(5), 4);  // 7
    EXPECT_EQ(nx::blockDepthFor(6), 8);  // 9
    EXPECT_EQ(nx::blockDepthFor(8), 8);  // 12
    EXPECT_EQ(nx::blockDepthFor(10), 8); // 15
    EXPECT_EQ(nx::blockDepthFor(11), 16);
    EXPECT_EQ(nx::blockDepthFor(16), 16);
    EXPECT_EQ(nx::blockDepthFor(256), 16);
}

TEST(BlockLinear, GobSwizzleMatchesSpecExamples) {
    EXPECT_EQ(nx::gobOffset(0, 0), 0u);
    EXPECT_EQ(nx::gobOffset(16, 0), 32u);
    EXPECT_EQ(nx::gobOffset(0, 1), 16u);
    EXPECT_EQ(nx::gobOffset(32, 0), 256u);
    EXPECT_EQ(nx::gobOffset(63, 7), 511u);
    // Every byte of a GOB lands on a distinct place in 0..511.
    std::set<std::uint32_t> seen;
    for (std::uint32_t y = 0; y < 8; ++y)
        for (std::uint32_t x = 0; x < 64; ++x)
            seen.insert(nx::gobOffset(x, y));
    EXPECT_EQ(seen.size(), 512u);
    EXPECT_EQ(*seen.rbegin(), 511u);
}

TEST(BlockLinear, TexelOffsetsFromTheDoc16) {
    const auto g = nx::tileGeometry(16, 16, 16, 4);
    EXPECT_EQ(nx::tiledOffset(g, 15, 0, 0), 300u);
    EXPECT_EQ(nx::tiledOffset(g, 0, 15, 0), 8400u);
    EXPECT_EQ(nx::tiledOffset(g, 0, 0, 15), 7680u);
    EXPECT_EQ(nx::tiledOffset(g, 5, 10, 3), 9828u);
    EXPECT_EQ(nx::tiledOffset(g, 15, 15, 15), 16380u);
    EXPECT_EQ(nx::tiledSize(g), 16384u);
}

TEST(BlockLinear, General3DMatches16CubedClosedForm) {
    const auto g = nx::tileGeometry(16, 16, 16, 4);
    for (int b = 0; b < 16; ++b)
        for (int gg = 0; gg < 16; ++gg)
            for (int r = 0; r < 16; ++r) {
                const std::uint64_t expected = 8192 * (gg >> 3) + 512 * b + 256 * (r >> 3) +
                                               64 * ((gg >> 1) & 3) + 32 * ((r >> 2) & 1) +
                                               16 * (gg & 1) + 4 * (r & 3);
                ASSERT_EQ(nx::tiledOffset(g, r, gg, b), expected) << r << "," << gg << "," << b;
            }
}

TEST(BlockLinear, SizesFromTheDoc) {
    EXPECT_EQ(nx::tiledSize(nx::tileGeometry(32, 32, 32, 4)), 131072u);
    EXPECT_EQ(nx::tiledSize(nx::tileGeometry(8, 8, 8, 4)), 4096u); // padded from 2048
    EXPECT_EQ(nx::tiledSize(nx::tileGeometry(33, 33, 33, 4)), 368640u);
    // Hand-computed: 2^3: W=1, 1 GOB row, bd(2)=2 -> 1*1*2*512.
    EXPECT_EQ(nx::tiledSize(nx::tileGeometry(2, 2, 2, 4)), 1024u);
}

TEST(BlockLinear, RejectsNonPositiveSizes) {
    EXPECT_THROW(nx::tileGeometry(0, 4, 4, 4), lut::Error);
    EXPECT_THROW(nx::tileGeometry(4, 4, -1, 4), lut::Error);
    EXPECT_THROW(nx::tileGeometry(4, 4, 4, 0), lut::Error);
}

// For any size: every texel byte maps to a distinct offset below tiledSize, tile/untile invert
// each other, and bytes not covered by a texel (padding) stay zero.
class TilingSizes : public ::testing::TestWithParam<std::tuple<int, int, int, int>> {};

TEST_P(TilingSizes, BijectiveRoundTripZeroPadding) {
    const auto [w, h, d, bpp] = GetParam();
    const auto g = nx::tileGeometry(w, h, d, bpp);
    const std::size_t n = static_cast<std::size_t>(w) * h * d * bpp;
    std::vector<std::uint8_t> linear(n);
    for (std::size_t i = 0; i < n; ++i)
        linear[i] = static_cast<std::uint8_t>(1 + (i * 7919) % 251); // never 0
    const auto tiled = nx::tile(g, linear.data());
    ASSERT_EQ(tiled.size(), nx::tiledSize(g));
    std::size_t nonZero = 0;
    for (auto v : tiled)
        nonZero += v != 0;
    EXPECT_EQ(nonZero, n) << "each texel byte placed once, padding zero";
    EXPECT_EQ(nx::untile(g, tiled.data()), linear);
    if (16 % bpp == 0) {
        // The texel address function agrees with where tile() put the bytes.
        for (int z = 0; z < d; z += std::max(1, d / 3))
            for (int y = 0; y < h; y += std::max(1, h / 3))
                for (int x = 0; x < w; x += std::max(1, w / 3)) {
                    const std::size_t lin = ((static_cast<std::size_t>(z) * h + y) * w + x) * bpp;
                    EXPECT_EQ(tiled[nx::tiledOffset(g, x, y, z)], linear[lin]);
                }
    }
}

INSTANTIATE_TEST_SUITE_P(
    Sizes, TilingSizes,
    ::testing::Values(std::make_tuple(16, 16, 16, 4), std::make_tuple(2, 2, 2, 4),
                      std::make_tuple(3, 3, 3, 4), std::make_tuple(8, 8, 8, 4),
                      std::make_tuple(17, 17, 17, 4), std::make_tuple(33, 33, 33, 4),
                      std::make_tuple(20, 9, 5, 4), std::make_tuple(70, 3, 1, 1),
                      std::make_tuple(13, 11, 7, 3), std::make_tuple(9, 17, 6, 16)));
