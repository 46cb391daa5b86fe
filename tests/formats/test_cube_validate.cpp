// SPDX-License-Identifier: Apache-2.0
// `lutkit validate` and lut::formats::validateCube: ok lines, strict departures, errors with
// file:line:col, exit codes (0 ok, 1 bad input or departures with --strict, 2 bad usage).
#include "TestPaths.h"
#include "TestSupport.h"

#include "lut/formats/Cube.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace lut;
using namespace lut::formats;
using lut::test::dataPath;
using lut::test::runCli;

namespace {

std::string cube(const std::string& name) {
    return dataPath("cube/" + name);
}

// The CLI tests need the lutkit binary of this build tree (formats_tests does not depend on it).
bool haveCli() {
    return std::filesystem::exists(LUTKIT_CLI);
}

} // namespace

TEST(CubeValidate, LibraryStrictAndLenient) {
    const CubeValidation lenient = validateCube(cube("crlf_bom_comments.cube"), false);
    EXPECT_TRUE(lenient.ok);
    EXPECT_TRUE(lenient.diagnostics.empty());
    EXPECT_EQ(lenient.summary(), "adobe 3D, 2^3");

    const CubeValidation strict = validateCube(cube("crlf_bom_comments.cube"), true);
    EXPECT_FALSE(strict.ok);
    EXPECT_TRUE(strict.parsed());
    // BOM + 19 CR LF + lower-case keyword + indented comment.
    EXPECT_EQ(strict.departures, 22);

    const CubeValidation clean = validateCube(cube("adobe_3d_domain.cube"), true);
    EXPECT_TRUE(clean.ok);
    EXPECT_EQ(clean.departures, 0);

    const CubeValidation missing = validateCube("/nonexistent/dir/x.cube", false);
    EXPECT_FALSE(missing.ok);
    ASSERT_EQ(missing.diagnostics.size(), 1u);
    EXPECT_EQ(missing.diagnostics[0].severity, Diagnostic::Severity::Error);
}

TEST(CubeValidate, CliOkLines) {
    ASSERT_TRUE(haveCli()) << "lutkit not built (formats_tests depends on it)";
    const auto r = runCli("validate '" + cube("adobe_3d_domain.cube") + "' '" +
                          cube("resolve_shaper_3d.cube") + "' '" + cube("adobe_1d.cube") + "'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find(cube("adobe_3d_domain.cube") + ": ok (adobe 3D, 2^3)\n"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(cube("resolve_shaper_3d.cube") + ": ok (resolve 1D 4 + 3D, 2^3)\n"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(cube("adobe_1d.cube") + ": ok (adobe 1D, 5)\n"), std::string::npos)
        << r.out;
    EXPECT_EQ(r.err, "");
}

TEST(CubeValidate, CliStrictListsDeparturesAndFails) {
    ASSERT_TRUE(haveCli()) << "lutkit not built (formats_tests depends on it)";
    const std::string p = cube("crlf_bom_comments.cube");
    const auto lenient = runCli("validate '" + p + "'");
    EXPECT_EQ(lenient.exitCode, 0);
    EXPECT_EQ(lenient.out, p + ": ok (adobe 3D, 2^3)\n");

    const auto strict = runCli("validate --strict '" + p + "'");
    EXPECT_EQ(strict.exitCode, 1);
    EXPECT_EQ(
        strict.out,
        p + ":1:1: warning: file starts with a UTF-8 byte order mark\n" + p +
            ":1:18: warning: line ends with CR LF; the Adobe spec uses LF\n" + p +
            ":3:1: warning: keyword 'title' is not upper case; the Adobe spec spells it TITLE\n" +
            p +
            ":4:3: warning: comment does not start at column 1; the Adobe spec wants '#' first\n" +
            p + ": warning: and 18 more: lines end with CR LF\n" + p +
            ": 22 departures from the Adobe .cube 1.0 spec (adobe 3D, 2^3)\n");

    const auto clean = runCli("validate --strict '" + cube("size2.cube") + "'");
    EXPECT_EQ(clean.exitCode, 0);
    EXPECT_EQ(clean.out, cube("size2.cube") + ": ok (adobe 3D, 2^3)\n");
}

TEST(CubeValidate, CliErrorsNameFileLineColumn) {
    ASSERT_TRUE(haveCli()) << "lutkit not built (formats_tests depends on it)";
    const std::string bad = dataPath("cube/malformed/data_two_numbers.cube");
    const auto r = runCli("validate '" + bad + "' '" + cube("size2.cube") + "'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err,
              bad + ":7:9: error: expected 3 numbers on a data line, found 2 (found '0.1 0.2')\n");
    // The good file after the bad one is still checked.
    EXPECT_EQ(r.out, cube("size2.cube") + ": ok (adobe 3D, 2^3)\n");

    const auto missing = runCli("validate /nonexistent/x.cube");
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find("/nonexistent/x.cube: cannot open"), std::string::npos)
        << missing.err;

    const auto usage = runCli("validate");
    EXPECT_EQ(usage.exitCode, 2);
}
