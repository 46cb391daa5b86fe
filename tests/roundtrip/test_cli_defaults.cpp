// SPDX-License-Identifier: Apache-2.0
// The round trip's defaults pair up through the lutkit binary: embed records what it is for,
// extract needs no options, a .nutexb output means the game; convert --target smash makes the
// game's LUT from a graded strip (Smush-LUT's neutral.png) and extract reads Smush-LUT's own
// files; --help states every default.
#include "RoundtripTestUtil.h"
#include "TestSupport.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/Layout.h"
#include "lut/roundtrip/Extract.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace lut;
using namespace lut::rt;
using lut::test::runCli;

namespace {

using lut::test::fileBytes;
using lut::test::shellQuoted;
std::string shotFile(const std::string& dir) {
    const std::string path = dir + "/shot.png";
    formats::ImageWriteOptions o;
    o.alpha = false;
    formats::writeImage(path, syntheticScreenshot(kShotWidth, kShotHeight, 8), o);
    return path;
}
std::string edited(const std::string& in, const std::string& out, const Edit& f) {
    auto img = formats::readImage(in);
    applyEdit(img.image, f, 8);
    formats::ImageWriteOptions o;
    o.alpha = false;
    formats::writeImage(out, img.image, o);
    return out;
}
bool has(const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
}

} // namespace

TEST(RoundtripDefaults, EmbedThenExtractNeedsNoOptions) {
    const std::string dir = rtDir();
    const std::string shot = shotFile(dir);
    for (const char* target : {"smash", "raw"}) {
        SCOPED_TRACE(target);
        const std::string emb = dir + "/emb-" + target + ".png";
        const auto e = runCli("embed " + shellQuoted(shot) + " " + shellQuoted(emb) +
                              (std::string(target) == "raw" ? " --target raw" : ""));
        ASSERT_EQ(e.exitCode, 0) << e.err;
        EXPECT_TRUE(has(e.out, std::string("patch for ") + target)) << e.out;
        EXPECT_TRUE(has(e.out, "at scale 8")) << e.out;
        EXPECT_TRUE(has(e.out, "no options needed")) << e.out;
        const std::string ed = edited(emb, dir + "/edited-" + target + ".png", curvesEdit());
        const auto x = runCli("extract " + shellQuoted(ed) + " " +
                              shellQuoted(dir + "/out-" + target + ".cube"));
        ASSERT_EQ(x.exitCode, 0) << x.err;
        EXPECT_TRUE(has(x.out, std::string("target: ") + target + " (recorded in the patch)"))
            << x.out;
        EXPECT_TRUE(has(x.out, std::string("wrote 16^3 ") + target)) << x.out;
        // the same LUT the library makes with the recorded target
        const ExtractResult lib = extractLut(formats::readImage(ed).image.view(), {});
        const Lut3D got = formats::readLut(dir + "/out-" + target + ".cube").toLut3D();
        for (std::size_t i = 0; i < got.entryCount(); ++i)
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(got.entries()[i][c], lib.lut.entries()[i][c], 1e-5);
        // writing to .nutexb means the game, whatever the patch was made for
        const auto n = runCli("extract " + shellQuoted(ed) + " " +
                              shellQuoted(dir + "/cgl-" + target + ".nutexb"));
        ASSERT_EQ(n.exitCode, 0) << n.err;
        EXPECT_TRUE(has(n.out, "target: smash (the output is a .nutexb")) << n.out;
        // ... unless --target raw says otherwise
        const auto r = runCli("extract " + shellQuoted(ed) + " " +
                              shellQuoted(dir + "/raw-" + target + ".nutexb") + " --target raw");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_TRUE(has(r.out, "target: raw (given)")) << r.out;
    }
    // bad combinations are bad usage
    EXPECT_EQ(runCli("embed " + shellQuoted(shot) + " " + shellQuoted(dir + "/x.png") +
                     " --target raw --original-lut " + shellQuoted(dir + "/out-smash.cube"))
                  .exitCode,
              2);
}

TEST(RoundtripDefaults, ExtractPrintsWhatTheExpectedErrorCovers) {
    const std::string dir = rtDir();
    const std::string shot = shotFile(dir);
    ASSERT_EQ(runCli("embed " + shellQuoted(shot) + " " + shellQuoted(dir + "/emb.png")).exitCode,
              0);
    const std::string ed = edited(dir + "/emb.png", dir + "/ed.png", levelsEdit());
    const auto x =
        runCli("extract " + shellQuoted(ed) + " " + shellQuoted(dir + "/cgl.nutexb") + " --refine");
    ASSERT_EQ(x.exitCode, 0) << x.err;
    EXPECT_TRUE(has(x.out, "expected error, an upper estimate from the patch's own redundancy"));
    EXPECT_TRUE(has(x.out, "what the game shows with the 8-bit LUT")) << x.out;
    EXPECT_TRUE(has(x.out, "at the LUT's lattice points: max")) << x.out;
    EXPECT_TRUE(has(x.out, "over all inputs, between the lattice points too: max")) << x.out;
    EXPECT_TRUE(has(x.out, "least-squares refinement")) << x.out;
    const auto quiet =
        runCli("extract " + shellQuoted(ed) + " " + shellQuoted(dir + "/q.nutexb") + " -q");
    EXPECT_FALSE(has(quiet.out, "expected error")) << quiet.out;
}

