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

namespace {

std::string randomTable(const std::string& path, int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<glm::dvec3> v(static_cast<std::size_t>(n) * n * n);
    for (auto& e : v)
        e = glm::dvec3(u(rng), u(rng), u(rng));
    return writeCube(path, n, [&](glm::dvec3 p) {
        const auto i = [&](double t) { return static_cast<std::size_t>(std::lround(t * (n - 1))); };
        return v[(i(p.b) * n + i(p.g)) * n + i(p.r)];
    });
}

// The largest |A - B| per channel over the inputs, as OpenColorIO applies each file.
glm::dvec3 channelMax(const std::vector<float>& a, const std::vector<float>& b) {
    glm::dvec3 m(0.0);
    for (std::size_t i = 0; i < a.size(); ++i)
        m[i % 3] = std::max(m[i % 3], std::fabs(double(a[i]) - double(b[i])));
    return m;
}

double jsonChannel(const std::string& json, int c) {
    const char* p = json.c_str() + json.find("\"max_8bit_steps\": [") + 19;
    double v = 0.0;
    for (int k = 0; k <= c; ++k) {
        char* end = nullptr;
        v = std::strtod(p, &end);
        p = end + 1;
    }
    return v / 255.0;
}

} // namespace

// diff's 8-bit maximum over a lattice. Two tables of one lattice: between the points both blend
// their entries with the same weights, so the maximum at the entries is the maximum over every
// input (said so), per channel. Two lattices of other sizes: the maximum at the compared points
// is a sample (a 9^3 entry between the 13^3 points: OpenColorIO shows more there), so diff also
// prints a bound over every input. Truth: OpenColorIO applying both files (tetrahedral) on random
// inputs in [0,1].
TEST(Truth, DiffMaximumOverALatticeIsExactOnOneLatticeAndBoundedAcrossTwo) {
    const std::string dir = workDir("diff-lattice");
    const std::string a = randomTable(dir + "/a9.cube", 9, 1),
                      b = randomTable(dir + "/b9.cube", 9, 2),
                      c = writeCube(dir + "/c13.cube", 13, [](glm::dvec3 p) { return p; });
    const std::vector<float> x = randomUnitInputs(100000, 53);
    std::vector<float> fa = x, fb = x, fc = x;
    ocioApply(a, fa);
    ocioApply(b, fb);
    ocioApply(c, fc);

    const auto same =
        lut::test::runCli("diff " + shellQuoted(a) + " " + shellQuoted(b) + " --json");
    ASSERT_EQ(same.exitCode, 0) << same.err;
    EXPECT_NE(same.out.find("\"max_8bit_steps_covers\": \"every input\""), std::string::npos)
        << same.out;
    const glm::dvec3 tSame = channelMax(fa, fb);
    for (int ch = 0; ch < 3; ++ch) {
        const double printed = jsonChannel(same.out, ch);
        row("diff 9^3 vs 9^3 (one lattice), channel " + std::to_string(ch), tSame[ch], printed);
        EXPECT_GE(printed + kOracleRounding, tSame[ch]) << same.out;
        // exact: random inputs come close to the worst entry, never past it
        EXPECT_GE(tSame[ch], 0.9 * printed) << same.out;
    }

    // A 9^3 with one entry off neutral, against a neutral 13^3: the entry's point (1/8 on each
    // axis) is no point of the 13^3 lattice compared on, which sees two thirds of it.
    const std::string a2 = writeCube(dir + "/a2.cube", 9, [](glm::dvec3 p) {
        const bool spike =
            std::lround(p.r * 8) == 1 && std::lround(p.g * 8) == 1 && std::lround(p.b * 8) == 1;
        return spike ? glm::dvec3(1.0, p.g, p.b) : p;
    });
    fa = x;
    ocioApply(a2, fa);
    const auto two =
        lut::test::runCli("diff " + shellQuoted(a2) + " " + shellQuoted(c) + " --json");
    ASSERT_EQ(two.exitCode, 0) << two.err;
    EXPECT_NE(two.out.find("\"max_8bit_steps_covers\": \"the lattice's points\""),
              std::string::npos)
        << two.out;
    const glm::dvec3 tTwo = channelMax(fa, fc);
    const double truth = std::max({tTwo.x, tTwo.y, tTwo.z});
    const double sampled =
        std::max({jsonChannel(two.out, 0), jsonChannel(two.out, 1), jsonChannel(two.out, 2)});
    const double bound = jsonNumber(two.out, "bound_8bit_steps") / 255.0;
    row("diff 9^3 spike vs 13^3: at the lattice's points (a sample)", truth, sampled);
    row("diff 9^3 spike vs 13^3: bound over every input", truth, bound);
    EXPECT_GE(bound + kOracleRounding, truth) << two.out;
    EXPECT_GT(truth, sampled) << two.out; // why the points' maximum is not the figure
    const auto text = lut::test::runCli("diff " + shellQuoted(a2) + " " + shellQuoted(c));
    EXPECT_NE(text.out.find("max: at the lattice's points; over every input of A's domain at most"),
              std::string::npos)
        << text.out;
}
