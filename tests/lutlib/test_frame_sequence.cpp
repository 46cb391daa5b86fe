// SPDX-License-Identifier: Apache-2.0
// Frame sequence names and ranges as oiiotool and ffmpeg spell them (lut/io/FrameSequence.h).
#include "TestSupport.h"

#include "lut/Error.h"
#include "lut/io/FrameSequence.h"

#include <gtest/gtest.h>

#include <fstream>

using namespace lut;

TEST(FrameSequence, Placeholders) {
    struct Case {
        const char* path;
        const char* prefix;
        const char* suffix;
        int padding;
        const char* frame7;
    };
    const Case cases[] = {
        {"f.%04d.exr", "f.", ".exr", 4, "f.0007.exr"},
        {"f.%d.exr", "f.", ".exr", 0, "f.7.exr"},
        {"f.%6d.exr", "f.", ".exr", 0, "f.7.exr"},
        {"f.#.exr", "f.", ".exr", 4, "f.0007.exr"},
        {"f.####.exr", "f.", ".exr", 4, "f.0007.exr"},
        {"f.##.exr", "f.", ".exr", 2, "f.07.exr"},
        {"f.@@@.exr", "f.", ".exr", 3, "f.007.exr"},
        {"f.#@@.exr", "f.", ".exr", 6, "f.000007.exr"},
        {"d/shot_%03d.png", "d/shot_", ".png", 3, "d/shot_007.png"},
    };
    for (const auto& c : cases) {
        const auto p = parseFramePattern(c.path);
        ASSERT_TRUE(p) << c.path;
        EXPECT_EQ(p->prefix, c.prefix) << c.path;
        EXPECT_EQ(p->suffix, c.suffix) << c.path;
        EXPECT_EQ(p->padding, c.padding) << c.path;
        EXPECT_EQ(p->path(7), c.frame7) << c.path;
    }
    EXPECT_FALSE(parseFramePattern("plain.exr"));
    EXPECT_FALSE(parseFramePattern("100%.png"));        // % not followed by d
    EXPECT_FALSE(parseFramePattern("dir#1/plain.exr")); // only the file name counts
    EXPECT_THROW(parseFramePattern("a.%04d.#.exr"), Error);
    EXPECT_EQ(parseFramePattern("f.%04d.exr")->path(12345), "f.12345.exr");
}

TEST(FrameSequence, AnExistingFileIsAFileNotAPattern) {
    const std::string dir = lut::test::tempDir();
    const std::string odd = dir + "/take#1.png";
    std::ofstream(odd) << "x";
    EXPECT_FALSE(parseFramePattern(odd));
    EXPECT_TRUE(parseFramePattern(dir + "/take#2.png"));
}

TEST(FrameSequence, MatchingNames) {
    const FramePattern p = *parseFramePattern("f.%04d.exr");
    EXPECT_EQ(p.frameOf("f.0012.exr"), 12);
    EXPECT_EQ(p.frameOf("f.12345.exr"), 12345);
    EXPECT_FALSE(p.frameOf("f.012.exr"));   // 3 digits where 4 are padded
    EXPECT_FALSE(p.frameOf("f.00012.exr")); // 5 digits with a leading zero
    EXPECT_FALSE(p.frameOf("f.00a2.exr"));
    EXPECT_FALSE(p.frameOf("g.0012.exr"));
    EXPECT_FALSE(p.frameOf("f..exr"));
    const FramePattern any = *parseFramePattern("f.%d.exr");
    EXPECT_EQ(any.frameOf("f.7.exr"), 7);
    EXPECT_EQ(any.frameOf("f.0007.exr"), 7);
}

TEST(FrameSequence, RangesAsOiiotoolTakesThem) {
    using V = std::vector<long>;
    EXPECT_EQ(parseFrameRange("1-5"), (V{1, 2, 3, 4, 5}));
    EXPECT_EQ(parseFrameRange("5-1"), (V{5, 4, 3, 2, 1}));
    EXPECT_EQ(parseFrameRange("1-5x2"), (V{1, 3, 5}));
    EXPECT_EQ(parseFrameRange("1-5y2"), (V{2, 4}));
    EXPECT_EQ(parseFrameRange("3,4,10-20x5"), (V{3, 4, 10, 15, 20}));
    EXPECT_EQ(parseFrameRange("7"), (V{7}));
    for (const char* bad : {"", "a", "1-", "1-5x0", "1-5x", "1,,2", "1-5z2", "-3", "1 - 5"})
        EXPECT_THROW(parseFrameRange(bad), Error) << bad;
    EXPECT_THROW(parseFrameRange("1-999999999"), Error);
}

TEST(FrameSequence, FindsFramesAndNamesTheGaps) {
    const std::string dir = lut::test::tempDir();
    for (int f : {1, 2, 3, 5, 9, 10})
        std::ofstream(dir + "/s." + std::string(f < 10 ? "000" : "00") + std::to_string(f) + ".png")
            << "x";
    std::ofstream(dir + "/s.01.png") << "x";       // wrong padding: not a frame
    std::ofstream(dir + "/other.0004.png") << "x"; // another sequence
    const auto frames = findFrames(*parseFramePattern(dir + "/s.####.png"));
    EXPECT_EQ(frames, (std::vector<long>{1, 2, 3, 5, 9, 10}));
    EXPECT_EQ(missingFrames(frames), "4, 6-8");
    EXPECT_EQ(describeFrames(frames), "1-3, 5, 9-10");
    EXPECT_EQ(missingFrames({1, 2, 3}), "");
}
