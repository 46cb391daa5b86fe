// SPDX-License-Identifier: Apache-2.0
// lutkit's BMP reader (formats/src/imageio/BmpCodec.cpp) against OpenImageIO 2.4, the reader it
// replaces, on every variant ImageMagick writes and the ones the test derives from them byte by
// byte (top-down rows, RLE4 and RLE with deltas, GDI's X8R8G8B8, a short colour map): every
// sample, ImageInfo and the attributes handed to writers (BmpTgaOracle.h). Broken and hostile
// files: one line naming the file, refused where OpenImageIO refuses them.
#include "BmpTgaOracle.h"

#include "lut/Error.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace lut::test;
using namespace lut::test::bmptga;

namespace {

struct Layout {
    std::size_t offset, stride;
    int width, height, bpp;
};
Layout layoutOf(const Bytes& b) {
    Layout l{};
    l.offset = get32(b, 10);
    l.width = static_cast<std::int32_t>(get32(b, 18));
    l.height = static_cast<std::int32_t>(get32(b, 22));
    l.bpp = static_cast<int>(get16(b, 28));
    l.stride = (static_cast<std::size_t>(l.width) * l.bpp + 31) / 32 * 4;
    return l;
}

// The same picture stored top-down: rows reversed, the height negative.
Bytes topDown(Bytes b) {
    const Layout l = layoutOf(b);
    const Bytes rows = b.substr(l.offset, l.stride * l.height);
    for (int r = 0; r < l.height; ++r)
        b.replace(l.offset + r * l.stride, l.stride,
                  rows.substr((l.height - 1 - r) * l.stride, l.stride));
    put32(b, 22, static_cast<std::uint32_t>(-l.height));
    return b;
}

// ImageMagick ends an RLE stream with an end-of-line after the last row, then the end-of-bitmap
// marker, which OpenImageIO refuses; the twin ends the last row with the marker alone.
Bytes endOfBitmapTwin(const Bytes& b) {
    EXPECT_EQ(b.substr(b.size() - 4), Bytes("\0\0\0\1", 4));
    return b.substr(0, b.size() - 4) + Bytes("\0\1", 2);
}

// An uncompressed 4- or 8-bit file run-length coded by the specification ("Bitmap Compression"):
// runs of 3 or more equal indices, literal runs of 3 or more, single runs otherwise; rows ended by
// end-of-line, the last by end-of-bitmap. With `delta`, the third stored row starts with a delta
// to x 5 of the fourth: the rest of the third and 5 pixels of the fourth are left (entry 0).
Bytes runLengthCoded(Bytes b, bool delta) {
    const Layout l = layoutOf(b);
    const bool four = l.bpp == 4;
    auto index = [&](int r, int x) {
        const unsigned char byte = static_cast<unsigned char>(
            b[l.offset + r * l.stride + static_cast<std::size_t>(four ? x / 2 : x)]);
        return four ? (x % 2 ? byte & 15 : byte >> 4) : byte;
    };
    Bytes s;
    auto add = [&](int v) { s.push_back(static_cast<char>(v)); };
    int startX = 0;
    for (int r = 0; r < l.height; ++r) {
        if (delta && r == 2) {
            add(0), add(2), add(5), add(1);
            startX = 5;
            continue;
        }
        for (int x = startX; x < l.width;) {
            auto runAt = [&](int i) {
                int n = 1;
                while (i + n < l.width && n < 255 && index(r, i + n) == index(r, i))
                    ++n;
                return n;
            };
            const int run = runAt(x);
            if (run >= 3 || l.width - x < 3) {
                add(run), add(four ? index(r, x) * 17 : index(r, x));
                x += run;
                continue;
            }
            int n = 0;
            while (x + n < l.width && n < 255 && (n < 3 || runAt(x + n) < 3))
                ++n;
            add(0), add(n);
            const int bytes = four ? ((n + 1) / 2 + 1) & ~1 : (n + 1) & ~1;
            for (int i = 0; i < bytes; ++i)
                add(four ? (2 * i < n ? index(r, x + 2 * i) << 4 : 0) |
                               (2 * i + 1 < n ? index(r, x + 2 * i + 1) : 0)
                         : (i < n ? index(r, x + i) : 0));
            x += n;
        }
        startX = 0;
        add(0), add(r + 1 < l.height ? 0 : 1);
    }
    put32(b, 30, four ? 2 : 1);
    put32(b, 34, static_cast<std::uint32_t>(s.size()));
    b = b.substr(0, l.offset) + s;
    put32(b, 2, static_cast<std::uint32_t>(b.size()));
    return b;
}

// A 24-bit file as GDI's 32-bit X8R8G8B8: B, G, R and an unused 0 byte, no alpha mask.
Bytes unusedFourthByte(Bytes b) {
    const Layout l = layoutOf(b);
    Bytes px;
    for (int r = 0; r < l.height; ++r)
        for (int x = 0; x < l.width; ++x)
            px += b.substr(l.offset + r * l.stride + 3 * x, 3) + Bytes(1, '\0');
    put16(b, 28, 32);
    put32(b, 34, static_cast<std::uint32_t>(px.size()));
    b = b.substr(0, l.offset) + px;
    put32(b, 2, static_cast<std::uint32_t>(b.size()));
    return b;
}

class BmpRead : public ReaderTest {
protected:
    // ImageMagick's file NAME written as PREFIX (BMP3:, BMP:, BMP2:) with ARGS.
    std::string made(const std::string& name, const std::string& prefix, const std::string& args,
                     bool alpha = false) {
        return madeAs(prefix, name, args, alpha);
    }
};

} // namespace

