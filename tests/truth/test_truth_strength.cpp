// SPDX-License-Identifier: Apache-2.0
// The truth harness, convert --strength of a shaper + table (Resolve .cube, log2 shaper over
// 0..64): the truth is the strength blend written here in float64 (tests/support/
// OklabReference.h) of OpenColorIO's reading of the source, against OpenColorIO's reading of the
// written file (a LUT image: interpolated here in float64), on random inputs in [0,1] (a quarter
// in [0, 1/16], where the shaper is steepest); the printed maximum (the blend's, plus resampling
// and storage) must not be below it.
#include "OklabReference.h"
#include "TruthHarness.h"

#include <gtest/gtest.h>

using namespace lut::truth;

namespace {

// "max X" in the --strength note of convert's --json diagnostics; NaN if absent.
double strengthPrinted(const std::string& json) {
    const auto at = json.find("(--strength): max ");
    return at == std::string::npos ? NAN : std::strtod(json.c_str() + at + 18, nullptr);
}

} // namespace

// Issue 40 (round three): the blend sampled the shaper file onto its table's 33^3 lattice over
// the shaper's whole 0..64 first, so 0..1 got a few planes: every output here was mean 37.9 / max
// 57.3 8-bit steps off the blend of OpenColorIO's reading, and nothing printed for it. Now blended
// behind the shaper where the output keeps one (0.42 / 1.36), at a lattice over 0..1 where it
// cannot (the 33^3 lattice's own cost there, max 10.6), the error bounded over 0..1 and printed.
TEST(Truth, StrengthOfAShaperCubeBlendsOverTheDisplayRange) {
    const std::string dir = workDir("strength");
    const std::string src = writeShapedCube(dir + "/shaped.cube");
    const std::vector<float> x = randomUnitInputs(100000, 45);
    std::vector<float> graded = x;
    ocioApply(src, graded);
    std::vector<float> want(x.size());
    for (std::size_t i = 0; i < x.size(); i += 3) {
        const glm::dvec3 b =
            lut::test::strengthBlend(glm::dvec3(x[i], x[i + 1], x[i + 2]),
                                     glm::dvec3(graded[i], graded[i + 1], graded[i + 2]), 0.5, 0.5);
        for (int c = 0; c < 3; ++c)
            want[i + c] = static_cast<float>(b[c]);
    }
    struct Case {
        std::string name, args;
        bool image = false, shaperKept = false;
    };
    const Case cases[] = {{"out.cube", "", false, true},
                          {"adobe.cube", "--format iridas_cube"},
                          {"out.3dl", ""},
                          {"out.png", "", true}};
    for (const Case& k : cases) {
        const std::string out = dir + "/" + k.name;
        const auto r = lut::test::runCli("convert " + shellQuoted(src) + " " + shellQuoted(out) +
                                         " -y --json --strength 0.5 " + k.args);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const double blend = strengthPrinted(r.out);
        ASSERT_FALSE(std::isnan(blend)) << r.out;
        const auto rs = r.out.find("\"resample\": {");
        const double resample = rs == std::string::npos ? 0.0 : jsonNumber(r.out, "max", rs);
        const double storage = jsonNumber(r.out, "max", r.out.find("\"storage\": {"));
        const double printed = blend + resample + (std::isnan(storage) ? 0.0 : storage);
        EXPECT_EQ(lut::test::fileBytes(out).find("LUT_1D_SIZE") != std::string::npos, k.shaperKept)
            << k.name;
        std::vector<float> got = x;
        if (k.image)
            stripApply(out, got);
        else
            ocioApply(out, got);
        const Truth t = compare(want, got);
        row("convert --strength 0.5 shaper 4096 + 33^3 -> " + k.name + " " + k.args, t.max, printed,
            t.mean);
        EXPECT_GE(printed + kOracleRounding, t.max) << k.name << "\n" << r.out;
        EXPECT_LT(t.mean * 255, 1.0) << k.name;
    }
}
