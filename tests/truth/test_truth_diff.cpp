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

// The same rule in compose: A, a shaper file, taken as one table over 0..1 (the note's maximum,
// in A's output) then B after it. The printed figures (the note's and compose's own) against
// OpenColorIO's B(A(x)) and the written file, B's slope times the note's maximum allowed for.
TEST(Truth, ComposeOfAShaperCubeBoundsBAfterA) {
    const std::string dir = workDir("compose-shaper");
    const std::string a = writeShapedCube(dir + "/shaped.cube");
    const std::string b = writeCube(dir + "/grade.cube", 17, [](glm::dvec3 p) {
        return glm::dvec3(0.9 * p.r + 0.1 * p.g, 0.95 * p.g + 0.05 * p.b, 0.8 * p.b + 0.2 * p.r);
    });
    const std::string out = dir + "/ab.cube";
    const auto r = lut::test::runCli("compose " + shellQuoted(a) + " " + shellQuoted(b) + " " +
                                     shellQuoted(out) + " -y");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto noteAt = r.err.find("taken as one 33^3 table over 0..1");
    ASSERT_NE(noteAt, std::string::npos) << r.err;
    const double note = std::strtod(r.err.c_str() + r.err.find("max ", noteAt) + 4, nullptr);
    const auto opAt = r.out.find("against B(A(x)): max ");
    ASSERT_NE(opAt, std::string::npos) << r.out;
    const double op = std::strtod(r.out.c_str() + opAt + 21, nullptr);
    const std::vector<float> x = randomUnitInputs(100000, 51);
    std::vector<float> want = x, got = x;
    ocioApply(a, want);
    ocioApply(b, want);
    ocioApply(out, got);
    const Truth t = compare(want, got);
    // B is a matrix with rows summing to 1 (its entries' largest row sum of |m|): slope 1.
    const double printed = op + 1.0 * note;
    row("compose shaper + 33^3 then a matrix 17^3 -> .cube", t.max, printed, t.mean);
    EXPECT_GE(printed + kOracleRounding, t.max) << r.out << r.err;
}
