// SPDX-License-Identifier: Apache-2.0
// builtin:neutral and builtin:smash-default wherever a LUT file goes: convert writes the game's
// default stage LUT as it is (it is the game's LUT), and a screenshot of a stage without its own
// LUT previews closer to the game with --original-lut builtin:smash-default than with the neutral
// default -- the game's pictures made here with the float64 reference chain of
// docs/specs/smash-pipeline.md (tests/support/PipelineTestUtil.h).
#include "CliTestSupport.h"
#include "PipelineTestUtil.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace lut;
using namespace lut::test;

namespace {

const int kDefault[16] = {0, 15, 30, 46, 64, 82, 101, 121, 140, 158, 176, 193, 209, 224, 240, 255};

Lut3D smashDefault() {
    Lut3D l(16);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r)
                l.at(r, g, b) = glm::vec3(kDefault[r], kDefault[g], kDefault[b]) / 255.0f;
    return l;
}

// What the game shows of a linear scene with a stage LUT (no bloom: the scene has no light
// above the bloom threshold), 8-bit display codes.
Image gamePicture(const Image& scene, const Lut3D& lut) {
    Image out(scene.width(), scene.height());
    for (int y = 0; y < scene.height(); ++y)
        for (int x = 0; x < scene.width(); ++x) {
            double in[3], o[3];
            for (int c = 0; c < 3; ++c)
                in[c] = scene.pixel(x, y)[c];
            refSmashGrade(lut, in, 1.0, o);
            for (int c = 0; c < 3; ++c)
                out.pixel(x, y)[c] = static_cast<float>(
                    std::lround(std::clamp(refSrgbEncode(o[c]), 0.0, 1.0) * 255.0) / 255.0);
            out.pixel(x, y)[3] = 1.0f;
        }
    return out;
}

struct Steps {
    double max = 0, mean = 0;
};
Steps stepsApart(const Image& a, const Image& b) {
    Steps s;
    std::size_t n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                const double d = std::fabs(a.pixel(x, y)[c] - b.pixel(x, y)[c]) * 255.0;
                s.max = std::max(s.max, d);
                s.mean += d;
                ++n;
            }
    s.mean /= static_cast<double>(n);
    return s;
}

} // namespace

TEST(CliBuiltin, ConvertWritesTheGamesDefaultLutAsItIs) {
    const std::string dir = workDir();
    RunResult r = runCli("convert builtin:smash-default '" + dir + "/d.nutexb'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find("target   smash"), std::string::npos) << r.out; // not compensated
    // What it is for, and why: its name, not a file (it said "the file says so").
    EXPECT_NE(r.out.find("in:  smash (a built-in game LUT)"), std::string::npos) << r.out;
    const Lut3D back = formats::readLut(dir + "/d.nutexb").toLut3D();
    const Lut3D want = smashDefault();
    ASSERT_EQ(back.size(), 16);
    EXPECT_EQ(back.entries(), want.entries());
    r = runCli("convert builtin:neutral '" + dir + "/n.cube'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(formats::readLut(dir + "/n.cube").cube->isIdentity(0.0f));
    r = runCli("convert builtin:smash-defualt '" + dir + "/x.cube'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("unknown built-in LUT"), std::string::npos) << r.err;
}

TEST(CliBuiltin, AScreenshotOfAStageWithoutItsOwnLutPreviewsCloserWithTheDefault) {
    const std::string dir = workDir();
    // A scene below the bloom threshold and below what the brighten step clips.
    Image scene(48, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 48; ++x) {
            float* p = scene.pixel(x, y);
            p[0] = static_cast<float>(0.45 * x / 47.0);
            p[1] = static_cast<float>(0.45 * y / 31.0);
            p[2] = static_cast<float>(0.45 * ((x * 7 + y * 13) % 48) / 47.0);
            p[3] = 1.0f;
        }
    const Image shot = gamePicture(scene, smashDefault()); // the stage as the game shows it
    const Lut3D mine = makeWarmLut(16);                    // the modder's new stage LUT
    const Image truth = gamePicture(scene, mine);          // what the game will show with it
    formats::writeImage(dir + "/shot.png", shot, {8, false, false});
    {
        std::ofstream f(dir + "/mine.cube");
        f.precision(9);
        f << "LUT_3D_SIZE 16\n";
        for (const auto& e : mine.entries())
            f << e.r << " " << e.g << " " << e.b << "\n";
    }
    // mine.cube is a game LUT (--lut-target smash): the game's chain uses it as it is.
    const std::string base =
        "preview '" + dir + "/shot.png' --lut-target smash --lut '" + dir + "/mine.cube' -o '";
    ASSERT_EQ(runCli(base + dir + "/neutral.png'").exitCode, 0);
    const RunResult r = runCli(base + dir + "/default.png' --original-lut builtin:smash-default");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Steps withNeutral = stepsApart(formats::readImage(dir + "/neutral.png").image, truth);
    const Steps withDefault = stepsApart(formats::readImage(dir + "/default.png").image, truth);
    std::printf("[ measured ] preview against the game: --original-lut neutral (the default) max "
                "%.1f mean %.2f 8-bit steps; builtin:smash-default max %.1f mean %.2f\n",
                withNeutral.max, withNeutral.mean, withDefault.max, withDefault.mean);
    EXPECT_LT(withDefault.mean, 0.5 * withNeutral.mean);
    EXPECT_LT(withDefault.max, withNeutral.max);
    EXPECT_LE(withDefault.max, 3.0);
}
