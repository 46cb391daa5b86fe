// SPDX-License-Identifier: Apache-2.0
// LUT images: pixel positions of each layout checked against hand-computed places in the file
// (read back with OpenImageIO directly, not with our reader), exact 8/16-bit/float round trips,
// any N, bit depths, clamping and quantisation diagnostics, dither, Hald through the strip format.
#include "lut/Quantize.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/Layout.h"

#include "TestSupport.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>

using lut::test::tempDir;

namespace {

// The raw integer samples of an image file, via OIIO (independent of our reader).
struct Raw {
    int w = 0, h = 0, ch = 0;
    OIIO::TypeDesc type;
    std::vector<float> px; // as float in the file's own units (0..255, 0..65535 or float)
    float at(int x, int y, int c) const {
        return px[(static_cast<std::size_t>(y) * w + x) * ch + c];
    }
};

Raw rawRead(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << path;
    Raw r;
    r.w = in->spec().width;
    r.h = in->spec().height;
    r.ch = in->spec().nchannels;
    r.type = in->spec().format;
    std::vector<float> buf(static_cast<std::size_t>(r.w) * r.h * r.ch);
    in->read_image(0, 0, 0, r.ch, OIIO::TypeDesc::FLOAT, buf.data());
    const double scale = r.type == OIIO::TypeDesc::UINT8    ? 255.0
                         : r.type == OIIO::TypeDesc::UINT16 ? 65535.0
                                                            : 1.0;
    if (scale > 1.0)
        for (auto& v : buf)
            v = static_cast<float>(std::round(v * scale));
    r.px = std::move(buf);
    return r;
}

// A LUT of 8-bit values that differ per entry and per channel.
lut::Lut3D graded8(int n) {
    lut::Lut3D lut(n);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                lut.at(r, g, b) =
                    glm::vec3(static_cast<float>((r * 37 + g * 11 + b * 5) % 256) / 255.0f,
                              static_cast<float>((r * 3 + g * 71 + b * 13) % 256) / 255.0f,
                              static_cast<float>((r * 7 + g * 17 + b * 101) % 256) / 255.0f);
    return lut;
}

lut::LutFile fileOf(const lut::Lut3D& l) {
    lut::LutFile f;
    f.cube = l;
    return f;
}

lut::Diagnostics write(const std::string& path, const lut::Lut3D& l, const std::string& layout,
                       int bits = 0, const std::string& format = {}) {
    lut::FormatOptions o;
    o.layout = lut::parseOptionalLayout(layout);
    o.bitDepth = bits;
    return lut::formats::writeLut(path, fileOf(l), o, format);
}

lut::LutFile read(const std::string& path, const std::string& layout = {}) {
    lut::FormatOptions o;
    o.layout = lut::parseOptionalLayout(layout);
    return lut::formats::readLut(path, o);
}

bool hasMessage(const lut::Diagnostics& d, const std::string& s) {
    for (const auto& x : d)
        if (x.message.find(s) != std::string::npos)
            return true;
    return false;
}

// Neutral 16^3 with one marked entry (3,5,7) = (0.2, 0.4, 0.6) (51, 102, 153 in 8 bits).
lut::Lut3D marked16() {
    lut::Lut3D lut = lut::Lut3D::identity(16);
    lut.at(3, 5, 7) = glm::vec3(51 / 255.0f, 102 / 255.0f, 153 / 255.0f);
    return lut;
}

void expectMarkAt(const std::string& path, int x, int y) {
    const Raw r = rawRead(path);
    EXPECT_EQ(r.at(x, y, 0), 51.0f);
    EXPECT_EQ(r.at(x, y, 1), 102.0f);
    EXPECT_EQ(r.at(x, y, 2), 153.0f);
}

} // namespace

