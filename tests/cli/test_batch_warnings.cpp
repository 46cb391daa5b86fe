// SPDX-License-Identifier: Apache-2.0
// Issue 43: a batch's warnings. Values outside the LUT's domain are said once per batch (a
// sequence said it once per frame, 230 characters each), counted over every frame, naming the
// colour spaces of the active config whose images hold such values; -q keeps that one warning.
// Warnings during a batch never land inside the progress bar's line: lutkit runs on a terminal
// (script(1) gives it one) and every "lutkit:" line starts a line. The frames are written by
// oiiotool, the expected spaces read from the configs' text.
//
// LUTKIT_TEST_BINARY runs the same checks on another build.
#include "TestPaths.h"
#include "TestSupport.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;
using namespace lut::test;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {

std::string lutkit() {
    const char* other = std::getenv("LUTKIT_TEST_BINARY");
    return other && *other ? other : LUTKIT_CLI;
}

RunResult run(const std::string& args, const std::string& env = "env -u OCIO") {
    return runCommand(env + " '" + lutkit() + "' " + args);
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

// Frames f.0001.exr ... of 64x64 half RGB: `bright` of them with red at `red` (outside [0, 1]),
// the others within.
std::string frames(const std::string& dir, int total, int bright, double red) {
    const std::string in = dir + "/frames";
    fs::create_directories(in);
    for (int i = 1; i <= total; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "/f.%04d.exr", i);
        const double r = i <= bright ? red : 0.5;
        const RunResult o = runCommand("oiiotool --pattern constant:color=" + std::to_string(r) +
                                       ",0.5,0.1 64x64 3 -d half -o " + shellQuoted(in + name));
        EXPECT_EQ(o.exitCode, 0) << o.err;
    }
    return in;
}

std::string neutral(const std::string& dir) {
    const std::string lut = dir + "/n.cube";
    EXPECT_EQ(run("neutral --size 17 -y " + shellQuoted(lut)).exitCode, 0);
    return lut;
}

} // namespace

TEST(BatchWarnings, OutsideTheDomainOncePerBatchNamingColourSpaces) {
    if (!haveProgram("oiiotool"))
        GTEST_SKIP() << "oiiotool is not installed";
    const std::string dir = tempDir();
    const std::string in = frames(dir, 6, 4, 2.5), lut = neutral(dir);
    for (const char* quiet : {"", " -q"}) {
        SCOPED_TRACE(quiet);
        fs::remove_all(dir + "/out");
        const RunResult r = run("apply --lut " + shellQuoted(lut) + " " + shellQuoted(in) + " -o " +
                                shellQuoted(dir + "/out/") + quiet);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(count(r.err, "outside the LUT's domain"), 1u) << r.err;
        // 4 frames of 6, every pixel of them: 16384 of 24576 pixels.
        EXPECT_THAT(r.err, HasSubstr("lutkit: warning: 4 of 6 files (" + in +
                                     "/f.0001.exr ...): 16384 of 24576 pixels (66.6667%) outside "
                                     "the LUT's domain [0, 1] (worst 2.5)"));
        // lutkit's own config: its four scene-linear spaces (lg2 allocations up to 2^4.03).
        EXPECT_THAT(r.err, HasSubstr("--from one of 'Linear Rec.709 (sRGB)', 'ACEScg', "
                                     "'ACES2065-1', 'CIE-XYZ-D65' (lutkit's own config)"));
    }
    // One file: its name.
    const RunResult one =
        run("apply -y --lut " + shellQuoted(lut) + " " + shellQuoted(in + "/f.0002.exr") + " -o " +
            shellQuoted(dir + "/one.exr"));
    EXPECT_THAT(one.err, HasSubstr("lutkit: warning: " + in +
                                   "/f.0002.exr: 4096 of 4096 pixels (100%) outside"));
    // Nothing outside: nothing said.
    const RunResult none =
        run("apply -y --lut " + shellQuoted(lut) + " " + shellQuoted(in + "/f.0006.exr") + " -o " +
            shellQuoted(dir + "/none.exr"));
    EXPECT_EQ(none.err, "");
}