TEST_F(BmpRead, EveryVariantImageMagickWritesReadsAsOpenImageIO) {
    struct Made {
        const char* name;
        const char* prefix;
        const char* args;
        bool alpha;
    };
    const Made made_[] = {
        {"v3-24.bmp", "BMP3:", "-type TrueColor", false},
        {"v3-32-alpha.bmp", "BMP3:", "-define bmp3:alpha=true", true},
        {"v4-32-alpha.bmp", "BMP:", "-define bmp:format=bmp4", true},
        {"v5-32-alpha.bmp", "BMP:", "", true},
        {"v5-24.bmp", "BMP:", "-type TrueColor", false},
        {"v3-8.bmp", "BMP3:", "-colors 200 -type Palette -compress None", false},
        {"v5-8.bmp", "BMP:", "-colors 200 -type Palette -compress None", false},
        {"v3-4.bmp", "BMP3:", "-colors 12", false},
        {"v3-1.bmp", "BMP3:", "-monochrome", false},
        {"v3-8-grey.bmp", "BMP3:", "-colorspace Gray -colors 200 -compress None", false},
        {"v3-4-grey.bmp", "BMP3:", "-colorspace Gray -colors 12", false},
        {"v3-565.bmp", "BMP3:", "-type TrueColor -define bmp:subtype=RGB565", false},
        {"v3-555.bmp", "BMP3:", "-type TrueColor -define bmp:subtype=RGB555", false},
        {"v5-565.bmp", "BMP:", "-type TrueColor -define bmp:subtype=RGB565", false},
        {"v5-555.bmp", "BMP:", "-type TrueColor -define bmp:subtype=RGB555", false},
        {"v5-1555.bmp", "BMP:", "-define bmp:subtype=ARGB1555", true},
        {"v5-4444.bmp", "BMP:", "-define bmp:subtype=ARGB4444", true},
        {"os2-24.bmp", "BMP2:", "-type TrueColor", false},
        {"os2-8.bmp", "BMP2:", "-colors 200 -compress None", false},
    };
    std::vector<Case> cases;
    for (const Made& m : made_)
        cases.push_back({made(m.name, m.prefix, m.args, m.alpha)});
    checkCases(cases);
}

TEST_F(BmpRead, TopDownRowsReadAsOpenImageIO) {
    std::vector<Case> cases;
    for (const char* args :
         {"-type TrueColor", "-define bmp3:alpha=true", "-colors 200 -type Palette -compress None",
          "-colors 12", "-monochrome", "-type TrueColor -define bmp:subtype=RGB565"}) {
        SCOPED_TRACE(args);
        const std::string up = made("up.bmp", "BMP3:", args, true);
        cases.push_back({derived("down.bmp", topDown(fileBytes(up)))});
    }
    checkCases(cases);
}