TEST(RoundtripDefaults, TheStageLutIsEmbeddedAndNotNeededAgain) {
    const std::string dir = rtDir();
    const std::string shot = shotFile(dir);
    Lut3D warm = Lut3D::identity(16);
    for (auto& e : warm.entries())
        e = glm::vec3(std::min(1.0f, e.x * 1.05f + 0.02f), e.y, e.z * 0.92f);
    LutFile wf;
    wf.cube = warm;
    formats::writeLut(dir + "/stage.nutexb", wf);
    const auto e = runCli("embed " + shellQuoted(shot) + " " + shellQuoted(dir + "/emb.png") +
                          " --original-lut " + shellQuoted(dir + "/stage.nutexb"));
    ASSERT_EQ(e.exitCode, 0) << e.err;
    EXPECT_TRUE(has(e.out, "16^3 game-display patch for smash with the stage LUT")) << e.out;
    const std::string ed = edited(dir + "/emb.png", dir + "/ed.png", curvesEdit());
    const auto x = runCli("extract " + shellQuoted(ed) + " " + shellQuoted(dir + "/cgl.nutexb"));
    ASSERT_EQ(x.exitCode, 0) << x.err;
    EXPECT_TRUE(has(x.out, "for the stage LUT")) << x.out;
    // given again, the right LUT is quietly accepted; another one is a warning
    const auto same =
        runCli("extract " + shellQuoted(ed) + " " + shellQuoted(dir + "/cgl2.nutexb") +
               " --original-lut " + shellQuoted(dir + "/stage.nutexb"));
    EXPECT_FALSE(has(same.err, "stage LUT")) << same.err;
    EXPECT_EQ(fileBytes(dir + "/cgl.nutexb"), fileBytes(dir + "/cgl2.nutexb"));
    LutFile nf;
    nf.cube = Lut3D::identity(16);
    formats::writeLut(dir + "/neutral.cube", nf);
    const auto other =
        runCli("extract " + shellQuoted(ed) + " " + shellQuoted(dir + "/cgl3.nutexb") +
               " --original-lut " + shellQuoted(dir + "/neutral.cube"));
    EXPECT_EQ(other.exitCode, 0);
    EXPECT_TRUE(has(other.err, "was embedded for the stage LUT")) << other.err;
}

TEST(RoundtripDefaults, ConvertMakesTheGamesLutFromAGradedStrip) {
    // Smush-LUT's workflow: grade its neutral.png (a 256x16 identity in its own layout, here
    // lutkit's smush layout) like the screenshot, then turn it into the game's LUT.
    const std::string dir = rtDir();
    Lut3D graded = Lut3D::identity(16);
    const Edit grade = warmGradientMap();
    for (auto& e : graded.entries())
        e = glm::vec3(grade(glm::dvec3(e)));
    LutFile gf;
    gf.cube = graded;
    FormatOptions smush;
    smush.layout = LutLayout::Smush;
    formats::writeLut(dir + "/neutral_graded.png", gf, smush);
    const auto c = runCli("convert " + shellQuoted(dir + "/neutral_graded.png") + " " +
                          shellQuoted(dir + "/cgl.nutexb"));
    ASSERT_EQ(c.exitCode, 0) << c.err;
    EXPECT_TRUE(has(c.out, "out: smash (the output is a .nutexb")) << c.out;
    EXPECT_TRUE(has(c.out, "exact composition:")) << c.out;
    EXPECT_TRUE(has(c.out, "least-squares refinement:")) << c.out;
    EXPECT_TRUE(has(c.err + c.out, "layout detected: smush")) << c.err << c.out;
    // extract on the same file: the same LUT (one library call)
    const auto x = runCli("extract " + shellQuoted(dir + "/neutral_graded.png") + " " +
                          shellQuoted(dir + "/cgl-extract.nutexb"));
    ASSERT_EQ(x.exitCode, 0) << x.err;
    EXPECT_TRUE(has(x.out, "Smush-LUT's neutral.png")) << x.out;
    EXPECT_EQ(fileBytes(dir + "/cgl.nutexb"), fileBytes(dir + "/cgl-extract.nutexb"));
    // to a .cube, the edit as it is, the table convert writes from the same file (extract
    // compensated it for the game before, while saying "the edit itself")
    const auto xc = runCli("extract " + shellQuoted(dir + "/neutral_graded.png") + " " +
                           shellQuoted(dir + "/x-extract.cube"));
    ASSERT_EQ(xc.exitCode, 0) << xc.err;
    EXPECT_TRUE(has(xc.out, "target: raw")) << xc.out;
    ASSERT_EQ(runCli("convert " + shellQuoted(dir + "/neutral_graded.png") + " " +
                     shellQuoted(dir + "/x-convert.cube"))
                  .exitCode,
              0);
    const Lut3D viaExtract = formats::readLut(dir + "/x-extract.cube").toLut3D();
    const Lut3D viaConvert = formats::readLut(dir + "/x-convert.cube").toLut3D();
    ASSERT_EQ(viaExtract.size(), viaConvert.size());
    float worstCube = 0.0f;
    for (int b = 0; b < viaExtract.size(); ++b)
        for (int g = 0; g < viaExtract.size(); ++g)
            for (int r = 0; r < viaExtract.size(); ++r)
                for (int c = 0; c < 3; ++c)
                    worstCube = std::max(worstCube, std::fabs(viaExtract.at(r, g, b)[c] -
                                                              viaConvert.at(r, g, b)[c]));
    EXPECT_LE(worstCube, 1e-6f);
    // --refine writes the refinement; --target raw the strip as it is
    ASSERT_EQ(runCli("convert " + shellQuoted(dir + "/neutral_graded.png") + " " +
                     shellQuoted(dir + "/refined.nutexb") + " --refine")
                  .exitCode,
              0);
    EXPECT_NE(fileBytes(dir + "/cgl.nutexb"), fileBytes(dir + "/refined.nutexb"));
    ASSERT_EQ(runCli("convert " + shellQuoted(dir + "/neutral_graded.png") + " " +
                     shellQuoted(dir + "/raw.nutexb") + " --target raw")
                  .exitCode,
              0);
    const Lut3D raw = formats::readLut(dir + "/raw.nutexb").toLut3D();
    EXPECT_NEAR(raw.at(3, 9, 5).x, graded.at(3, 9, 5).x, 0.5f / 255.0f + 1e-6f);
    EXPECT_EQ(runCli("convert " + shellQuoted(dir + "/neutral_graded.png") + " " +
                     shellQuoted(dir + "/x.cube") + " --refine")
                  .exitCode,
              2); // --refine is for the smash target
}

