// SPDX-License-Identifier: Apache-2.0
// lutkit info: the JSON output parsed strictly and its fields checked against values known here.
#include "CliTestSupport.h"
#include "test_convert_json.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using lut::test::runCli;
using lut::test::samplePath;
using lut::test::workDir;

namespace {

using lut::test::shellQuoted;

} // namespace

TEST(CliInfo, JsonFieldsOfTheSampleGrade) {
    const auto r = runCli("info --json " + shellQuoted(samplePath("sample_grade.cube")));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto js = lut::test::json::parse(r.out);
    EXPECT_EQ(js["format"].string, "cube");
    EXPECT_EQ(js["size"].number, 33);
    EXPECT_EQ(js["title"].string, "lutkit sample sunset grade");
    EXPECT_EQ(js["neutral"].string, "no");
    EXPECT_GT(js["max_deviation_from_identity"].number, 0.01);
    EXPECT_TRUE(js["shaper"].isNull());
    ASSERT_EQ(js["domain_min"].array.size(), 3u);
    EXPECT_EQ(js["domain_min"][0].number, 0.0);
    EXPECT_EQ(js["domain_max"][2].number, 1.0);
    EXPECT_GE(js["value_min"].number, 0.0);
    EXPECT_LE(js["value_max"].number, 1.0);
    EXPECT_LT(js["value_min"].number, js["value_max"].number);
    // Text values are floating point: 32-bit float, not "0" (issue 18).
    EXPECT_EQ(js["source_bit_depth"].number, 32);
    EXPECT_TRUE(js["float"].boolean);
    EXPECT_EQ(js["comments"].type, lut::test::json::Value::Type::Number);
}

TEST(CliInfo, NeutralIsExactAndEightBitNeutralIsNear) {
    const std::string dir = workDir();
    ASSERT_EQ(runCli("neutral --size 5 " + shellQuoted(dir + "/n.cube")).exitCode, 0);
    auto js = lut::test::json::parse(runCli("info --json " + shellQuoted(dir + "/n.cube")).out);
    EXPECT_EQ(js["neutral"].string, "exact");
    EXPECT_EQ(js["max_deviation_from_identity"].number, 0.0);
    EXPECT_EQ(js["size"].number, 5);
    // A 12-bit .3dl neutral is within half an 8-bit step of the identity, but not exact.
    ASSERT_EQ(runCli("neutral --size 17 " + shellQuoted(dir + "/n.3dl")).exitCode, 0);
    js = lut::test::json::parse(runCli("info --json " + shellQuoted(dir + "/n.3dl")).out);
    EXPECT_EQ(js["format"].string, "ocio");
    EXPECT_EQ(js["neutral"].string, "near");
    EXPECT_EQ(js["source_bit_depth"].number, 12);
    EXPECT_FALSE(js["float"].boolean);
    EXPECT_EQ(js["size"].number, 17);
}

TEST(CliInfo, JsonEscapesStrings) {
    const std::string dir = workDir();
    // A path with a quote, a backslash and a tab must still give valid JSON that round-trips.
    const std::string weird = dir + "/we\"ird\\na\tme.cube";
    ASSERT_EQ(runCli("neutral --size 2 " + shellQuoted(weird)).exitCode, 0);
    const auto r = runCli("info --json " + shellQuoted(weird));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto js = lut::test::json::parse(r.out);
    EXPECT_EQ(js["path"].string, weird);
}

TEST(CliInfo, TextOutputAndErrors) {
    const auto r = runCli("info " + shellQuoted(samplePath("sample_grade.cube")));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("33^3"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("neutral     no"), std::string::npos) << r.out;
    EXPECT_EQ(runCli("info").exitCode, 2);
    const auto bad = runCli("info " + shellQuoted(workDir() + "/none.cube"));
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find("none.cube"), std::string::npos) << bad.err;
}
