// SPDX-License-Identifier: Apache-2.0
// lutkit's TGA reader (formats/src/imageio/TgaCodec.cpp) against OpenImageIO 2.4, the reader it
// replaces, on every variant ImageMagick writes (true colour, colour-mapped with 24- and 16-bit
// maps, grey, raw and RLE, every origin) and the ones the test derives from them byte by byte
// (15/16-bit pixels, 16-bit grey with alpha, packets across rows and past the end, a TGA 2.0
// extension area, a colour map that starts at an index, alpha that is all 0): every sample,
// ImageInfo and the attributes handed to writers (BmpTgaOracle.h). Broken and hostile files: one
// line naming the file, refused where OpenImageIO refuses them.
#include "BmpTgaOracle.h"

#include "lut/Error.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace lut::test;
using namespace lut::test::bmptga;

namespace {

struct Tga {
    std::size_t data; // where the pixels start
    int width, height, bpp, attr;
};
Tga tgaOf(const Bytes& b) {
    const std::size_t map = b[1] ? get16(b, 5) * ((static_cast<unsigned char>(b[7]) + 7) / 8) : 0;
    return {18 + static_cast<unsigned char>(b[0]) + map, static_cast<int>(get16(b, 12)),
            static_cast<int>(get16(b, 14)), static_cast<unsigned char>(b[16]),
            static_cast<unsigned char>(b[17])};
}

// A raw file's pixels run-length coded as one stream (Truevision 2.0, "Run-length Packet"): runs
// of 2 or more equal pixels, raw packets otherwise, packets running on across rows; with
// `overrun`, the last packet is a run of 128 past the image's end.
Bytes runLengthCoded(Bytes b, bool overrun) {
    const Tga t = tgaOf(b);
    const std::size_t pb = (t.bpp + 7) / 8, n = static_cast<std::size_t>(t.width) * t.height;
    const Bytes px = b.substr(t.data, n * pb);
    auto pixel = [&](std::size_t i) { return px.substr(i * pb, pb); };
    Bytes s;
    for (std::size_t i = 0; i < n;) {
        std::size_t run = 1;
        while (i + run < n && run < 128 && pixel(i + run) == pixel(i))
            ++run;
        if (run >= 2 || i + 1 == n) {
            const bool last = i + run == n;
            s += static_cast<char>(0x80 | ((last && overrun ? 128 : run) - 1));
            s += pixel(i);
            i += run;
            continue;
        }
        std::size_t k = 1;
        while (i + k < n && k < 128 && (i + k + 1 >= n || pixel(i + k) != pixel(i + k + 1)))
            ++k;
        s += static_cast<char>(k - 1);
        s += px.substr(i * pb, k * pb);
        i += k;
    }
    b[2] = static_cast<char>(b[2] + 8);
    return b.substr(0, t.data) + s;
}

// A TGA 2.0 extension area and footer after the file (the specification's field offsets), with
// a 2x2 postage stamp before it.
struct Extension {
    int alphaType = 3;
    int gammaNum = 22, gammaDen = 10;
};
Bytes withExtension(Bytes b, const Extension& x) {
    const Tga t = tgaOf(b);
    const std::size_t stamp = b.size();
    b += Bytes("\2\2", 2) + Bytes(4 * ((t.bpp + 7) / 8), '\x40');
    const std::size_t at = b.size();
    Bytes e(495, '\0');
    put16(e, 0, 495);
    e.replace(2, 11, "lutkit test");
    e.replace(43, 9, "A picture");
    e.replace(43 + 162, 9, "of plasma"); // line 2 empty, line 3 set
    const unsigned stampTime[6] = {7, 14, 2023, 12, 34, 56};
    for (int i = 0; i < 6; ++i)
        put16(e, 367 + 2 * i, stampTime[i]);
    e.replace(379, 5, "Job 7");
    put16(e, 420, 1), put16(e, 422, 2), put16(e, 424, 3);
    e.replace(426, 4, "Tool");
    put16(e, 467, 205);
    e[469] = 'b';
    put16(e, 474, 4), put16(e, 476, 3);
    put16(e, 478, static_cast<std::uint32_t>(x.gammaNum));
    put16(e, 480, static_cast<std::uint32_t>(x.gammaDen));
    put32(e, 486, static_cast<std::uint32_t>(stamp));
    e[494] = static_cast<char>(x.alphaType);
    b += e;
    Bytes foot(8, '\0');
    put32(foot, 0, static_cast<std::uint32_t>(at));
    return b + foot + Bytes("TRUEVISION-XFILE.\0", 18);
}

// 24-bit pixels as 32 with an alpha byte of 0 and the header's alpha bits `attrAlpha`.
Bytes zeroAlpha(Bytes b, int attrAlpha) {
    const Tga t = tgaOf(b);
    Bytes px;
    for (int i = 0; i < t.width * t.height; ++i)
        px += b.substr(t.data + 3 * static_cast<std::size_t>(i), 3) + Bytes(1, '\0');
    b[16] = 32;
    b[17] = static_cast<char>((t.attr & 0x30) | attrAlpha);
    return b.substr(0, t.data) + px;
}

class TgaRead : public ReaderTest {
protected:
    std::string made(const std::string& name, const std::string& args, bool alpha = false) {
        return madeAs("TGA:", name, args, alpha);
    }
};

// OpenImageIO 2.4 says 2 bits per sample for an 8-bit colour-mapped file (8 bits / 3 channels):
// lutkit says what a channel is stored with.
Case mapped(const std::string& path, int bits) {
    Case c{path};
    c.bitsPerSample = bits;
    return c;
}

} // namespace

