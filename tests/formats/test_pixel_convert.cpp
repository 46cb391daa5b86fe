// SPDX-License-Identifier: Apache-2.0
// formats/src/imageio/PixelConvert: stored samples <-> float RGBA, against the definitions
// written here in float64 (lut/Quantize.h's rule: round half away from zero, clamp to [0, 1],
// NaN -> 0; v/255 and v/65535 on the way in; IEEE half). The 8/16-bit writes and the half
// runs and the 8-bit reads have vectorized paths (AVX, F16C) with a scalar tail: runs of every
// length up to 19 go through both, with values one ulp either side of every rounding boundary.
#include "imageio/PixelConvert.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

using namespace lut::formats;

namespace {

double expectedUnorm(float v, double max) {
    if (!(v > 0.0f))
        return 0.0;
    if (v >= 1.0f)
        return max;
    return std::floor(static_cast<double>(v) * max + 0.5);
}

// Values that probe the rounding: one ulp either side of (k + 0.5) / max for k spread over the
// range, the edges, NaN, infinities, -0, denormals, and random values in and around [0, 1].
std::vector<float> probes(double max) {
    std::vector<float> v;
    const float inf = std::numeric_limits<float>::infinity();
    for (float x : {0.0f, -0.0f, 1.0f, -1.0f, 2.0f, 1e-45f, -1e-45f, 1e30f, -1e30f, inf, -inf,
                    std::numeric_limits<float>::quiet_NaN(), 0.99999994f, 1.0000001f})
        v.push_back(x);
    const int steps = max > 255 ? 65536 : 256; // every rounding boundary
    for (int i = 0; i < steps; ++i) {
        const double k = std::floor(i * (max - 1) / (steps - 1));
        const float mid = static_cast<float>((k + 0.5) / max);
        v.push_back(mid);
        v.push_back(std::nextafter(mid, 0.0f));
        v.push_back(std::nextafter(mid, 2.0f));
    }
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-0.25f, 1.25f);
    for (int i = 0; i < 2000; ++i)
        v.push_back(u(rng));
    return v;
}

template <class T> void checkWrites(PixelType type, double max) {
    const std::vector<float> values = probes(max);
    for (int nch : {3, 4}) {
        RgbaMap map;
        map.a = nch == 4 ? 3 : -1;
        for (std::size_t n = 1; n <= 19; ++n)
            for (std::size_t at = 0; at + 4 * n <= values.size(); at += 4 * n) {
                const float* rgba = values.data() + at;
                std::vector<T> out(n * static_cast<std::size_t>(nch));
                fromRgba(rgba, n, out.data(), type, nch, map);
                for (std::size_t i = 0; i < n; ++i)
                    for (int c = 0; c < nch; ++c) {
                        const float v = rgba[4 * i + static_cast<std::size_t>(c)];
                        ASSERT_EQ(static_cast<double>(out[i * nch + c]), expectedUnorm(v, max))
                            << "value " << v << " (" << nch << " channels, run of " << n << ")";
                    }
            }
    }
}

// IEEE binary16, decoded from its fields in float64.
double halfValue(std::uint16_t h) {
    const int e = (h >> 10) & 31, m = h & 1023;
    const double s = (h & 0x8000) ? -1.0 : 1.0;
    if (e == 0)
        return s * std::ldexp(m, -24);
    if (e == 31)
        return m ? std::numeric_limits<double>::quiet_NaN()
                 : s * std::numeric_limits<double>::infinity();
    return s * std::ldexp(1024 + m, e - 25);
}

} // namespace

TEST(PixelConvert, EightBitWritesRoundAsTheRuleSays) {
    checkWrites<std::uint8_t>(PixelType::UInt8, 255.0);
}

TEST(PixelConvert, SixteenBitWritesRoundAsTheRuleSays) {
    checkWrites<std::uint16_t>(PixelType::UInt16, 65535.0);
}

// Every run length up to 19 (the AVX path's blocks of 4 and the scalar tail; RGB reads ahead, so
// the buffer is exactly the run: ASan sees a read past it) and 256 pixels (every code).
TEST(PixelConvert, EightBitReadsAreTheDivision) {
    std::vector<std::size_t> lengths{256};
    for (std::size_t n = 1; n <= 19; ++n)
        lengths.push_back(n);
    for (int nch : {3, 4})
        for (std::size_t n : lengths) {
            std::vector<std::uint8_t> in(n * static_cast<std::size_t>(nch));
            for (std::size_t i = 0; i < in.size(); ++i)
                in[i] = static_cast<std::uint8_t>((i * 37 + 11) % 256);
            RgbaMap map;
            map.a = nch == 4 ? 3 : -1;
            std::vector<float> rgba(4 * n);
            toRgba(in.data(), PixelType::UInt8, nch, map, n, rgba.data());
            for (std::size_t i = 0; i < n; ++i)
                for (int c = 0; c < 4; ++c) {
                    const float want = c < nch ? static_cast<float>(in[i * nch + c] / 255.0) : 1.0f;
                    ASSERT_EQ(rgba[4 * i + c], want) << i << " " << c;
                }
        }
}

