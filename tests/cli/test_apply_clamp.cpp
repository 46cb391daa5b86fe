// SPDX-License-Identifier: Apache-2.0
// lutkit apply into an integer output: LUT outputs outside [0,1] that the 8/16-bit output clamps
// are counted and warned about, never clamped silently. The LUT is an affine map (a 2^3 .cube
// every interpolation reproduces exactly), so the count is computed here from the map itself:
// the pixels where a channel leaves [0,1] by more than half a step of the output.
#include "TestSupport.h"

#include "lut/Image.h"
#include "lut/formats/ImageIO.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace lut;
using namespace lut::test;
using ::testing::HasSubstr;

namespace {

using lut::test::shellQuoted;

// out = 1.3 x - 0.1 per channel: below 0 under x = 1/13, above 1 over x = 11/13.
double affine(double x) {
    return 1.3 * x - 0.1;
}

} // namespace

TEST(ApplyClamp, IntegerOutputsCountWhatTheyClamp) {
    const std::string dir = tempDir() + "-clamp";
    fs::remove_all(dir);
    fs::create_directories(dir);
    {
        std::ofstream f(dir + "/stretch.cube");
        f << "LUT_3D_SIZE 2\n";
        for (int b = 0; b < 2; ++b)
            for (int g = 0; g < 2; ++g)
                for (int r = 0; r < 2; ++r)
                    f << affine(r) << " " << affine(g) << " " << affine(b) << "\n";
    }
    // 256 x 4: red runs over every 8-bit code, green and blue stay mid-grey.
    Image img(256, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 256; ++x) {
            float* p = img.pixel(x, y);
            p[0] = x / 255.0f;
            p[1] = p[2] = 0.5f;
            p[3] = 1.0f;
        }
    formats::writeImage(dir + "/in.png", img, formats::ImageWriteOptions(8, false, false));
    int expected = 0;
    for (int x = 0; x < 256; ++x) {
        const double v = affine(x / 255.0);
        expected += (v < -0.5 / 255 || v > 1 + 0.5 / 255) ? 4 : 0;
    }
    RunResult r = runCli("apply --lut " + shellQuoted(dir + "/stretch.cube") + " " +
                         shellQuoted(dir + "/in.png") + " -o " + shellQuoted(dir + "/out.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr(std::to_string(expected) + " of 1024 pixels"));
    EXPECT_THAT(r.err, HasSubstr("clamped by the 8-bit output"));
    // A float output keeps them: no warning.
    r = runCli("apply --lut " + shellQuoted(dir + "/stretch.cube") + " " +
               shellQuoted(dir + "/in.png") + " -o " + shellQuoted(dir + "/out.exr") +
               " --bit-depth 32");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("clamped"), std::string::npos) << r.err;
    // 16-bit: half a 16-bit step.
    int expected16 = 0;
    for (int x = 0; x < 256; ++x) {
        const double v = affine(x / 255.0);
        expected16 += (v < -0.5 / 65535 || v > 1 + 0.5 / 65535) ? 4 : 0;
    }
    r = runCli("apply --lut " + shellQuoted(dir + "/stretch.cube") + " " +
               shellQuoted(dir + "/in.png") + " -o " + shellQuoted(dir + "/out16.png") +
               " --bit-depth 16");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr(std::to_string(expected16) + " of 1024 pixels"));
    EXPECT_THAT(r.err, HasSubstr("clamped by the 16-bit output"));
}
