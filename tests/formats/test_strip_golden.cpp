// SPDX-License-Identifier: Apache-2.0
// Golden LUT images written by tests/data/strip/make_golden.py with its own PNG encoder from the
// layout formulas (not by lutkit): our reader must find each entry where the spec puts it.
#include "lut/formats/Registry.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

using lut::test::dataPath;

namespace {

glm::vec3 gradedExpected(int r, int g, int b, float max) {
    const int m = static_cast<int>(max) + 1;
    return glm::vec3(static_cast<float>((r * 37 + g * 11 + b * 5) % m) / max,
                     static_cast<float>((r * 3 + g * 71 + b * 13) % m) / max,
                     static_cast<float>((r * 7 + g * 17 + b * 101) % m) / max);
}

lut::LutFile read(const std::string& name, const std::string& layout = {},
                  const std::string& format = {}) {
    lut::FormatOptions o;
    o.layout = lut::parseOptionalLayout(layout);
    return lut::formats::readLut(dataPath(name), o, format);
}

} // namespace

TEST(StripGolden, NeutralInEachLayoutAutoDetected) {
    for (const char* layout : {"pilot", "unity", "smush"}) {
        SCOPED_TRACE(layout);
        const lut::LutFile f = read(std::string("strip/neutral4_") + layout + ".png");
        EXPECT_EQ(f.dialect, lut::toString(lut::parseLayout(layout)));
        ASSERT_EQ(f.cube->size(), 4);
        EXPECT_EQ(f.sourceBitDepth, 8);
        for (int b = 0; b < 4; ++b)
            for (int g = 0; g < 4; ++g)
                for (int r = 0; r < 4; ++r)
                    ASSERT_EQ(f.cube->at(r, g, b),
                              glm::vec3(85.0f * r, 85.0f * g, 85.0f * b) / 255.0f);
    }
}

TEST(StripGolden, AlphaIsIgnoredNotPremultiplied) {
    const lut::LutFile f = read("strip/neutral4_pilot_alpha128.png");
    EXPECT_EQ(f.dialect, "unreal"); // the user-facing name of the pilot layout
    EXPECT_EQ(f.cube->at(3, 3, 3), glm::vec3(1.0f));
    EXPECT_EQ(f.cube->at(1, 2, 3), glm::vec3(85.0f, 170.0f, 255.0f) / 255.0f);
}

TEST(StripGolden, GradedRgba8SmushAndSixteenBitUnity) {
    lut::LutFile f = read("strip/graded5_smush_rgba8.png", "smush");
    ASSERT_EQ(f.cube->size(), 5);
    for (int b = 0; b < 5; ++b)
        for (int g = 0; g < 5; ++g)
            for (int r = 0; r < 5; ++r)
                ASSERT_EQ(f.cube->at(r, g, b), gradedExpected(r, g, b, 255.0f));
    f = read("strip/graded3_unity16.png", "unity");
    EXPECT_EQ(f.sourceBitDepth, 16);
    ASSERT_EQ(f.cube->size(), 3);
    for (int b = 0; b < 3; ++b)
        for (int g = 0; g < 3; ++g)
            for (int r = 0; r < 3; ++r) {
                const glm::vec3 e = gradedExpected(r, g, b, 65535.0f);
                ASSERT_EQ(f.cube->at(r, g, b), e) << r << g << b;
            }
}

TEST(HaldGolden, ReadsLevel2And3BySizeAndByFormatName) {
    lut::LutFile f = read("hald/neutral_level2.png");
    EXPECT_EQ(f.dialect, "hald");
    ASSERT_EQ(f.cube->size(), 4);
    for (int b = 0; b < 4; ++b)
        for (int g = 0; g < 4; ++g)
            for (int r = 0; r < 4; ++r)
                ASSERT_EQ(f.cube->at(r, g, b), glm::vec3(85.0f * r, 85.0f * g, 85.0f * b) / 255.0f);
    f = read("hald/graded_level3.png", "", "hald");
    ASSERT_EQ(f.cube->size(), 9);
    for (int b = 0; b < 9; ++b)
        for (int g = 0; g < 9; ++g)
            for (int r = 0; r < 9; ++r)
                ASSERT_EQ(f.cube->at(r, g, b), gradedExpected(r, g, b, 255.0f));
    // A strip is not a Hald image.
    EXPECT_THROW(read("strip/neutral4_pilot.png", "", "hald"), lut::Error);
}
