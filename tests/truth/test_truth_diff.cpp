// SPDX-License-Identifier: Apache-2.0
// The truth harness, diff: the printed 8-bit maximum of |A - B| against A and B read and applied
// by OpenColorIO on random inputs in [0,1] (a fifth of them in [0, 1/16]) the diff never saw.
#include "TruthHarness.h"

#include <gtest/gtest.h>

using namespace lut::truth;

namespace {

double printedMax(const std::string& json) {
    const auto k = json.find("\"max_8bit_steps\": [");
    if (k == std::string::npos)
        return NAN;
    const char* p = json.c_str() + k + 19;
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        char* end = nullptr;
        worst = std::max(worst, std::strtod(p, &end));
        p = end + 1;
    }
    return worst / 255.0;
}

} // namespace

// Issue 40's fault in every command that works on one lattice (diff, compose, mix, resize,
// smooth, adjust): a shaper + table was taken as one table over the shaper's 0..64, so `diff` of
// the log2 shaper file and a display grade compared colours nearly all above 1 (printed max 239
// 8-bit steps; OpenColorIO's difference over 0..1 is 113.5). Now over 0..1, said so.
TEST(Truth, DiffOfAShaperCubeComparesTheDisplayRange) {
    const std::string dir = workDir("diff");
    const std::string a = writeShapedCube(dir + "/shaped.cube");
    const std::string b = writeCube(dir + "/grade.cube", 17, [](glm::dvec3 p) {
        return glm::dvec3(std::pow(p.r, 0.8), std::pow(p.g, 0.9), std::pow(p.b, 1.2));
    });
    const std::vector<float> x = randomUnitInputs(100000, 50);
    std::vector<float> fa = x, fb = x;
    ocioApply(a, fa);
    ocioApply(b, fb);
    const Truth t = compare(fa, fb);
    for (const auto& [first, second] : {std::pair{a, b}, std::pair{b, a}}) {
        const auto r =
            lut::test::runCli("diff " + shellQuoted(first) + " " + shellQuoted(second) + " --json");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const double printed = printedMax(r.out);
        row(std::string("diff ") + (first == a ? "shaper + 33^3 vs" : "17^3 vs shaper +") +
                " a grade, 8-bit max",
            t.max, printed, t.mean);
        EXPECT_NE(r.err.find("over 0..1, where display pictures live"), std::string::npos) << r.err;
        EXPECT_GE(printed + kOracleRounding, t.max) << r.out;
        EXPECT_LE(printed, t.max + 2.0 / 255.0) << r.out; // over 0..1, not over 0..64
    }
}
