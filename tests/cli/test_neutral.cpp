// SPDX-License-Identifier: Apache-2.0
// lutkit neutral: default sizes per format and identity contents read back.
#include "CliTestSupport.h"

#include "lut/formats/Registry.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using lut::test::runCli;
using lut::test::workDir;

namespace {

using lut::test::shellQuoted;

} // namespace

TEST(CliNeutral, DefaultSizesPerFormat) {
    const std::string dir = workDir();
    struct Case {
        const char* file;
        int size;
        double tolerance; // what the format stores
    } cases[] = {
        {"n.cube", 33, 0.0},
        {"n.png", 16, 0.5 / 255},
        {"color_grading_lut.nutexb", 16, 0.5 / 255},
        {"n.3dl", 33, 0.5 / 4095 + 1e-6},
        {"n.csp", 33, 1e-6},
    };
    for (const auto& c : cases) {
        const std::string path = dir + "/" + c.file;
        const auto r = runCli("neutral " + shellQuoted(path));
        ASSERT_EQ(r.exitCode, 0) << c.file << ": " << r.err;
        const lut::LutFile f = lut::formats::readLut(path);
        ASSERT_TRUE(f.cube) << c.file;
        EXPECT_EQ(f.cube->size(), c.size) << c.file;
        EXPECT_LE(f.cube->maxDeviationFromIdentity(), c.tolerance) << c.file;
    }
}

TEST(CliNeutral, SizeAndUsage) {
    const std::string dir = workDir();
    ASSERT_EQ(runCli("neutral --size 2 " + shellQuoted(dir + "/two.cube")).exitCode, 0);
    const lut::LutFile f = lut::formats::readLut(dir + "/two.cube");
    EXPECT_EQ(f.cube->size(), 2);
    EXPECT_TRUE(f.cube->isIdentity(0.0f));
    EXPECT_EQ(runCli("neutral").exitCode, 2);
    EXPECT_EQ(runCli("neutral --size 300 " + shellQuoted(dir + "/x.cube")).exitCode, 2);
    EXPECT_EQ(runCli("neutral " + shellQuoted(dir + "/x.unknownext")).exitCode, 1);
    EXPECT_FALSE(fs::exists(dir + "/x.cube"));
}