TEST(RoundtripDefaults, SmushLutsFirstStripFilesAreRead) {
    // Smush-LUT 0.1's "<shot>.lut.png": the screenshot darkened (v / 1.4, truncated) with a
    // 256x16 strip over its top-left pixels, axis values of the default stage LUT, entry (r,g,b)
    // at x = r + 16 b, y = g. Its model: the graded strip is the game's LUT.
    const std::string dir = rtDir();
    const int axis[16] = {0, 15, 30, 46, 64, 82, 101, 121, 140, 158, 176, 193, 209, 224, 240, 255};
    Image img = syntheticScreenshot(400, 260, 8);
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                float& v = img.pixel(x, y)[c];
                v = static_cast<float>(std::floor(std::lround(v * 255.0) / 1.4) / 255.0);
            }
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                float* p = img.pixel(r + 16 * b, g);
                p[0] = axis[r] / 255.0f;
                p[1] = axis[g] / 255.0f;
                p[2] = axis[b] / 255.0f;
            }
    applyEdit(img, curvesEdit(), 8);
    formats::ImageWriteOptions o;
    o.alpha = false;
    formats::writeImage(dir + "/stage.lut.png", img, o);
    const auto x = runCli("extract " + shellQuoted(dir + "/stage.lut.png") + " " +
                          shellQuoted(dir + "/cgl.nutexb"));
    ASSERT_EQ(x.exitCode, 0) << x.err;
    EXPECT_TRUE(has(x.out, "Smush-LUT strip")) << x.out;
    const Lut3D lut = formats::readLut(dir + "/cgl.nutexb").toLut3D();
    const Edit f = curvesEdit();
    for (int b = 0; b < 16; b += 5)
        for (int g = 0; g < 16; g += 3)
            for (int r = 0; r < 16; r += 2) {
                const glm::dvec3 want = f(glm::dvec3(axis[r], axis[g], axis[b]) / 255.0);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(lut.at(r, g, b)[c], want[c], 1.0 / 255.0 + 1e-6);
            }
    // the same picture without the name is not taken for a strip
    std::filesystem::copy_file(dir + "/stage.lut.png", dir + "/plain.png");
    EXPECT_EQ(
        runCli("extract " + shellQuoted(dir + "/plain.png") + " " + shellQuoted(dir + "/x.nutexb"))
            .exitCode,
        1);
}

TEST(RoundtripDefaults, HelpStatesEveryDefault) {
    const auto embed = runCli("embed --help");
    EXPECT_TRUE(has(embed.out, "smash (default)")) << embed.out;
    EXPECT_TRUE(has(embed.out, "default 8")) << embed.out;
    EXPECT_TRUE(has(embed.out, "default: game-display for smash, uniform for raw")) << embed.out;
    const auto extract = runCli("extract --help");
    EXPECT_TRUE(has(extract.out, "default: what the patch records")) << extract.out;
    EXPECT_TRUE(has(extract.out, "smash for a .nutexb output")) << extract.out;
    const auto convert = runCli("convert --help");
    EXPECT_TRUE(has(convert.out, "default: smash for a .nutexb")) << convert.out;
    const auto preview = runCli("preview --help");
    EXPECT_TRUE(has(preview.out, "8/16-bit images are in-game screenshots")) << preview.out;
}
