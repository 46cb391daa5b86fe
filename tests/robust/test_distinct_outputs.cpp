// SPDX-License-Identifier: Apache-2.0
// Issue 41: no two outputs of one command are one file, and standard output that the shell
// pointed at an input is refused like any output that is an input (lut::CommandOutputs,
// lut::checkOutput). Before: `match SRC REF OUT.png --report-image OUT.png` wrote the report over
// the LUT and `apply ... -o - 1<> lut.cube` wrote the picture over the LUT, both exit 0; `check
// --report DIR/` with two LUTs of one base name failed "already exists" on the second.
#include "RobustSupport.h"
#include "TestPaths.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using namespace lut::robust;
using lut::test::runCli;
using lut::test::runCommand;
using lut::test::shellQuoted;
using ::testing::HasSubstr;

namespace {

void oiiotool(const std::string& args) {
    ASSERT_EQ(runCommand("oiiotool " + args).exitCode, 0) << args;
}

TEST(DistinctOutputs, MatchReportImageOverItsOwnLutIsRefused) {
    const std::string dir = lut::test::tempDir();
    oiiotool("--pattern fill:top=0.2,0.3,0.4:bottom=0.6,0.5,0.3 48x32 3 -d uint8 -o " +
             shellQuoted(dir + "/src.png"));
    oiiotool("--pattern fill:top=0.5,0.3,0.2:bottom=0.3,0.6,0.7 48x32 3 -d uint8 -o " +
             shellQuoted(dir + "/ref.png"));
    for (const std::string& report : {dir + "/out.cube", dir + "/./out.cube", std::string("-")}) {
        SCOPED_TRACE(report);
        const std::string out = report == "-" ? "-" : dir + "/out.cube";
        const auto r =
            runCli("match " + shellQuoted(dir + "/src.png") + " " + shellQuoted(dir + "/ref.png") +
                   " " + shellQuoted(out) + " --report-image " + shellQuoted(report));
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_THAT(r.err, HasSubstr(report + ": is also another output of this command"));
        EXPECT_FALSE(fs::exists(dir + "/out.cube")); // nothing written
        EXPECT_EQ(r.out, "");
    }
}

// `lutkit apply --lut LUT IN -o - --format png` with its standard output opened by the shell on
// `target` (1<>: read and written, not truncated).
lut::test::RunResult applyToStdoutOn(const std::string& dir, const std::string& target) {
    const std::string inner = "\"" + std::string(LUTKIT_CLI) + "\" apply --lut \"" + dir +
                              "/lut.cube\" \"" + dir + "/in.png\" -o - --format png 1<> \"" +
                              target + "\"";
    return runCommand("sh -c '" + inner + "'");
}

// The shell opens standard output on the LUT (or the picture) read and written: refused, the
// file as it was.
TEST(DistinctOutputs, StandardOutputThatIsAnInputIsRefused) {
    const std::string dir = lut::test::tempDir();
    const std::string cube = neutralCube(2);
    writeBytes(dir + "/lut.cube", cube);
    oiiotool("--pattern fill:top=0.2,0.3,0.4:bottom=0.6,0.5,0.3 16x8 3 -d uint8 -o " +
             shellQuoted(dir + "/in.png"));
    const std::string png = fileBytes(dir + "/in.png");
    for (const std::string& target : {dir + "/lut.cube", dir + "/in.png"}) {
        SCOPED_TRACE(target);
        const auto r = applyToStdoutOn(dir, target);
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_THAT(r.err, HasSubstr("-: standard output is the same file as input " + target));
        EXPECT_EQ(fileBytes(dir + "/lut.cube"), cube);
        EXPECT_EQ(fileBytes(dir + "/in.png"), png);
    }
    // Standard output on another file is written.
    writeBytes(dir + "/other.png", "");
    const auto r = applyToStdoutOn(dir, dir + "/other.png");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(fileBytes(dir + "/other.png").substr(1, 3), "PNG");
}

TEST(DistinctOutputs, CheckReportPicturesOfLutsSharingABaseName) {
    const std::string dir = lut::test::tempDir();
    fs::create_directories(dir + "/a");
    fs::create_directories(dir + "/b");
    writeBytes(dir + "/a/x.cube", neutralCube(5));
    writeBytes(dir + "/b/x.cube", neutralCube(5));
    ASSERT_EQ(
        runCli("convert " + shellQuoted(dir + "/a/x.cube") + " " + shellQuoted(dir + "/a/x.3dl"))
            .exitCode,
        0);
    const auto r =
        runCli("check " + shellQuoted(dir + "/a/x.cube") + " " + shellQuoted(dir + "/b/x.cube") +
               " " + shellQuoted(dir + "/a/x.3dl") + " --report " + shellQuoted(dir + "/pics/"));
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_EQ(
        listDir(dir + "/pics"),
        (std::vector<std::string>{"x.3dl.check.png", "x.cube-1.check.png", "x.cube-2.check.png"}));
}

} // namespace