// ImageMagick's RLE8 (its default for 8-bit BMP3) ends its last row with an end-of-line before
// the end-of-bitmap marker: OpenImageIO 2.4 refuses it ("out-of-bounds pixel"), lutkit reads it
// as OpenImageIO reads the twin whose last row ends with the marker alone.
TEST_F(BmpRead, RunLengthFilesReadAsOpenImageIOReadsTheirTwins) {
    std::vector<Case> cases;
    for (const char* args :
         {"-colors 200 -type Palette", "-colors 200 -type Palette -compress RLE"}) {
        SCOPED_TRACE(args);
        const std::string im = made("im-rle8.bmp", "BMP3:", args);
        ASSERT_EQ(get32(fileBytes(im), 30), 1u) << "ImageMagick wrote no RLE8";
        EXPECT_TRUE(oiioRefuses(im));
        const std::string twin = derived("twin-rle8.bmp", endOfBitmapTwin(fileBytes(im)));
        cases.push_back({im, twin});
        cases.push_back({twin});
    }
    // A grey colour map: OpenImageIO says one channel but writes three bytes a pixel (the first
    // third of each row); lutkit gives the map's grey, as OpenImageIO's RGB read of the file.
    const Bytes g = fileBytes(made("g.bmp", "BMP3:", "-colorspace Gray -colors 200"));
    ASSERT_EQ(get16(g, 28), 8u);
    ASSERT_EQ(get32(g, 30), 1u);
    const std::string grey = derived("grey-rle8.bmp", endOfBitmapTwin(g));
    Case c{grey};
    c.extra = "--iconfig bmp:monochrome_detect 0";
    c.greyFromRed = true;
    cases.push_back(c);
    // Wide rows (a mark at every row), the test's own coder: RLE8 and RLE4, with a delta.
    const std::string wide = dir + "/wide.png";
    magick("-seed 5 -size 301x9 plasma:fractal -depth 8", wide);
    for (const char* args : {"-colors 200 -type Palette -compress None", "-colors 12"})
        for (const std::string& from : {src.rgb, wide})
            for (bool delta : {false, true}) {
                SCOPED_TRACE(std::string(args) + (delta ? ", delta" : "") + " " + from);
                const std::string plain = unique("plain.bmp");
                magick(shellQuoted(from) + " " + args, "BMP3:" + plain);
                cases.push_back({derived("coded.bmp", runLengthCoded(fileBytes(plain), delta))});
            }
    checkCases(cases);
}

TEST_F(BmpRead, OddFilesReadAsOpenImageIOOrAsTheyMean) {
    std::vector<Case> cases;
    // Colour-map indices past a short map take its last entry (OpenImageIO's clamp).
    Bytes four = fileBytes(made("four.bmp", "BMP3:", "-colors 12"));
    put32(four, 46, 3);
    cases.push_back({derived("short-map.bmp", four)});
    // GDI's X8R8G8B8: no alpha mask, every fourth byte 0. OpenImageIO: alpha 0 everywhere (a
    // picture that vanishes); lutkit: opaque, the colours OpenImageIO reads.
    Case x{derived("x8r8g8b8.bmp",
                   unusedFourthByte(fileBytes(made("rgb.bmp", "BMP3:", "-type TrueColor"))))};
    x.opaque = true;
    cases.push_back(x);
    // An alpha that is 0 somewhere but not everywhere is alpha (BI_RGB, as ImageMagick writes it).
    cases.push_back({made("some-alpha.bmp", "BMP3:", "-define bmp3:alpha=true", true)});
    checkCases(cases);
}

TEST_F(BmpRead, BrokenAndHostileFilesAreOneLineNamingTheFile) {
    const Bytes rgb = fileBytes(made("rgb.bmp", "BMP3:", "-type TrueColor"));
    const Bytes rle = fileBytes(made("rle.bmp", "BMP3:", "-colors 200 -type Palette"));
    const Bytes four = fileBytes(made("four.bmp", "BMP3:", "-colors 12"));
    refused("cut.bmp", rgb.substr(0, rgb.size() - 100), "truncated", true);
    refused("cut-rle.bmp", rle.substr(0, rle.size() / 2), "truncated", true);
    refused("cut-header.bmp", rgb.substr(0, 30), "truncated", true);
    // A command after the last row's end-of-line (a run of 5 pixels of entry 2).
    const std::string pastEnd =
        refused("past-end.bmp", rle.substr(0, rle.size() - 2) + Bytes("\x05\x02\0\1", 4),
                "past the last row", true);
    Bytes b = rgb;
    put32(b, 18, 100000), put32(b, 22, 100000);
    refused("huge.bmp", b, "100000x100000", true);
    b = rgb;
    put32(b, 18, 0);
    refused("no-width.bmp", b, "no pixels", true);
    b = rgb;
    put32(b, 22, 0);
    refused("no-height.bmp", b, "no pixels", true);
    b = four;
    put32(b, 46, 17);
    refused("many-colours.bmp", b, "colour count 17", true);
    b = rgb;
    put32(b, 14, 64);
    refused("os2v2.bmp", b, "info header of 64 bytes", false);
    b = rgb;
    put32(b, 30, 4);
    refused("jpeg.bmp", b, "compression 4", false);
    b = rgb;
    put16(b, 28, 2);
    refused("two-bit.bmp", b, "2 bits per pixel", true);
    b = four;
    put32(b, 30, 1);
    refused("rle8-four.bmp", b, "RLE8 needs 8 bits", false);
    // A colour map that runs past the end of a file whose pixels fit.
    b = rgb.substr(0, 54) + Bytes(16, '\0');
    put16(b, 28, 8), put32(b, 18, 1), put32(b, 22, 1), put32(b, 46, 256);
    put32(b, 10, 54);
    refused("map-past-end.bmp", b, "colour map of 256 entries", true);
    expectCliRefuses(pastEnd);
}
