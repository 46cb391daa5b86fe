// SPDX-License-Identifier: Apache-2.0
// Issue 22, "double compensation": a LUT file says what it is for (lut/LutPurpose.h) and every
// command honours it. From the default (game) patch, `extract EDITED grade.cube` writes the
// game's LUT and says so in the file; `convert grade.cube color_grading_lut.nutexb` then copies
// it instead of compensating it a second time. The oracle is the game's model in float64, written
// plainly in TruthOracle.h from docs/specs/smash-pipeline.md: what the game shows with the
// written nutexb against the edit of what it showed before.
#include "RoundtripTestUtil.h"
#include "TestSupport.h"
#include "TruthOracle.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

using namespace lut;
using namespace lut::rt;
using lut::test::runCli;

namespace {

using lut::test::fileBytes;
using lut::test::shellQuoted;
bool has(const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
}

// embed -> the edit applied to the patched screenshot -> the edited file.
std::string editedPatch(const std::string& dir, const Edit& edit) {
    const std::string shot = dir + "/shot.png";
    formats::ImageWriteOptions o;
    o.alpha = false;
    formats::writeImage(shot, syntheticScreenshot(kShotWidth, kShotHeight, 8), o);
    const auto e = runCli("embed " + shellQuoted(shot) + " " + shellQuoted(dir + "/patch.png"));
    EXPECT_EQ(e.exitCode, 0) << e.err;
    auto img = formats::readImage(dir + "/patch.png");
    applyEdit(img.image, edit, 8);
    formats::writeImage(dir + "/edited.png", img.image, o);
    return dir + "/edited.png";
}

} // namespace

TEST(Purpose, AnExtractedGameLutIsNotCompensatedTwice) {
    const std::string dir = rtDir();
    const Edit edit = warmGradientMap();
    const std::string ed = editedPatch(dir, edit);
    const auto x = runCli("extract " + shellQuoted(ed) + " " + shellQuoted(dir + "/grade.cube"));
    ASSERT_EQ(x.exitCode, 0) << x.err;
    // the file says what it is, in a comment other readers skip
    EXPECT_TRUE(has(fileBytes(dir + "/grade.cube"), "\n# LUTKIT_PURPOSE smash\n") ||
                fileBytes(dir + "/grade.cube").rfind("# LUTKIT_PURPOSE smash\n", 0) == 0);
    const auto c = runCli("convert " + shellQuoted(dir + "/grade.cube") + " " +
                          shellQuoted(dir + "/cgl.nutexb"));
    ASSERT_EQ(c.exitCode, 0) << c.err;
    EXPECT_TRUE(has(c.out, "in:  smash (the file says so: LUTKIT_PURPOSE smash)")) << c.out;
    // what the game shows against the edit: as extract's own .nutexb (the same bytes)
    const Truth once = smashTruth(formats::readLut(dir + "/cgl.nutexb").toLut3D(), edit);
    ASSERT_EQ(
        runCli("extract " + shellQuoted(ed) + " " + shellQuoted(dir + "/direct.nutexb")).exitCode,
        0);
    EXPECT_EQ(fileBytes(dir + "/cgl.nutexb"), fileBytes(dir + "/direct.nutexb"));
    std::printf("[ measured ] extract -> .cube -> convert -> .nutexb, game vs edit: mean %.2f, "
                "p99 %.2f, max %.2f 8-bit steps\n",
                once.overall.mean, once.overall.p99, once.overall.max);
    EXPECT_LT(once.overall.mean, 1.5);
    EXPECT_LT(once.overall.p99, 8.0);
    // What convert did before the file said what it was (--in-target raw forces it): the game's
    // LUT compensated a second time, far off the edit.
    const auto twice = runCli("convert " + shellQuoted(dir + "/grade.cube") + " " +
                              shellQuoted(dir + "/twice.nutexb") + " --in-target raw");
    ASSERT_EQ(twice.exitCode, 0) << twice.err;
    const Truth bad = smashTruth(formats::readLut(dir + "/twice.nutexb").toLut3D(), edit);
    std::printf("[ measured ] compensated twice (--in-target raw): mean %.2f, p99 %.2f 8-bit "
                "steps\n",
                bad.overall.mean, bad.overall.p99);
    EXPECT_GT(bad.overall.mean, 10.0);
}
