// SPDX-License-Identifier: Apache-2.0
// lut/formats/ImageFiles.h: the one policy for what a rendered image is written as, shared by
// `lutkit apply`/`preview` and the editor's "save preview" (they used to decide apart and drift:
// an RGBA input saved as .jpg got 4 channels from the editor and 3 from the CLI).
#include "lut/formats/ImageFiles.h"

#include <gtest/gtest.h>

using namespace lut::formats;

namespace {
ImageInfo info(int channels, int bitDepth, bool isFloat) {
    ImageInfo i;
    i.width = i.height = 4;
    i.channels = channels;
    i.bitDepth = bitDepth;
    i.isFloat = isFloat;
    return i;
}
} // namespace

TEST(ImageFiles, ExtensionsAreImagesInAnyCase) {
    EXPECT_TRUE(isImageExtension("a/b.PNG"));
    EXPECT_TRUE(isImageExtension("x.tiff"));
    EXPECT_TRUE(isImageExtension("x.Exr"));
    EXPECT_FALSE(isImageExtension("x.cube"));
    EXPECT_FALSE(isImageExtension("x.nutexb"));
    EXPECT_FALSE(isImageExtension("png"));
}

TEST(ImageFiles, AlphaOnlyWhereTheFormatHoldsIt) {
    for (const char* p : {"o.jpg", "o.JPEG", "o.bmp", "o.hdr", "o.gif"}) {
        EXPECT_FALSE(canHoldAlpha(p)) << p;
        EXPECT_FALSE(renderedImageWriteOptions(info(4, 8, false), p).alpha) << p;
    }
    for (const char* p : {"o.png", "o.tif", "o.exr", "o.tga"}) {
        EXPECT_TRUE(canHoldAlpha(p)) << p;
        EXPECT_TRUE(renderedImageWriteOptions(info(4, 8, false), p).alpha) << p;
        EXPECT_TRUE(renderedImageWriteOptions(info(2, 8, false), p).alpha) << p;
        EXPECT_FALSE(renderedImageWriteOptions(info(3, 8, false), p).alpha) << p;
    }
}

TEST(ImageFiles, BitDepthFollowsTheInputThenTheFormat) {
    EXPECT_EQ(renderedImageWriteOptions(info(3, 16, false), "o.png").bitDepth, 16);
    EXPECT_EQ(renderedImageWriteOptions(info(3, 16, false), "o.jpg").bitDepth, 8);
    EXPECT_EQ(renderedImageWriteOptions(info(3, 8, false), "o.exr").bitDepth, 8);
    EXPECT_EQ(renderedImageWriteOptions(info(4, 32, true), "o.exr").bitDepth, 32);
    EXPECT_EQ(renderedImageWriteOptions(info(4, 32, true), "o.png").bitDepth, 16);
    EXPECT_EQ(renderedImageWriteOptions(info(4, 32, true), "o.jpg").bitDepth, 8);
    EXPECT_EQ(renderedImageWriteOptions(info(4, 8, false), "o.png", 16).bitDepth, 16);
}
