// SPDX-License-Identifier: Apache-2.0
// The PNG writer (formats/src/imageio/PngWriter.cpp) at every compression level, decoded by
// OpenImageIO (libpng + zlib, which checks the stream's Adler-32 and every chunk's CRC) and by
// ffmpeg's own PNG decoder where installed. Levels 1-3 deflate with ISA-L and the others with zlib,
// each in strips of about 1 MiB primed with the strip before's last 32 KiB: the pictures here are
// several strips tall and mix noise (stored and literal blocks), flat areas (long matches across
// strip boundaries) and ramps, so every way a strip can end is in them. The expected samples are
// the codes the test put in, k / 255 and k / 65535 exactly.
#include "lut/Image.h"
#include "lut/formats/ImageIO.h"

#include "TestSupport.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace {

// Codes per sample (0..maxCode) for a w x h picture of `channels`: the top third noise, the middle
// third flat patches, the bottom third ramps.
std::vector<int> pictureCodes(int w, int h, int channels, int maxCode, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> any(0, maxCode);
    std::vector<int> codes(static_cast<std::size_t>(w) * h * channels);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < channels; ++c) {
                int v;
                if (y < h / 3)
                    v = any(rng);
                else if (y < 2 * h / 3)
                    v = ((x / 97 + y / 61 + c) % 3) * (maxCode / 2);
                else
                    v = static_cast<int>((static_cast<long long>(x + 3 * y + 17 * c) * 7) %
                                         (maxCode + 1));
                codes[(static_cast<std::size_t>(y) * w + x) * channels + c] = v;
            }
    return codes;
}

lut::Image imageOf(const std::vector<int>& codes, int w, int h, int channels, int maxCode) {
    lut::Image img(w, h, 1.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < channels; ++c)
                img.pixel(x, y)[c] =
                    static_cast<float>(
                        codes[(static_cast<std::size_t>(y) * w + x) * channels + c]) /
                    static_cast<float>(maxCode);
    return img;
}

// The samples OpenImageIO decodes, as codes.
std::vector<int> decodedCodes(const std::string& path, int channels, int maxCode, int* w, int* h) {
    OIIO::ImageSpec config; // the stored samples, not multiplied by alpha
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    EXPECT_TRUE(in) << path << ": " << OIIO::geterror();
    if (!in)
        return {};
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.nchannels, channels) << path;
    *w = spec.width;
    *h = spec.height;
    std::vector<std::uint16_t> px(static_cast<std::size_t>(spec.width) * spec.height *
                                  spec.nchannels);
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT16, px.data()))
        << path << ": " << in->geterror();
    std::vector<int> codes(px.size());
    for (std::size_t i = 0; i < px.size(); ++i) // UINT16 of an 8-bit file is code * 257
        codes[i] = maxCode == 255 ? px[i] / 257 : px[i];
    return codes;
}

void expectLevelsDecodeExactly(int w, int h, int channels, int bits) {
    const int maxCode = bits == 8 ? 255 : 65535;
    const std::vector<int> codes = pictureCodes(w, h, channels, maxCode, 1234u + bits);
    const lut::Image img = imageOf(codes, w, h, channels, maxCode);
    const std::string dir = lut::test::tempDir();
    const bool ffmpeg = lut::test::haveProgram("ffmpeg");
    for (const std::string level :
         {"", "zip:0", "zip:1", "zip:2", "zip:3", "zip:4", "zip:6", "zip:9"}) {
        SCOPED_TRACE("compression '" + level + "', " + std::to_string(bits) + "-bit, " +
                     std::to_string(channels) + " channels");
        lut::formats::ImageWriteOptions o(bits, false, channels == 4);
        o.compression = level;
        const std::string path =
            dir + "/level" + (level.empty() ? std::string("default") : level.substr(4)) + ".png";
        lut::formats::writeImage(path, img, o);
        int rw = 0, rh = 0;
        const std::vector<int> back = decodedCodes(path, channels, maxCode, &rw, &rh);
        ASSERT_EQ(rw, w);
        ASSERT_EQ(rh, h);
        ASSERT_EQ(back.size(), codes.size());
        std::size_t wrong = 0, first = 0;
        for (std::size_t i = 0; i < codes.size(); ++i)
            if (back[i] != codes[i] && wrong++ == 0)
                first = i;
        EXPECT_EQ(wrong, 0u) << "first at sample " << first << ": " << back[first] << " for "
                             << codes[first];
        if (ffmpeg) { // a second decoder: ffmpeg's PNG decoder, samples as raw big-endian bytes
            const std::string raw = path + ".raw";
            const auto r = lut::test::runCommand(
                "ffmpeg -v error -y -i " + lut::test::shellQuoted(path) + " -f rawvideo -pix_fmt " +
                (bits == 8 ? (channels == 3 ? "rgb24" : "rgba")
                           : (channels == 3 ? "rgb48be" : "rgba64be")) +
                " " + lut::test::shellQuoted(raw) + " 2>&1");
            ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
            const std::string bytes = lut::test::fileBytes(raw);
            const std::size_t each = bits == 8 ? 1 : 2;
            ASSERT_EQ(bytes.size(), codes.size() * each);
            std::size_t differ = 0;
            for (std::size_t i = 0; i < codes.size(); ++i) {
                const auto* b = reinterpret_cast<const unsigned char*>(bytes.data()) + i * each;
                const int v = each == 1 ? b[0] : (b[0] << 8 | b[1]);
                differ += v != codes[i];
            }
            EXPECT_EQ(differ, 0u) << "samples ffmpeg decodes differently";
        }
    }
}

} // namespace

TEST(PngWrite, EveryLevelDecodesExactlyAcrossStrips8BitRgb) {
    // 1500 x 3 + 1 bytes a row, 900 rows: 4 MB filtered, four strips.
    expectLevelsDecodeExactly(1500, 900, 3, 8);
}

TEST(PngWrite, EveryLevelDecodesExactlyAcrossStrips16BitRgba) {
    // Two thirds of it incompressible noise in the top third's rows: stored blocks.
    expectLevelsDecodeExactly(700, 600, 4, 16);
}