TEST(StripLayouts, HandComputedPixelPositions) {
    const std::string dir = tempDir();
    write(dir + "/p.png", marked16(), "pilot");
    expectMarkAt(dir + "/p.png", 3 + 16 * 7, 5);
    write(dir + "/u.png", marked16(), "unreal");
    expectMarkAt(dir + "/u.png", 3 + 16 * 7, 5);
    write(dir + "/un.png", marked16(), "unity");
    expectMarkAt(dir + "/un.png", 3 + 16 * 7, 10);
    write(dir + "/s.png", marked16(), "smush");
    expectMarkAt(dir + "/s.png", 3 + 16 * 5, 7);
    write(dir + "/l.png", marked16(), "lattice");
    expectMarkAt(dir + "/l.png", 3 + 16 * 5, 7);
    // Hald level 4: i = 3 + 16*5 + 256*7 = 1875 -> x = 1875 % 64 = 19, y = 1875 / 64 = 29.
    write(dir + "/h.png", marked16(), "hald");
    expectMarkAt(dir + "/h.png", 19, 29);
    const Raw h = rawRead(dir + "/h.png");
    EXPECT_EQ(h.w, 64);
    EXPECT_EQ(h.h, 64);
    // Pilot: green 0 on the top row, red to the right: pixel (15, 0) is entry (15, 0, 0),
    // stored as (255, 0, 0).
    const Raw p = rawRead(dir + "/p.png");
    EXPECT_EQ(p.w, 256);
    EXPECT_EQ(p.h, 16);
    EXPECT_EQ(p.at(15, 0, 0), 255.0f);
    EXPECT_EQ(p.at(15, 0, 1), 0.0f);
    EXPECT_EQ(p.at(0, 15, 1), 255.0f);      // green 15 on the bottom row
    EXPECT_EQ(p.at(16 * 15, 0, 2), 255.0f); // blue 15 in the last tile
    const Raw u = rawRead(dir + "/un.png");
    EXPECT_EQ(u.at(0, 0, 1), 255.0f); // unity: green 15 on the top row
}

TEST(StripLayouts, ReadsEachLayoutBackAtTheMarkedEntry) {
    const std::string dir = tempDir();
    for (const char* layout : {"pilot", "unity", "smush", "hald", "godot", "lattice"}) {
        SCOPED_TRACE(layout);
        const std::string path = dir + "/" + layout + ".png";
        write(path, marked16(), layout);
        const lut::LutFile f = read(path, layout);
        ASSERT_TRUE(f.cube);
        EXPECT_EQ(f.cube->at(3, 5, 7), glm::vec3(51 / 255.0f, 102 / 255.0f, 153 / 255.0f));
        EXPECT_EQ(f.cube->at(15, 0, 0), glm::vec3(1.0f, 0.0f, 0.0f));
        EXPECT_EQ(f.sourceBitDepth, 8);
        EXPECT_EQ(f.dialect, lut::toString(lut::parseLayout(layout)));
    }
}

TEST(StripRoundTrip, EightBitExactAnySizeAndLayout) {
    const std::string dir = tempDir();
    for (int n : {2, 3, 16, 17, 33}) {
        for (const char* layout : {"pilot", "unity", "smush"}) {
            SCOPED_TRACE(std::to_string(n) + " " + layout);
            const std::string path = dir + "/g" + std::to_string(n) + layout + ".png";
            const lut::Lut3D lut = graded8(n);
            const auto diags = write(path, lut, layout);
            EXPECT_FALSE(hasMessage(diags, "quantised"))
                << "8-bit values must not be reported as quantised";
            const lut::LutFile back = read(path, layout);
            ASSERT_EQ(back.cube->size(), n);
            EXPECT_EQ(back.cube->entries(), lut.entries());
            EXPECT_EQ(rawRead(path).type, OIIO::TypeDesc::UINT8);
        }
    }
}

