// SPDX-License-Identifier: Apache-2.0
// Issue 42: a dip along grey in auto's LUT is repaired on the table, not a reason to fall back to
// a method further from the reference. The sample scene is graded by ffmpeg (curves, then a
// saturation matrix: the commonest look, and one whose HM-MKL-HM goes down along grey), the
// graded pixels flipped so no correspondence is left; the written .cube is evaluated along grey
// by OpenColorIO's processor (the oracle), and every channel must go up, checked in float64 here.
#include "CliTestSupport.h"
#include "OcioTestUtil.h"
#include "TestPaths.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using namespace lut::test;
using ::testing::HasSubstr;

TEST(CliMatchRepair, AutoRepairsADipAlongGreyAndSaysSo) {
    if (!haveProgram("ffmpeg"))
        GTEST_SKIP() << "ffmpeg is not installed";
    const std::string d = workDir();
    const std::string src = samplePath("sample_scene.png"), ref = d + "/reference.png",
                      cube = d + "/auto.cube";
    const auto g = runCommand(
        "ffmpeg -v error -nostdin -y -i " + shellQuoted(src) +
        " -vf \"curves=r='0/0.04 0.5/0.56 1/0.97':b='0/0.08 0.5/0.46 1/0.9',"
        "colorchannelmixer=rr=1.3:rg=-0.15:rb=-0.15:gr=-0.15:gg=1.3:gb=-0.15:br=-0.15:bg=-0.15:"
        "bb=1.3,vflip,hflip\" -pix_fmt rgb24 -frames:v 1 " +
        shellQuoted(ref));
    ASSERT_EQ(g.exitCode, 0) << g.err;
    const auto r =
        runCli("match -y " + shellQuoted(src) + " " + shellQuoted(ref) + " " + shellQuoted(cube));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // The floor, kept: no fallback to hm or mkl for its shape.
    EXPECT_THAT(r.out, HasSubstr("method   hm-mkl-hm")) << r.out;
    // The report says what was repaired and by how much.
    EXPECT_THAT(r.out, HasSubstr("repaired the dip along grey (down by ")) << r.out;
    EXPECT_THAT(r.out, HasSubstr("of the table's grey nodes moved, by up to ")) << r.out;
    EXPECT_THAT(r.out, HasSubstr("monotone along grey;")) << r.out;

    // Grey through the written file, 1021 levels: no channel goes down by more than float
    // round-off (1e-6 of the range).
    const auto p = ocioFileProcessor(cube);
    double worst = 0.0, prev[3] = {-1e9, -1e9, -1e9};
    for (int i = 0; i <= 1020; ++i) {
        const float x = static_cast<float>(i) / 1020.0f;
        const glm::vec3 y = ocioEval(p, glm::vec3(x));
        for (int c = 0; c < 3; ++c) {
            const double v = static_cast<double>(y[c]);
            worst = std::max(worst, prev[c] - v);
            prev[c] = std::max(prev[c], v);
        }
    }
    EXPECT_LE(worst * 255.0, 1e-3)
        << "the LUT goes down along grey by " << worst * 255.0 << " 8-bit steps";
}
