// SPDX-License-Identifier: Apache-2.0
// Round trips across formats that must be exact (issue 3): the neutral LUT through
// cube -> pilot png -> nutexb -> smush png -> hald -> cube keeps its 8-bit values, and any 8-bit
// LUT goes through nutexb <-> png <-> cube bit-exactly (in every order and layout).
#include "lut/formats/Registry.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <random>

using lut::test::tempDir;

namespace {

lut::LutFile convert(const std::string& in, const std::string& out, const std::string& layout = {},
                     const std::string& inLayout = {}) {
    lut::FormatOptions ro;
    ro.layout = lut::parseOptionalLayout(inLayout);
    const lut::LutFile f = lut::formats::readLut(in, ro);
    lut::FormatOptions wo;
    wo.layout = lut::parseOptionalLayout(layout);
    wo.size = f.cube ? f.cube->size() : 0;
    lut::formats::writeLut(out, f, wo);
    lut::FormatOptions back;
    back.layout = lut::parseOptionalLayout(layout);
    return lut::formats::readLut(out, back);
}

lut::Lut3D random8(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> byte(0, 255);
    lut::Lut3D lut(n);
    for (auto& e : lut.entries())
        e = glm::vec3(static_cast<float>(byte(rng)), static_cast<float>(byte(rng)),
                      static_cast<float>(byte(rng))) /
            255.0f;
    return lut;
}

} // namespace

TEST(RoundTripFormats, NeutralThroughEveryFormatKeepsItsEightBitValues) {
    const std::string d = tempDir();
    lut::LutFile start;
    start.cube = lut::Lut3D::identity(16);
    lut::formats::writeLut(d + "/a.cube", start);
    convert(d + "/a.cube", d + "/b.png", "pilot");
    convert(d + "/b.png", d + "/c.nutexb");
    convert(d + "/c.nutexb", d + "/d.png", "smush");
    convert(d + "/d.png", d + "/e.png", "hald");
    const lut::LutFile end = convert(d + "/e.png", d + "/f.cube", {}, "hald");
    ASSERT_EQ(end.cube->size(), 16);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r)
                ASSERT_EQ(end.cube->at(r, g, b),
                          glm::vec3(17.0f * r, 17.0f * g, 17.0f * b) / 255.0f);
    // And the nutexb in the middle is the reference file.
    const lut::LutFile mid = lut::formats::readLut(d + "/c.nutexb");
    EXPECT_EQ(mid.cube->entries(), end.cube->entries());
}

TEST(RoundTripFormats, AnyEightBitLutIsBitExactThroughNutexbPngCube) {
    const std::string d = tempDir();
    for (int n : {2, 16, 17}) {
        for (const char* layout : {"pilot", "unity", "smush"}) {
            SCOPED_TRACE(std::to_string(n) + " " + layout);
            const lut::Lut3D lut = random8(n, static_cast<unsigned>(n * 31 + layout[0]));
            lut::LutFile f;
            f.cube = lut;
            lut::FormatOptions o;
            o.size = n;
            lut::formats::writeLut(d + "/s.nutexb", f, o);
            // nutexb -> png -> cube -> nutexb -> cube -> png
            EXPECT_EQ(convert(d + "/s.nutexb", d + "/1.png", layout).cube->entries(),
                      lut.entries());
            EXPECT_EQ(convert(d + "/1.png", d + "/2.cube", {}, layout).cube->entries(),
                      lut.entries());
            EXPECT_EQ(convert(d + "/2.cube", d + "/3.nutexb").cube->entries(), lut.entries());
            EXPECT_EQ(convert(d + "/3.nutexb", d + "/4.cube").cube->entries(), lut.entries());
            EXPECT_EQ(convert(d + "/4.cube", d + "/5.png", layout).cube->entries(), lut.entries());
            EXPECT_EQ(convert(d + "/5.png", d + "/6.nutexb", {}, layout).cube->entries(),
                      lut.entries());
        }
    }
}

TEST(RoundTripFormats, SixteenBitAndFloatImagesThroughCubeExact) {
    const std::string d = tempDir();
    lut::Lut3D lut(7);
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> word(0, 65535);
    for (auto& e : lut.entries())
        e = glm::vec3(static_cast<float>(word(rng)), static_cast<float>(word(rng)),
                      static_cast<float>(word(rng))) /
            65535.0f;
    lut::LutFile f;
    f.cube = lut;
    lut::FormatOptions o;
    o.layout = lut::parseOptionalLayout("unity");
    o.bitDepth = 16;
    lut::formats::writeLut(d + "/a.tif", f, o);
    EXPECT_EQ(convert(d + "/a.tif", d + "/b.cube", {}, "unity").cube->entries(), lut.entries());
    lut::LutFile c = lut::formats::readLut(d + "/b.cube");
    o.bitDepth = 32;
    lut::formats::writeLut(d + "/c.exr", c, o);
    lut::FormatOptions ro;
    ro.layout = lut::parseOptionalLayout("unity");
    EXPECT_EQ(lut::formats::readLut(d + "/c.exr", ro).cube->entries(), lut.entries());
}
