// SPDX-License-Identifier: Apache-2.0
// lutkit convert --cccid: the six .ccc/.cdl files of OpenColorIO's test data that OCIO reads only
// with a CCC id, each converted with an id (by name where the file has ids, by index) and
// compared with OpenColorIO's processor of the source with the same id, the written file read
// back by OCIO; without --cccid the error names the option.
#include "CliTableSupport.h"
#include "CliTestSupport.h"
#include "OcioTestUtil.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace fs = std::filesystem;
using namespace lut::test;
using ::testing::HasSubstr;

namespace {

using lut::test::shellQuoted;

} // namespace

TEST(ConvertCccId, TheSixCorrectionFilesOcioReads) {
    const std::string dir = workDir();
    const std::vector<std::pair<std::string, std::string>> files = {
        {"cdl_test1.ccc", "cc0003"},
        {"cdl_test1.cdl", "cc0002"},
        {"cdl_test_cc_file_with_extension.ccc", "0"},
        {"cdl_test_cc_file_with_extension.cdl", "0"},
        {"configs/context_test1/looks.cdl", "look-02"},
        {"configs/mergeconfigs/merged3/looks.cdl", "1"},
    };
    for (const auto& [name, id] : files) {
        SCOPED_TRACE(name + " --cccid " + id);
        const std::string src = corpusPath(name), out = dir + "/out.cube";
        const RunResult none = runCli("convert -y " + shellQuoted(src) + " " + shellQuoted(out));
        EXPECT_EQ(none.exitCode, 1);
        EXPECT_THAT(none.err, HasSubstr("--cccid"));
        const RunResult r = runCli("convert -y " + shellQuoted(src) + " " + shellQuoted(out) +
                                   " --cccid " + shellQuoted(id));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const auto source = ocioFileProcessor(src, id);
        const auto written = ocioFileProcessor(out);
        double worst = 0.0;
        for (int b = 0; b < 9; ++b)
            for (int g = 0; g < 9; ++g)
                for (int rr = 0; rr < 9; ++rr) {
                    const glm::vec3 x = glm::vec3(rr, g, b) / 8.0f;
                    const glm::vec3 want = ocioEval(source, x), got = ocioEval(written, x);
                    for (int c = 0; c < 3; ++c)
                        worst = std::max(worst, std::fabs(double(got[c]) - want[c]));
                }
        EXPECT_LT(worst, 1e-4) << r.out;
    }
}