TEST(StripRoundTrip, SixteenBitPngAndTiffExact) {
    const std::string dir = tempDir();
    lut::Lut3D lut(9);
    for (std::size_t i = 0; i < lut.entryCount(); ++i)
        lut.entries()[i] =
            glm::vec3(lut::fromUnorm16(static_cast<std::uint16_t>((i * 2741) % 65536)),
                      lut::fromUnorm16(static_cast<std::uint16_t>((i * 911 + 5) % 65536)),
                      lut::fromUnorm16(static_cast<std::uint16_t>((i * 40503 + 1) % 65536)));
    for (const char* ext : {".png", ".tif", ".tiff"}) {
        SCOPED_TRACE(ext);
        const std::string path = dir + "/s16" + ext;
        write(path, lut, "smush", 16);
        EXPECT_EQ(rawRead(path).type, OIIO::TypeDesc::UINT16);
        const lut::LutFile back = read(path, "smush");
        EXPECT_EQ(back.sourceBitDepth, 16);
        EXPECT_EQ(back.cube->entries(), lut.entries());
    }
}

TEST(StripRoundTrip, FloatExrExactIncludingOutOfRange) {
    const std::string dir = tempDir();
    lut::Lut3D lut = lut::Lut3D::identity(8);
    lut.at(1, 2, 3) = glm::vec3(-0.25f, 1.5f, 0.123456789f);
    lut.at(7, 7, 7) = glm::vec3(1e30f, 1.0f / 3.0f, 2.0f);
    const std::string path = dir + "/f.exr";
    const auto diags = write(path, lut, "pilot");
    EXPECT_FALSE(hasMessage(diags, "clamped"));
    EXPECT_EQ(rawRead(path).type, OIIO::TypeDesc::FLOAT);
    const lut::LutFile back = read(path, "pilot");
    EXPECT_EQ(back.sourceBitDepth, 0);
    EXPECT_EQ(back.cube->entries(), lut.entries());
    // EXR cannot hold 8-bit integers: refused rather than silently written as float.
    EXPECT_THROW(write(dir + "/f8.exr", lut, "pilot", 8), lut::Error);
    // PNG cannot hold float.
    EXPECT_THROW(write(dir + "/f.png", lut, "pilot", 32), lut::Error);
}

TEST(StripWrite, RoundsToNearestClampsAndSaysSo) {
    const std::string dir = tempDir();
    lut::Lut3D lut = lut::Lut3D::identity(4);
    lut.at(1, 0, 0) = glm::vec3(0.5f, 100.4f / 255.0f, 100.6f / 255.0f); // 127.5 -> 128, 100, 101
    lut.at(2, 0, 0) = glm::vec3(-1.0f, 7.0f, std::numeric_limits<float>::quiet_NaN());
    const std::string path = dir + "/q.png";
    const auto diags = write(path, lut, "pilot");
    EXPECT_TRUE(hasMessage(diags, "3 channel values outside 0..1 (or NaN) clamped"));
    EXPECT_TRUE(hasMessage(diags, "quantised to 8 bits"));
    const Raw r = rawRead(path);
    EXPECT_EQ(r.at(1, 0, 0), 128.0f);
    EXPECT_EQ(r.at(1, 0, 1), 100.0f);
    EXPECT_EQ(r.at(1, 0, 2), 101.0f);
    EXPECT_EQ(r.at(2, 0, 0), 0.0f);
    EXPECT_EQ(r.at(2, 0, 1), 255.0f);
    EXPECT_EQ(r.at(2, 0, 2), 0.0f);
}

