// SPDX-License-Identifier: Apache-2.0
// -q, the one rule for every command (issue 43; cli/Notes.h): nothing on standard output, and on
// standard error nothing but warnings and errors. `convert -q` used to print its whole report
// (1.3 KB), info, validate, diff, check and the writers theirs. --json is asked for by name and
// stays; a warning stays; the data written to `-` stays.
#include "CliTestSupport.h"

#include "lut/Image.h"
#include "lut/formats/ImageIO.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace lut;
using namespace lut::test;
using ::testing::HasSubstr;

namespace {

// Every line of stderr is a warning or an error ("lutkit: warning: ...", "FILE: warning: ...").
void expectOnlyWarningsAndErrors(const std::string& err) {
    std::istringstream lines(err);
    for (std::string line; std::getline(lines, line);)
        EXPECT_TRUE(line.find("warning: ") != std::string::npos ||
                    line.find("error: ") != std::string::npos ||
                    line.find("' shows where") != std::string::npos) // a warning's second line
            << "not a warning or an error: " << line;
}

// Every command, its outputs named with `tag`.
std::vector<std::string> commands(const CommandInputs& in, const std::string& tag) {
    const std::string a = shellQuoted(in.a), b = shellQuoted(in.b), shot = shellQuoted(in.shot),
                      strip = shellQuoted(in.strip);
    auto out = [&](const std::string& name) { return shellQuoted(in.dir + "/" + tag + name); };
    return {
        "neutral " + out("n.cube") + " --size 9",
        "convert " + a + " " + out("c.nutexb"),
        "convert " + a + " " + out("c.cube") + " --size 17",
        "convert " + a + " - --format cube", // the data stays, the report goes
        "info " + a,
        "info " + strip + " -v",
        "validate " + a,
        "diff " + a + " " + b,
        "diff " + a + " " + b + " --heatmap " + out("heat.png"),
        "check " + a,
        "compose " + a + " " + b + " " + out("compose.cube"),
        "invert " + a + " " + out("invert.cube"),
        "resize " + a + " " + out("resize.cube") + " --size 5",
        "smooth " + a + " " + out("smooth.cube"),
        "mix " + a + " " + b + " " + out("mix.cube") + " --strength 0.5",
        "adjust " + a + " --adjustments " + shellQuoted(in.adjustments) + " " + out("adj.cube"),
        "extract " + strip + " " + out("extract.cube") + " --target raw",
        "bake " + out("bake.cube") + " --lut " + a + " --cubesize 9",
        "plot " + a + " " + out("plot.png"),
        "chart grey " + out("chart.png") + " --bit-depth 8",
        "atlas build " + a + " " + b + " -o " + out("atlas.png"),
        "atlas info " + out("atlas.png"),
        "atlas split " + out("atlas.png") + " -o " + out("rows/"),
        "embed " + shot + " " + out("embed.png"),
        "apply --lut " + a + " " + shot + " -o " + out("apply.png"),
        "apply --lut " + a + " " + shot + " " + strip + " -o " + out("batch/"),
        "preview " + shot + " -o " + out("preview.png") + " --lut " + a,
        "match " + shot + " " + strip + " " + out("match.cube"),
    };
}

} // namespace

TEST(Quiet, EveryCommandSaysNothingButWarningsAndErrors) {
    const CommandInputs in = makeCommandInputs(tempDir());
    const std::vector<std::string> loud = commands(in, "loud-"), quiet = commands(in, "quiet-");
    for (std::size_t i = 0; i < quiet.size(); ++i) {
        SCOPED_TRACE("lutkit " + quiet[i] + " -q");
        // Without -q each command has a report (else the test would pass for a silent one).
        const RunResult l = runCli(loud[i]);
        EXPECT_EQ(l.exitCode, 0) << l.err;
        if (loud[i].find("apply.png") == std::string::npos) { // one apply says nothing
            EXPECT_NE(l.out + l.err, "") << "the report without -q";
        }
        const RunResult r = runCli(quiet[i] + " -q");
        EXPECT_EQ(r.exitCode, 0) << r.err;
        if (quiet[i].find(" - ") != std::string::npos) { // the LUT on stdout
            EXPECT_EQ(r.out.rfind("LUT_3D_SIZE 9\n", 0), 0u) << "the data alone on stdout";
        } else {
            EXPECT_EQ(r.out, "") << "stdout under -q";
        }
        expectOnlyWarningsAndErrors(r.err);
    }
}

TEST(Quiet, JsonAskedForByNameStays) {
    const CommandInputs in = makeCommandInputs(tempDir());
    const RunResult r = runCli("convert " + shellQuoted(in.a) + " " +
                               shellQuoted(in.dir + "/j.cube") + " --json -q");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("\"output\""));
    EXPECT_EQ(r.err, "");
}

TEST(Quiet, WarningsStay) {
    const CommandInputs in = makeCommandInputs(tempDir());
    // A keyword the Adobe spec does not have: a warning at its line, from the reader.
    const std::string kw = in.dir + "/keyword.cube";
    std::ofstream(kw) << "LUT_3D_SIZE 2\nFOO bar\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 "
                         "1\n1 1 1\n";
    for (const std::string& c :
         {"validate " + shellQuoted(kw), "info " + shellQuoted(kw),
          "convert " + shellQuoted(kw) + " " + shellQuoted(in.dir + "/k.nutexb")}) {
        SCOPED_TRACE("lutkit " + c + " -q");
        const RunResult r = runCli(c + " -q");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.out, "");
        EXPECT_THAT(r.err, HasSubstr("keyword.cube:2:1: warning: unknown keyword 'FOO' ignored"));
        expectOnlyWarningsAndErrors(r.err);
    }
}

TEST(Quiet, ErrorsStay) {
    const CommandInputs in = makeCommandInputs(tempDir());
    const RunResult r = runCli("info " + shellQuoted(in.dir + "/missing.cube") + " -q");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_THAT(r.err, HasSubstr("error: "));
}