TEST_F(TgaRead, EveryVariantImageMagickWritesReadsAsOpenImageIO) {
    std::vector<Case> cases;
    const char* orients[] = {"BottomLeft", "TopLeft", "TopRight", "BottomRight"};
    for (const char* orient : orients)
        for (const char* rle : {"", "-compress RLE"}) {
            const std::string o = std::string("-orient ") + orient + " " + rle + " ";
            cases.push_back({made("rgb.tga", o + "-type TrueColor")});
            cases.push_back({made("rgba.tga", o + "-type TrueColorAlpha", true)});
            cases.push_back({made("grey.tga", o + "-type Grayscale")});
            cases.push_back(mapped(made("map.tga", o + "-colors 200 -type Palette"), 8));
            const std::string map16 = made("map16.tga", o + "-colors 200 -depth 5 -type Palette");
            cases.push_back(mapped(map16, 5));
            const std::string rgb16 = made("rgb16.tga", o + "-type TrueColor -depth 5");
            cases.push_back({rgb16});
            // ImageMagick wrote what the names say.
            EXPECT_EQ(fileBytes(map16)[7], 16);
            EXPECT_EQ(fileBytes(rgb16)[16], 16);
            EXPECT_EQ(fileBytes(rgb16)[17] & 0x30,
                      (orient[0] == 'T' ? 0x20 : 0) |
                          (std::string(orient).find("Right") != std::string::npos ? 0x10 : 0));
        }
    checkCases(cases);
}