TEST(BatchWarnings, SpacesOfTheActiveConfigThatHoldTheValues) {
    if (!haveProgram("oiiotool"))
        GTEST_SKIP() << "oiiotool is not installed";
    const std::string dir = tempDir();
    const std::string cfg = dataPath("ocio/studio_names.ocio");
    const std::string lut = neutral(dir);
    // studio_names.ocio: 'lin studio' (lg2 up to 2^3 = 8) and 'wide lin' (no allocation) are
    // scene-linear; 'film log' and 'raw' are not.
    const std::string five = frames(dir + "/a", 2, 2, 5.0);
    RunResult r = run("apply --lut " + shellQuoted(lut) + " " + shellQuoted(five) + " -o " +
                          shellQuoted(dir + "/a/out/"),
                      "env OCIO=" + shellQuoted(cfg));
    EXPECT_THAT(r.err, HasSubstr("--from one of 'lin studio', 'wide lin' (" + cfg + " ($OCIO))"));
    // 20 is past 'lin studio''s allocation.
    const std::string twenty = frames(dir + "/b", 2, 2, 20.0);
    r = run("apply --lut " + shellQuoted(lut) + " " + shellQuoted(twenty) + " -o " +
                shellQuoted(dir + "/b/out/"),
            "env OCIO=" + shellQuoted(cfg));
    EXPECT_THAT(r.err, HasSubstr("(scene-linear values: --from 'wide lin' (" + cfg));
    EXPECT_THAT(r.err, Not(HasSubstr("'lin studio'")));
}

TEST(BatchWarnings, WarningsNeverLandInsideTheProgressBar) {
    if (!haveProgram("oiiotool") || !haveProgram("script"))
        GTEST_SKIP() << "oiiotool or script is not installed";
    const std::string dir = tempDir();
    // Frames outside the domain (said after the batch) and a per-file note: .3dl LUTs of another
    // size converted in a batch (each says it was resampled).
    const std::string in = frames(dir, 3, 3, 2.5), lut = neutral(dir);
    fs::create_directories(dir + "/luts");
    for (const char* n : {"a", "b", "c"})
        ASSERT_EQ(run("neutral --size 9 -y " + shellQuoted(dir + "/luts/" + n + ".cube")).exitCode,
                  0);
    const std::vector<std::string> commands = {
        "apply --threads 1 --lut " + shellQuoted(lut) + " " + shellQuoted(in) + " -o " +
            shellQuoted(dir + "/out/"),
        "convert --size 5 " + shellQuoted(dir + "/luts") + " -o " + shellQuoted(dir + "/3dl/") +
            " --format flame"};
    for (const auto& c : commands) {
        SCOPED_TRACE(c);
        // script(1): lutkit's standard error is a terminal, so it draws its bar.
        const RunResult r =
            runCommand("script -qec " + shellQuoted("'" + lutkit() + "' " + c) + " /dev/null");
        ASSERT_EQ(r.exitCode, 0) << r.out;
        ASSERT_THAT(r.out, HasSubstr("\r\033[K[")) << "no progress bar drawn";
        ASSERT_THAT(r.out, HasSubstr("lutkit: "));
        // Every "lutkit:" begins a line: after a newline, or after the bar's line was cleared.
        for (auto at = r.out.find("lutkit: "); at != std::string::npos;
             at = r.out.find("lutkit: ", at + 1)) {
            const bool lineStart = at == 0 || r.out[at - 1] == '\n' ||
                                   (at >= 4 && r.out.compare(at - 4, 4, "\r\033[K") == 0);
            EXPECT_TRUE(lineStart)
                << "inside the bar: ..." << r.out.substr(at >= 60 ? at - 60 : 0, 100);
        }
    }
}
