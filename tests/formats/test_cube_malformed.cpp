// SPDX-License-Identifier: Apache-2.0
// The malformed .cube corpus (tests/data/cube/malformed, one defect per file): each file's exact
// error text, physical line and column. Line and column numbers were counted by hand in the
// files (blank lines, comments, CR LF, BOM and lone-CR line ends included).
#include "TestSupport.h"

#include "lut/formats/Cube.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace lut;
using namespace lut::formats;

namespace {

struct Case {
    const char* file;
    int line;
    int column;
    const char* message; // ParseError::message()
    const char* found;   // ParseError::offending() ("" = none)
};

const Case kCases[] = {
    {"data_two_numbers", 7, 9, "expected 3 numbers on a data line, found 2", "0.1 0.2"},
    {"data_four_numbers", 9, 7, "expected 3 numbers on a data line, found 4", "1 0 1 0.5"},
    {"data_not_a_number", 8, 3, "expected a number", "abc"},
    {"data_nan", 10, 5, "NaN and infinity are not allowed in .cube data; expected a finite number",
     "nan"},
    {"data_inf", 4, 1, "NaN and infinity are not allowed in .cube data; expected a finite number",
     "-inf"},
    {"data_float_overflow", 5, 1, "number is out of the 32-bit float range", "1e40"},
    {"data_trailing_garbage", 11, 5, "expected a number", "1x"},
    {"size3d_too_large", 4, 13,
     "LUT_3D_SIZE 100000 is over the limit of 256 (lut::limits::kMax3DSize)", "100000"},
    {"size3d_too_small", 3, 13, "LUT_3D_SIZE 1 is below the minimum of 2", "1"},
    {"size3d_not_integer", 3, 13, "expected an integer size after LUT_3D_SIZE", "2.0"},
    {"size3d_negative", 3, 13, "LUT_3D_SIZE -5 is below the minimum of 2", "-5"},
    {"size3d_missing_value", 3, 13, "expected a size after LUT_3D_SIZE", "LUT_3D_SIZE"},
    {"size3d_extra_text", 3, 15, "unexpected text after LUT_3D_SIZE 2", "3"},
    {"size1d_too_large", 3, 13,
     "LUT_1D_SIZE 70000 is over the limit of 65536 (lut::limits::kMax1DSize)", "70000"},
    {"size_missing", 4, 1, "expected LUT_3D_SIZE or LUT_1D_SIZE before the first data line",
     "0 0 0"},
    {"empty", 1, 1, "the file is empty: expected a .cube header with LUT_3D_SIZE or LUT_1D_SIZE",
     ""},
    {"header_only", 5, 1,
     "expected 8 data rows for LUT_3D_SIZE 2, found 0 before the end of the file", ""},
    {"too_few_rows", 12, 1,
     "expected 8 data rows for LUT_3D_SIZE 2, found 7 before the end of the file", ""},
    {"too_many_rows", 14, 1,
     "too many data rows: expected 8 data rows for LUT_3D_SIZE 2, this is row 9", "0.5 0.5 0.5"},
    {"shaper_too_few_rows", 14, 1,
     "expected 2 + 8 = 10 data rows for LUT_1D_SIZE 2 and LUT_3D_SIZE 2, found 9 before the end of "
     "the file",
     ""},
    {"text_after_data", 12, 3,
     "expected only blank lines and comments after the last data row (line 10)", "END of table"},
    {"keyword_after_data", 8, 1, "DOMAIN_MAX must come before the first data line (line 4)",
     "DOMAIN_MAX"},
    {"size_repeated_different", 4, 1,
     "LUT_3D_SIZE given twice with different values (first on line 3)", "LUT_3D_SIZE 3"},
    {"title_unclosed", 3, 17, "TITLE has no closing quote", "\"half open"},
    {"title_missing_text", 3, 7, "expected a quoted title after TITLE", ""},
    {"title_trailing_text", 3, 14, "unexpected text after the TITLE's closing quote", "more"},
    {"domain_reversed", 5, 14,
     "DOMAIN_MIN must be below DOMAIN_MAX for every channel: green has min 1 and max 0.5", "0.5"},
    {"domain_two_numbers", 4, 16, "expected 3 numbers after DOMAIN_MIN, found 2", "DOMAIN_MIN 0 0"},
    {"domain_not_a_number", 4, 14, "expected 3 numbers after DOMAIN_MAX", "one"},
    {"input_range_reversed", 4, 22, "LUT_3D_INPUT_RANGE min must be below max", "1 0"},
    {"input_range_one_number", 4, 22, "expected 2 numbers after LUT_1D_INPUT_RANGE, found 1",
     "LUT_1D_INPUT_RANGE 0"},
    {"domain_and_input_range", 6, 1,
     "DOMAIN_MIN/DOMAIN_MAX and LUT_3D_INPUT_RANGE both set the input domain of the 3D table", ""},
    {"video_range_argument", 4, 20, "unexpected text after LUT_IN_VIDEO_RANGE", "1"},
    {"crlf_bom_bad_value", 9, 3, "expected a number", "0..5"},
    {"cr_only_bad_value", 6, 5, "expected a number", "--"},
};

class CubeMalformed : public ::testing::TestWithParam<Case> {};

} // namespace

TEST_P(CubeMalformed, ExactMessageLineAndColumn) {
    const Case& c = GetParam();
    const std::string path = lut::test::dataPath(std::string("cube/malformed/") + c.file + ".cube");
    try {
        readCube(path);
        FAIL() << c.file << " was accepted";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.path(), path);
        EXPECT_EQ(e.line(), c.line);
        EXPECT_EQ(e.column(), c.column);
        EXPECT_EQ(e.message(), c.message);
        EXPECT_EQ(e.offending(), c.found);
        std::string what =
            path + ":" + std::to_string(c.line) + ":" + std::to_string(c.column) + ": " + c.message;
        if (*c.found)
            what += std::string(" (found '") + c.found + "')";
        EXPECT_EQ(std::string(e.what()), what);
    }
    // Strict mode refuses the same way: departures never hide an error.
    CubeReadOptions strict;
    strict.strict = true;
    try {
        readCube(path, strict);
        FAIL() << c.file << " was accepted in strict mode";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), c.line);
        EXPECT_EQ(e.column(), c.column);
    }
    // validateCube turns the error into one Error diagnostic with the same place.
    const CubeValidation v = validateCube(path, false);
    EXPECT_FALSE(v.ok);
    EXPECT_FALSE(v.parsed());
    ASSERT_FALSE(v.diagnostics.empty());
    const Diagnostic& d = v.diagnostics.back();
    EXPECT_EQ(d.severity, Diagnostic::Severity::Error);
    EXPECT_EQ(d.line, c.line);
    EXPECT_EQ(d.column, c.column);
    EXPECT_EQ(d.message.rfind(c.message, 0), 0u) << d.message;
}

INSTANTIATE_TEST_SUITE_P(Corpus, CubeMalformed, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             return std::string(info.param.file);
                         });

// Every file in the corpus folder has a row in the table (a new file cannot go untested), and
// the corpus covers well over 15 distinct defects.
TEST(CubeMalformedCorpus, EveryFileIsListed) {
    namespace fs = std::filesystem;
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(lut::test::dataPath("cube/malformed"))) {
        if (entry.path().extension() != ".cube")
            continue;
        ++files;
        const std::string stem = entry.path().stem().string();
        bool listed = false;
        for (const Case& c : kCases)
            listed = listed || stem == c.file;
        EXPECT_TRUE(listed) << stem;
    }
    EXPECT_EQ(files, std::size(kCases));
    EXPECT_GE(files, 30u);
}