TEST_F(TgaRead, DerivedVariantsReadAsOpenImageIO) {
    std::vector<Case> cases;
    for (const char* orient : {"BottomLeft", "TopRight"}) {
        SCOPED_TRACE(orient);
        const std::string o = std::string("-orient ") + orient + " ";
        const Bytes rgb = fileBytes(made("rgb.tga", o + "-type TrueColor"));
        const Bytes rgba = fileBytes(made("rgba.tga", o + "-type TrueColorAlpha", true));
        const std::string mapPath = made("map.tga", o + "-colors 200 -type Palette");
        const Bytes map = fileBytes(mapPath);
        // 15-bit: the 16-bit file's pixels, said to be 15 bits.
        Bytes rgb15 = fileBytes(made("rgb16.tga", o + "-type TrueColor -depth 5"));
        rgb15[16] = 15;
        cases.push_back({derived("rgb15.tga", rgb15)});
        // Packets across rows, and a last run past the image's end.
        for (bool overrun : {false, true}) {
            cases.push_back({derived("rgb-rle.tga", runLengthCoded(rgb, overrun))});
            cases.push_back({derived("rgba-rle.tga", runLengthCoded(rgba, overrun))});
            cases.push_back(mapped(derived("map-rle.tga", runLengthCoded(map, overrun)), 8));
        }
        // 16-bit grey with 8 alpha bits: OpenImageIO names the channels R, G with no alpha.
        const Bytes grey = fileBytes(made("grey.tga", o + "-type Grayscale"));
        const Tga t = tgaOf(grey);
        Bytes ya;
        for (int i = 0; i < t.width * t.height; ++i)
            ya += Bytes(1, grey[t.data + static_cast<std::size_t>(i)]) +
                  Bytes(1, static_cast<char>((i * 7) % 256));
        Bytes g16 = grey.substr(0, t.data) + ya;
        g16[16] = 16;
        g16[17] = static_cast<char>(t.attr | 8);
        for (const Bytes& f : {g16, runLengthCoded(g16, false)}) {
            Case c{derived("grey-alpha.tga", f)};
            c.names = {"Y", "A"};
            c.alphaChannel = 1;
            cases.push_back(c);
        }
        // A colour map whose first entry is index 10: index v is entry v - 10 (the
        // specification; OpenImageIO read entry v + 10), the colours of the file it came from.
        Bytes shifted = map;
        put16(shifted, 3, 10);
        const Tga m = tgaOf(map);
        for (std::size_t i = m.data; i < shifted.size(); ++i)
            shifted[i] = static_cast<char>(static_cast<unsigned char>(shifted[i]) + 10);
        Case c = mapped(derived("map-first.tga", shifted), 8);
        c.oracle = mapPath;
        cases.push_back(c);
    }
    checkCases(cases);
}

TEST_F(TgaRead, ExtensionAreaAndAlphaAsOpenImageIOOrAsTheyMean) {
    std::vector<Case> cases;
    const Bytes rgba = fileBytes(made("rgba.tga", "-type TrueColorAlpha", true));
    const Bytes rgb = fileBytes(made("rgb.tga", "-type TrueColor"));
    // Author, comments, dates, job, software, aspect, gamma, alpha type, postage stamp.
    const std::string v2 = derived("v2.tga", withExtension(rgba, {}));
    cases.push_back({v2});
    cases.push_back({derived("v2-rle.tga", withExtension(runLengthCoded(rgba, false), {}))});
    cases.push_back({derived("v2-linear.tga", withExtension(rgb, {0, 10, 10}))});
    {
        auto src = lut::formats::openImageSource(v2);
        EXPECT_EQ(src->info().colorSpace, "Gamma2.2");
        const auto& text = src->metadata()->text;
        ASSERT_EQ(text.size(), 4u);
        EXPECT_EQ(text[0], std::make_pair(std::string("ImageDescription"),
                                          std::string("A picture\nof plasma")));
        EXPECT_EQ(text[3], std::make_pair(std::string("Software"), std::string("Tool 2.5b")));
    }
    // Alpha 0 everywhere: opaque unless a 2.0 extension area vouches for it (type 3, 4).
    for (int attr : {0, 8}) {
        Case c{derived("zero-alpha.tga", zeroAlpha(rgb, attr))};
        c.opaque = true;
        cases.push_back(c);
        Case r{derived("zero-alpha-rle.tga", runLengthCoded(zeroAlpha(rgb, attr), false))};
        r.opaque = true;
        cases.push_back(r);
        Case v1{derived("zero-alpha-ignore.tga", withExtension(zeroAlpha(rgb, attr), {1, 0, 0}))};
        v1.opaque = true;
        cases.push_back(v1);
        cases.push_back(
            {derived("zero-alpha-useful.tga", withExtension(zeroAlpha(rgb, attr), {3, 0, 0}))});
    }
    checkCases(cases);
    // Told as TGA without the name: by the named format, or by the 2.0 footer in memory.
    const std::string img = dir + "/v2.img";
    writeBytes(img, fileBytes(v2));
    const std::vector<int> want = oiioPixels({v2})[v2].samples;
    auto named = lut::formats::openImageSource(img, "tga");
    EXPECT_EQ(named->info().format, "targa");
    auto footer = lut::formats::openImageMemory("-", fileBytes(v2));
    EXPECT_EQ(footer->info().format, "targa");
    for (auto* src : {named.get(), footer.get()}) {
        std::vector<unsigned char> buf(lut::formats::rowBytes(src->info()) * 23);
        src->readRows(0, 23, buf.data());
        EXPECT_EQ(std::vector<int>(buf.begin(), buf.end()), want);
    }
}