TEST(StripWrite, DitherStaysWithinOneStepAndKeepsExactValues) {
    const std::string dir = tempDir();
    lut::Lut3D lut(16);
    for (std::size_t i = 0; i < lut.entryCount(); ++i) {
        const float v = static_cast<float>(i % 997) / 996.0f;
        lut.entries()[i] = glm::vec3(v, 1.0f - v, 0.5f);
    }
    lut.at(0, 0, 0) = glm::vec3(0.0f, 1.0f, 128 / 255.0f);
    lut::FormatOptions o;
    o.dither = true;
    lut::formats::writeLut(dir + "/d.png", fileOf(lut), o);
    const lut::LutFile back = read(dir + "/d.png", "pilot");
    int differsFromRounding = 0;
    for (std::size_t i = 0; i < lut.entryCount(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float v = lut.entries()[i][c];
            const float got = back.cube->entries()[i][c];
            EXPECT_LE(std::fabs(got - v), 1.0f / 255.0f + 1e-6f);
            differsFromRounding += got != lut::fromUnorm8(lut::toUnorm8(v));
        }
    EXPECT_GT(differsFromRounding, 0) << "dither changed nothing";
    EXPECT_EQ(back.cube->at(0, 0, 0), glm::vec3(0.0f, 1.0f, 128 / 255.0f))
        << "exact steps must survive dither";
}

TEST(StripRead, WrongSizesAreRefusedNamingWhatFits) {
    const std::string dir = tempDir();
    lut::Image img(100, 11, 0.5f);
    lut::formats::writeImage(dir + "/odd.png", img, {});
    try {
        (void)read(dir + "/odd.png");
        FAIL();
    } catch (const lut::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("100x11"), std::string::npos) << m;
        EXPECT_NE(m.find("N^2 x N"), std::string::npos) << m;
    }
    write(dir + "/p.png", lut::Lut3D::identity(16), "pilot");
    try {
        (void)read(dir + "/p.png", "hald");
        FAIL();
    } catch (const lut::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("256x16"), std::string::npos) << m;
        EXPECT_NE(m.find("hald layout needs"), std::string::npos) << m;
        EXPECT_NE(m.find("fits unreal, unity, smush"), std::string::npos) << m;
    }
    EXPECT_THROW(read(dir + "/p.png", "sideways"), lut::Error);
}

TEST(Hald, WritesNextSquareAndReadsBackBySizeAlone) {
    const std::string dir = tempDir();
    // 16 = 4^2: exact, 64x64, detected as hald from its square size.
    write(dir + "/h16.png", graded8(16), "hald");
    lut::LutFile f = read(dir + "/h16.png");
    EXPECT_EQ(f.dialect, "hald");
    EXPECT_EQ(f.format, "hald");
    EXPECT_EQ(f.cube->entries(), graded8(16).entries());
    // 9 = 3^2 through the "hald" format itself (no extension of its own).
    write(dir + "/h9.tif", graded8(9), "", 0, "hald");
    EXPECT_EQ(rawRead(dir + "/h9.tif").w, 27);
    lut::FormatOptions none;
    f = lut::formats::readLut(dir + "/h9.tif", none, "hald");
    EXPECT_EQ(f.cube->entries(), graded8(9).entries());
    // 17 is no square: written as 25^3 (level 5, 125x125) with a diagnostic.
    const auto diags = write(dir + "/h17.png", lut::Lut3D::identity(17), "hald");
    EXPECT_TRUE(hasMessage(diags, "17^3 written as 25^3"));
    const Raw r = rawRead(dir + "/h17.png");
    EXPECT_EQ(r.w, 125);
    EXPECT_EQ(r.h, 125);
    f = read(dir + "/h17.png");
    EXPECT_EQ(f.cube->size(), 25);
    EXPECT_LE(f.cube->maxDeviationFromIdentity(), 0.5f / 255.0f + 1e-6f);
    // The hald format refuses another layout.
    lut::FormatOptions smush;
    smush.layout = lut::parseOptionalLayout("smush");
    EXPECT_THROW(lut::formats::writeLut(dir + "/x.png", fileOf(graded8(4)), smush, "hald"),
                 lut::Error);
}

TEST(StripWrite, ShaperAndDomainAreBakedWithDiagnostics) {
    const std::string dir = tempDir();
    lut::Lut3D lut(5);
    lut.setDomain(glm::vec3(0.0f), glm::vec3(2.0f)); // identity over 0..2: on 0..1 still identity
    for (int b = 0; b < 5; ++b)
        for (int g = 0; g < 5; ++g)
            for (int r = 0; r < 5; ++r)
                lut.at(r, g, b) = lut.latticeInput(r, g, b);
    const auto diags = write(dir + "/d.exr", lut, "pilot");
    EXPECT_TRUE(hasMessage(diags, "re-sampled onto 0..1"));
    const lut::LutFile back = read(dir + "/d.exr", "pilot");
    EXPECT_LE(back.cube->maxDeviationFromIdentity(), 1e-6f);
}
