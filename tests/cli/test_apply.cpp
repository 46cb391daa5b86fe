// SPDX-License-Identifier: Apache-2.0
// lutkit apply: stored values through the LUT, alpha and bit depth kept, rounding to nearest;
// batch with -o DIR keeps going past bad files.
#include "CliTestSupport.h"

#include "lut/Quantize.h"
#include "lut/formats/ImageIO.h"

#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace lut;
using namespace lut::test;

namespace {

// An affine map as a 2^3 .cube: every interpolation reproduces it exactly, so the reference is
// the map itself.
glm::vec3 affine(glm::vec3 v) {
    return {0.21f + 0.4837f * v.r, 1.0f - 0.9123f * v.g, 0.2519f * v.b + 0.4711f * v.r};
}

// The 8-bit code the output must hold, or -1 where float and double may round apart (within
// 1e-3 of a half step).
int expected8(float v) {
    const double s = static_cast<double>(v) * 255.0;
    if (std::fabs(s - std::floor(s) - 0.5) < 1e-3)
        return -1;
    return toUnorm8(v);
}

std::string writeAffineCube(const std::string& dir) {
    const std::string path = dir + "/affine.cube";
    std::ofstream f(path);
    f.precision(9);
    f << "LUT_3D_SIZE 2\n";
    for (int b = 0; b < 2; ++b)
        for (int g = 0; g < 2; ++g)
            for (int r = 0; r < 2; ++r) {
                const glm::vec3 o = affine(glm::vec3(r, g, b));
                f << o.r << " " << o.g << " " << o.b << "\n";
            }
    return path;
}

Image testImage(int w, int h, int bits, bool fractionalAlpha = false) {
    Image img(w, h);
    const double maxv = bits == 8 ? 255.0 : 65535.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img.pixel(x, y);
            p[0] = static_cast<float>(std::round((x * 37 + y * 11) % 256 / 255.0 * maxv) / maxv);
            p[1] = static_cast<float>(std::round((x * 5 + y * 91) % 256 / 255.0 * maxv) / maxv);
            p[2] =
                static_cast<float>(std::round((x * 73 + y * 29 + 7) % 256 / 255.0 * maxv) / maxv);
            p[3] = fractionalAlpha
                       ? static_cast<float>(std::round(((x + y) % 4) / 3.0 * maxv) / maxv)
                       : 1.0f;
        }
    return img;
}

} // namespace

TEST(CliApply, EightBitValuesThroughTheLutAlphaKept) {
    const std::string dir = workDir();
    const std::string cube = writeAffineCube(dir);
    const Image in = testImage(13, 7, 8);
    formats::writeImage(dir + "/in.png", in, {8, false, true});
    for (const char* interp : {"trilinear", "tetrahedral"}) {
        const RunResult r = runCli("apply --lut '" + cube + "' '" + dir + "/in.png' -o '" + dir +
                                   "/out.png' -y --interp " + interp);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const formats::LoadedImage out = formats::readImage(dir + "/out.png");
        EXPECT_EQ(out.info.bitDepth, 8);
        EXPECT_EQ(out.info.channels, 4);
        for (int y = 0; y < 7; ++y)
            for (int x = 0; x < 13; ++x) {
                const float* p = in.pixel(x, y);
                const glm::vec3 want = affine(glm::vec3(p[0], p[1], p[2]));
                for (int c = 0; c < 3; ++c)
                    if (expected8(want[c]) >= 0) {
                        EXPECT_EQ(toUnorm8(out.image.pixel(x, y)[c]), expected8(want[c]))
                            << x << "," << y << " c" << c;
                    }
                EXPECT_EQ(out.image.pixel(x, y)[3], p[3]);
            }
    }
}

// Colour of pixels with alpha below 1 must not be scaled (no premultiplication on read or write).
TEST(CliApply, FractionalAlphaKeepsColourAndAlpha) {
    const std::string dir = workDir();
    const std::string cube = writeAffineCube(dir);
    const Image in = testImage(8, 4, 8, true);
    formats::writeImage(dir + "/ina.png", in, {8, false, true});
    const RunResult r =
        runCli("apply --lut '" + cube + "' '" + dir + "/ina.png' -o '" + dir + "/outa.png'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const formats::LoadedImage out = formats::readImage(dir + "/outa.png");
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            const float* p = in.pixel(x, y);
            const glm::vec3 want = affine(glm::vec3(p[0], p[1], p[2]));
            EXPECT_EQ(out.image.pixel(x, y)[3], p[3]);
            for (int c = 0; c < 3; ++c)
                if (expected8(want[c]) >= 0) {
                    EXPECT_EQ(toUnorm8(out.image.pixel(x, y)[c]), expected8(want[c]))
                        << x << "," << y << " a=" << p[3];
                }
        }
}

TEST(CliApply, SixteenBitStaysSixteenBit) {
    const std::string dir = workDir();
    const std::string cube = writeAffineCube(dir);
    const Image in = testImage(9, 5, 16);
    formats::writeImage(dir + "/in16.png", in, {16, false, true});
    const RunResult r =
        runCli("apply --lut '" + cube + "' '" + dir + "/in16.png' -o '" + dir + "/out16.png'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const formats::LoadedImage out = formats::readImage(dir + "/out16.png");
    EXPECT_EQ(out.info.bitDepth, 16);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 9; ++x) {
            const float* p = in.pixel(x, y);
            const glm::vec3 want = affine(glm::vec3(p[0], p[1], p[2]));
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(out.image.pixel(x, y)[c], want[c], 0.5 / 65535.0 + 1e-6);
        }
}

TEST(CliApply, BatchKeepsGoingAndReportsEveryFailure) {
    const std::string dir = workDir();
    const std::string cube = writeAffineCube(dir);
    std::filesystem::create_directories(dir + "/in");
    formats::writeImage(dir + "/in/a.png", testImage(4, 4, 8), {8, false, true});
    formats::writeImage(dir + "/in/b.png", testImage(5, 3, 8), {8, false, false});
    { std::ofstream(dir + "/in/broken.png") << "not a png"; }
    const RunResult r = runCli("apply --lut '" + cube + "' '" + dir + "/in' '" + dir +
                               "/missing.png' -o '" + dir + "/out/'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("broken.png"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("missing.png"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("2 of 4"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("\r"), std::string::npos); // no progress bar when not a terminal
    const formats::LoadedImage a = formats::readImage(dir + "/out/a.png");
    const formats::LoadedImage b = formats::readImage(dir + "/out/b.png");
    EXPECT_EQ(b.info.channels, 3);
    const glm::vec3 want =
        affine(glm::vec3(testImage(4, 4, 8).pixel(2, 1)[0], testImage(4, 4, 8).pixel(2, 1)[1],
                         testImage(4, 4, 8).pixel(2, 1)[2]));
    EXPECT_NEAR(a.image.pixel(2, 1)[1], want.g, 0.5 / 255 + 1e-6);
}

TEST(CliApply, UsageErrors) {
    const std::string dir = workDir();
    const std::string cube = writeAffineCube(dir);
    EXPECT_EQ(runCli("apply --lut '" + cube + "' onlyone.png").exitCode, 2);
    EXPECT_EQ(runCli("apply --lut '" + cube + "' a.png b.png c.png").exitCode, 2);
    EXPECT_EQ(runCli("apply --lut '" + cube + "' a.png b.png -o out.png").exitCode, 2);
    const RunResult r = runCli("apply --lut '" + dir + "/nope.cube' a.png -o b.png");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("nope.cube"), std::string::npos);
}