TEST_F(TgaRead, BrokenAndHostileFilesAreOneLineNamingTheFile) {
    const Bytes rgb = fileBytes(made("rgb.tga", "-type TrueColor"));
    const Bytes rle = fileBytes(made("rle.tga", "-type TrueColor -compress RLE"));
    const Bytes map = fileBytes(made("map.tga", "-colors 200 -type Palette"));
    const Bytes grey = fileBytes(made("grey.tga", "-type Grayscale"));
    refused("short-header.tga", rgb.substr(0, 10), "header is cut short", true);
    Bytes b = rgb;
    b[1] = 2;
    refused("map-type.tga", b, "colour-map type 2", true);
    b = rgb;
    b[2] = 0;
    refused("no-data.tga", b, "holds no image", true);
    b = rgb;
    b[2] = 4;
    refused("type-4.tga", b, "image type 4", true);
    b = rgb;
    b[16] = 12;
    refused("twelve-bits.tga", b, "12 bits", true);
    b = rgb;
    b[16] = 8;
    refused("rgb-8.tga", b, "8 bits", false);
    b = grey;
    b[1] = 1;
    refused("grey-map.tga", b, "has a colour map", true);
    b = map;
    b[1] = 0;
    refused("map-without.tga", b, "has no colour map", true);
    refused("cut.tga", rgb.substr(0, rgb.size() - 100), "truncated", true);
    const std::string cutRle =
        refused("cut-rle.tga", rle.substr(0, rle.size() - 100), "truncated", true);
    b = rgb;
    put16(b, 12, 0);
    refused("no-width.tga", b, "no pixels", false);
    b = rgb;
    put16(b, 12, 65535), put16(b, 14, 65535);
    refused("huge.tga", b, "65535x65535", true);
    // Indices past a colour map cut to 5 entries.
    const Tga m = tgaOf(map);
    b = map.substr(0, 18 + static_cast<unsigned char>(map[0])) +
        map.substr(18 + static_cast<unsigned char>(map[0]), 5 * 3) + map.substr(m.data);
    put16(b, 5, 5);
    refused("index-past-map.tga", b, "colour-map index", false);
    b = runLengthCoded(b, false);
    refused("index-past-map-rle.tga", b, "colour-map index", false);
    // A 2.0 footer whose extension area, or postage stamp, lies past the end.
    b = withExtension(rgb, {});
    put32(b, b.size() - 26, 1u << 30);
    refused("ext-past-end.tga", b, "extension area", true);
    b = withExtension(rgb, {});
    const std::size_t ext = get32(b, b.size() - 26);
    put32(b, ext + 486, 1u << 30);
    refused("stamp-past-end.tga", b, "postage stamp", true);
    expectCliRefuses(cutRle);
}
