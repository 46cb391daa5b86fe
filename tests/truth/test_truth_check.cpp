// SPDX-License-Identifier: Apache-2.0
// The truth harness, check: a file's slope is what OpenColorIO applies, the shaper then the table.
#include "TruthHarness.h"

#include <gtest/gtest.h>

using namespace lut::truth;

// Issue 40: `check` of the shaper .cube `invert` writes for x^2.2 failed "steep 64 steps per input
// step in the shaper": the shaper's output is a place in the table, not a colour. The file's own
// slope, measured by OpenColorIO (the steepest change over one input 8-bit step of the composite
// along red, sliding windows 1/4080 apart), is the truth the check's figure must follow: never
// above it, within a quarter of it, and graded by it (fail at 16).
TEST(Truth, CheckJudgesAShaperCubeAsOpenColorIOAppliesIt) {
    const std::string dir = workDir("check-shaper");
    const std::string src = writeCube(dir + "/pow.cube", 33, [](glm::dvec3 p) {
        return glm::dvec3(std::pow(p.r, 2.2), std::pow(p.g, 2.2), std::pow(p.b, 2.2));
    });
    const std::string inv = dir + "/inv.cube";
    ASSERT_EQ(
        lut::test::runCli("invert " + shellQuoted(src) + " " + shellQuoted(inv) + " -y").exitCode,
        0);
    ASSERT_NE(lut::test::fileBytes(inv).find("LUT_1D_SIZE"), std::string::npos);
    const auto r = lut::test::runCli("check " + shellQuoted(inv) + " --json");
    const double steepest = jsonNumber(r.out, "steepest");
    ASSERT_FALSE(std::isnan(steepest)) << r.out;
    EXPECT_EQ(r.out.find("in the shaper"), std::string::npos) << r.out;

    constexpr int kSub = 16, kSamples = 255 * kSub + 1;
    double truth = 0.0;
    for (const double gb : {0.0, 0.5, 1.0}) {
        std::vector<float> x;
        for (int i = 0; i < kSamples; ++i)
            for (const double v : {double(i) / (kSamples - 1), gb, gb})
                x.push_back(static_cast<float>(v));
        ocioApply(inv, x);
        for (int i = 0; i + kSub < kSamples; ++i)
            truth = std::max(truth, 255.0 * std::fabs(double(x[3 * (i + kSub)]) - x[3 * i]));
    }
    std::printf("[ truth    ] check of invert's shaper .cube: steepest %.2f, OpenColorIO's %.2f "
                "output steps per input step\n",
                steepest, truth);
    EXPECT_LE(steepest, truth * 1.01);
    EXPECT_GE(steepest, truth * 0.75);
    const bool fails =
        r.out.find("\"check\": \"banding\", \"status\": \"fail\"") != std::string::npos;
    EXPECT_EQ(fails, truth >= 16.0) << r.out;
}
