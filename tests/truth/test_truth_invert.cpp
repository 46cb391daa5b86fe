// SPDX-License-Identifier: Apache-2.0
// The truth harness, invert: the printed round trip |inverse(A(x)) - x| and residual
// |A(inverse(y)) - y| against A and the written inverse both read and applied by OpenColorIO
// (tetrahedral, unoptimised) on random inputs between the lattice points, for the two forms of a
// 3D inverse (lut/ops/InvertShaper.h): the table alone and a 1D shaper then the table.
#include "TruthHarness.h"

#include <gtest/gtest.h>

using namespace lut::truth;

namespace {

struct Inverted {
    std::string out, json;
};

Inverted invertTo(const std::string& src, const std::string& out, const std::string& args = {}) {
    const auto r = lut::test::runCli("invert " + shellQuoted(src) + " " + shellQuoted(out) +
                                     " -y --json " + args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return {out, r.out};
}

// A then the inverse (round trip) and the inverse then A (residual), by OpenColorIO.
Truth roundTripTruth(const std::string& a, const std::string& inverse,
                     const std::vector<float>& x) {
    std::vector<float> y = x;
    ocioApply(a, y);
    ocioApply(inverse, y);
    return compare(x, y);
}
Truth residualTruth(const std::string& a, const std::string& inverse, const std::vector<float>& x) {
    std::vector<float> y = x;
    ocioApply(inverse, y);
    ocioApply(a, y);
    return compare(x, y);
}

double printed(const Inverted& r, const std::string& key) {
    return jsonNumber(r.json, "max", r.json.find("\"" + key + "\": {"));
}

} // namespace

// Issue 40: the inverse of x^2.2 (a 33^3 .cube) rises 64 times faster in the first cell than a
// table alone can follow: 15 8-bit steps left in the round trip. Written as a 1D shaper then the
// table (auto, since the output is a .cube), under 2; the table's figure printed beside it.
TEST(Truth, InvertOfASteepCurveWritesAShaperWhereItHelps) {
    const std::string dir = workDir("invert-pow");
    const std::string src = writeCube(dir + "/pow.cube", 33, [](glm::dvec3 p) {
        return glm::dvec3(std::pow(p.r, 2.2), std::pow(p.g, 2.2), std::pow(p.b, 2.2));
    });
    const std::vector<float> x = randomUnitInputs(100000, 43);

    const Inverted shaped = invertTo(src, dir + "/inv.cube");
    EXPECT_NE(lut::test::fileBytes(shaped.out).find("LUT_1D_SIZE"), std::string::npos);
    EXPECT_NE(shaped.json.find("\"form\": \"shaper\""), std::string::npos) << shaped.json;
    const Truth ts = roundTripTruth(src, shaped.out, x);
    const Truth rs = residualTruth(src, shaped.out, x);
    row("invert x^2.2 33^3 -> shaper + table: round trip", ts.max, printed(shaped, "round_trip"),
        ts.mean);
    row("invert x^2.2 33^3 -> shaper + table: residual", rs.max, printed(shaped, "residual"),
        rs.mean);
    EXPECT_LT(ts.max * 255, 2.0);
    EXPECT_GE(printed(shaped, "round_trip") + kOracleRounding, ts.max) << shaped.json;
    EXPECT_GE(printed(shaped, "residual") + kOracleRounding, rs.max) << shaped.json;

    const Inverted table = invertTo(src, dir + "/inv_table.cube", "--lut-form table");
    EXPECT_EQ(lut::test::fileBytes(table.out).find("LUT_1D_SIZE"), std::string::npos);
    const Truth tt = roundTripTruth(src, table.out, x);
    const Truth rt = residualTruth(src, table.out, x);
    row("invert x^2.2 33^3 -> table: round trip", tt.max, printed(table, "round_trip"), tt.mean);
    row("invert x^2.2 33^3 -> table: residual", rt.max, printed(table, "residual"), rt.mean);
    EXPECT_GE(printed(table, "round_trip") + kOracleRounding, tt.max) << table.json;
    EXPECT_GE(printed(table, "residual") + kOracleRounding, rt.max) << table.json;
    EXPECT_GT(tt.max * 255, 5.0); // what the shaper buys
    // the shaper run printed the table's figure too, a bound of the table's truth
    EXPECT_GE(printed(shaped, "round_trip_table") + kOracleRounding, tt.max) << shaped.json;

    // Resolve's form, which ffmpeg and Photoshop refuse: one warning names the flag that writes
    // what they read and its round trip, a bound of OpenColorIO's round trip through that file
    const auto text = lut::test::runCli("invert " + shellQuoted(src) + " " +
                                        shellQuoted(dir + "/inv2.cube") + " -y");
    ASSERT_EQ(text.exitCode, 0) << text.err;
    const auto said = text.out.find("--format iridas_cube writes one");
    ASSERT_NE(said, std::string::npos) << text.out;
    EXPECT_EQ(text.out.find("--format iridas_cube", said + 1), std::string::npos) << text.out;
    const auto at = text.out.rfind("round trip would be max ", said);
    ASSERT_NE(at, std::string::npos) << text.out;
    const double warned = std::strtod(text.out.c_str() + at + 24, nullptr) / 255.0;
    const Inverted adobe = invertTo(src, dir + "/inv_adobe.cube", "--format iridas_cube");
    EXPECT_EQ(lut::test::fileBytes(adobe.out).find("LUT_1D_SIZE"), std::string::npos);
    const Truth ta = roundTripTruth(src, adobe.out, x);
    row("invert x^2.2 33^3: the iridas_cube warning's round trip", ta.max, warned, ta.mean);
    EXPECT_GE(warned + kOracleRounding, ta.max) << text.out;

    // a format without a shaper: the table, said so
    const auto png = lut::test::runCli("invert " + shellQuoted(src) + " " +
                                       shellQuoted(dir + "/inv.png") + " -y");
    EXPECT_EQ(png.exitCode, 0) << png.err;
    EXPECT_NE(png.out.find("holds no 1D shaper"), std::string::npos) << png.out;
}

// A gentle curve keeps the table alone (auto), its figures bounds too.
TEST(Truth, InvertOfAGentleGradeKeepsTheTable) {
    const std::string dir = workDir("invert-gentle");
    const std::string src = writeCube(dir + "/grade.cube", 17, [](glm::dvec3 p) {
        const glm::dvec3 m(0.9 * p.r + 0.1 * p.g, 0.05 * p.r + 0.9 * p.g + 0.05 * p.b,
                           0.1 * p.g + 0.85 * p.b + 0.05);
        return m;
    });
    const std::vector<float> x = randomUnitInputs(100000, 44);
    const Inverted r = invertTo(src, dir + "/inv.cube");
    EXPECT_EQ(lut::test::fileBytes(r.out).find("LUT_1D_SIZE"), std::string::npos);
    const Truth rt = roundTripTruth(src, r.out, x);
    row("invert matrix 17^3 -> table: round trip", rt.max, printed(r, "round_trip"), rt.mean);
    EXPECT_GE(printed(r, "round_trip") + kOracleRounding, rt.max) << r.json;
}