// Half RGB and RGBA runs, both ways, over every half value: reads give the value exactly,
// writes of those floats give the same bits back (NaNs stay NaN).
TEST(PixelConvert, HalfRunsReadAndWriteEveryValue) {
    for (int nch : {3, 4}) {
        RgbaMap map;
        map.a = nch == 4 ? 3 : -1;
        std::vector<std::uint16_t> in;
        for (std::uint32_t h = 0; h < 65536; ++h)
            in.push_back(static_cast<std::uint16_t>(h));
        while (in.size() % static_cast<std::size_t>(nch))
            in.push_back(0x3c00);
        const std::size_t n = in.size() / static_cast<std::size_t>(nch);
        std::vector<float> rgba(4 * n);
        toRgba(in.data(), PixelType::Half, nch, map, n, rgba.data());
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < nch; ++c) {
                const double want = halfValue(in[i * nch + c]);
                const float got = rgba[4 * i + c];
                if (std::isnan(want))
                    ASSERT_TRUE(std::isnan(got));
                else
                    ASSERT_EQ(static_cast<double>(got), want) << std::hex << in[i * nch + c];
            }
        std::vector<std::uint16_t> back(in.size(), 0x1234);
        fromRgba(rgba.data(), n, back.data(), PixelType::Half, nch, map);
        for (std::size_t k = 0; k < in.size(); ++k)
            if (!std::isnan(halfValue(in[k])))
                ASSERT_EQ(back[k], in[k]) << k;
            else
                ASSERT_TRUE(std::isnan(halfValue(back[k])));
    }
}

// Half RGB runs of every length up to 19 in buffers of exactly that size (the one-pass path reads
// ahead and works two pixels at a time; ASan sees a read or write past the run): alpha reads as 1,
// values exactly, writes give the same bits back and touch nothing past the run.
TEST(PixelConvert, HalfRgbRunsOfEveryLength) {
    RgbaMap map;
    map.a = -1;
    for (std::size_t n = 1; n <= 19; ++n) {
        std::vector<std::uint16_t> in(3 * n);
        for (std::size_t k = 0; k < in.size(); ++k)
            in[k] = static_cast<std::uint16_t>(0x3000 + 97 * k); // 0.125 upwards
        std::vector<float> rgba(4 * n);
        toRgba(in.data(), PixelType::Half, 3, map, n, rgba.data());
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t c = 0; c < 3; ++c)
                ASSERT_EQ(static_cast<double>(rgba[4 * i + c]), halfValue(in[3 * i + c]))
                    << n << " " << i << " " << c;
            ASSERT_EQ(rgba[4 * i + 3], 1.0f) << n << " " << i;
        }
        std::vector<std::uint16_t> back(3 * n + 3, 0x1234);
        fromRgba(rgba.data(), n, back.data(), PixelType::Half, 3, map);
        for (std::size_t k = 0; k < 3 * n; ++k)
            ASSERT_EQ(back[k], in[k]) << n << " " << k;
        for (std::size_t k = 3 * n; k < back.size(); ++k)
            ASSERT_EQ(back[k], 0x1234) << n << " " << k;
    }
}

// A reader's channel list or alpha index may point past the channels it stores (OpenImageIO's
// GIF reader said alpha = 4 of 4 channels for a fuzzed file, and the conversion read one sample
// past every row): the map uses only stored channels, alpha by its name when the index is wrong.
TEST(PixelConvert, ChannelIndicesPastTheStoredChannelsAreNeverUsed) {
    ImageInfo gif;
    gif.channels = 4;
    gif.type = PixelType::UInt8;
    gif.channelNames = {"R", "G", "B", "A"};
    gif.alphaChannel = 4;
    RgbaMap m = rgbaMapOf(gif);
    EXPECT_EQ(m.a, 3);

    gif.channelNames = {"R", "G", "B"};
    m = rgbaMapOf(gif); // no channel named A: no alpha
    EXPECT_EQ(m.a, -1);

    ImageInfo named; // more names than stored channels
    named.channels = 3;
    named.type = PixelType::UInt8;
    named.channelNames = {"X", "Y", "Z", "R", "G", "B"};
    m = rgbaMapOf(named);
    for (int i : {m.r, m.g, m.b, m.a})
        EXPECT_LT(i, 3);

    // The converted pixels: (10, 20, 30, 40) in 8 bits, alpha read from channel 3.
    gif.channelNames = {"R", "G", "B", "A"};
    m = rgbaMapOf(gif);
    const std::vector<std::uint8_t> px = {10, 20, 30, 40, 50, 60, 70, 80};
    std::vector<float> rgba(8);
    toRgba(px.data(), PixelType::UInt8, 4, m, 2, rgba.data());
    for (int i = 0; i < 8; ++i)
        EXPECT_FLOAT_EQ(rgba[i], static_cast<float>(px[i] / 255.0)) << i;
}
