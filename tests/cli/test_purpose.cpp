// SPDX-License-Identifier: Apache-2.0
// What a LUT is for (lut/LutPurpose.h), honoured by every command that reads one (issue 22,
// "double compensation"): convert copies the game's LUT and makes an edit into it, and makes the
// edit a game LUT makes with an error bound the truth does not exceed; apply applies the game's
// LUT as that edit; preview of an edit is preview of the .nutexb convert writes from it; compose,
// mix, resize, info and extract honour and keep it. Oracles: the game's model in float64 written
// here from docs/specs/smash-pipeline.md, OpenColorIO's processor on the written files, the
// program's own other command where the claim is that two commands agree.
#include "CliTestSupport.h"
#include "OcioTestUtil.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <OpenColorIO/OpenColorIO.h>
#include <glm/common.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <random>
#include <regex>

namespace OCIO = OCIO_NAMESPACE;
using namespace lut;
using namespace lut::test;

namespace {

using game::gameLut;
using game::gameShows;
using game::srgbDecode;
using lut::test::fileBytes;
using lut::test::shellQuoted;

// The colour the game shows with LUT `g` for a colour d the neutral game shows.
glm::dvec3 gameEditOf(const Lut3D& g, glm::dvec3 d) {
    glm::dvec3 s;
    for (int c = 0; c < 3; ++c)
        s[c] = std::pow(srgbDecode(d[c]), 1 / 2.2) / 1.3703;
    return gameShows(g, s);
}

Lut3D look(int n) { // an edit of display colours
    Lut3D l = Lut3D::identity(n);
    for (auto& e : l.entries())
        e = glm::vec3(0.92f * e.x + 0.04f, e.y * (0.6f + 0.4f * e.y), 0.85f * e.z + 0.1f * e.x);
    return l;
}

void writeTable(const std::string& path, const Lut3D& lut, std::optional<LutPurpose> purpose) {
    LutFile f;
    f.cube = lut;
    f.purpose = purpose;
    formats::writeLut(path, f);
}

// A picture of random colours, 8-bit.
std::string randomPicture(const std::string& path, int w, int h) {
    Image img(w, h);
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> u(0, 255);
    for (std::size_t i = 0; i < img.pixels().size(); ++i)
        img.pixels()[i] = i % 4 == 3 ? 1.0f : u(rng) / 255.0f;
    formats::ImageWriteOptions o;
    o.alpha = false;
    formats::writeImage(path, img, o);
    return path;
}

double printedMax(const std::string& text) {
    std::smatch m;
    const std::regex re("max ([0-9.]+), mean");
    return std::regex_search(text, m, re) ? std::stod(m[1]) : -1.0;
}

} // namespace

TEST(CliPurpose, ConvertCopiesTheGamesLutAndCompensatesAnEditOnce) {
    const std::string dir = workDir();
    const Lut3D game = gameLut();
    writeTable(dir + "/game.cube", game, LutPurpose::Smash);
    const auto c =
        runCli("convert " + shellQuoted(dir + "/game.cube") + " " + shellQuoted(dir + "/g.nutexb"));
    ASSERT_EQ(c.exitCode, 0) << c.err;
    EXPECT_TRUE(has(c.out, "in:  smash (the file says so: LUTKIT_PURPOSE smash)")) << c.out;
    EXPECT_FALSE(has(c.out, "exact composition")) << c.out;
    EXPECT_EQ(formats::readLut(dir + "/g.nutexb").cube->entries(), game.entries());
    // The same table untagged is taken as an edit, said with the flag that chooses, and made
    // into the game's LUT; --in-target smash copies it.
    writeTable(dir + "/plain.cube", game, std::nullopt);
    const auto p = runCli("convert " + shellQuoted(dir + "/plain.cube") + " " +
                          shellQuoted(dir + "/p.nutexb"));
    ASSERT_EQ(p.exitCode, 0) << p.err;
    EXPECT_TRUE(has(p.out, "in:  raw (the file does not say; --in-target smash if it is the "
                           "game's LUT)"))
        << p.out;
    EXPECT_TRUE(has(p.out, "exact composition")) << p.out;
    EXPECT_NE(formats::readLut(dir + "/p.nutexb").cube->entries(), game.entries());
    ASSERT_EQ(runCli("convert " + shellQuoted(dir + "/plain.cube") + " " +
                     shellQuoted(dir + "/s.nutexb") + " --in-target smash")
                  .exitCode,
              0);
    EXPECT_EQ(formats::readLut(dir + "/s.nutexb").cube->entries(), game.entries());
    // a .cube written from the game's LUT says so; from an edit that did not say, nothing
    ASSERT_EQ(
        runCli("convert " + shellQuoted(dir + "/g.nutexb") + " " + shellQuoted(dir + "/back.cube"))
            .exitCode,
        0);
    EXPECT_EQ(formats::readLut(dir + "/back.cube").purpose, LutPurpose::Smash);
    ASSERT_EQ(runCli("convert " + shellQuoted(dir + "/plain.cube") + " " +
                     shellQuoted(dir + "/plain2.cube"))
                  .exitCode,
              0);
    EXPECT_EQ(formats::readLut(dir + "/plain2.cube").purpose, std::nullopt);
    // a bad name is bad usage
    EXPECT_EQ(runCli("convert " + shellQuoted(dir + "/plain.cube") + " " +
                     shellQuoted(dir + "/x.cube") + " --in-target game")
                  .exitCode,
              2);
}

// smash -> raw: the edit the game's LUT makes; the printed max is not below the truth at 200,000
// random colours (OpenColorIO evaluates the written .cube, the game's model here the truth).
TEST(CliPurpose, TheEditOfTheGamesLutIsBoundedByWhatConvertPrints) {
    const std::string dir = workDir();
    const Lut3D game = gameLut();
    writeTable(dir + "/g.nutexb", game, std::nullopt);
    const auto c = runCli("convert " + shellQuoted(dir + "/g.nutexb") + " " +
                          shellQuoted(dir + "/edit.cube") + " --target raw --json");
    ASSERT_EQ(c.exitCode, 0) << c.err;
    std::smatch m;
    const std::regex re("\"sampling\": \\{\"max\": ([0-9.e+-]+)");
    ASSERT_TRUE(std::regex_search(c.out, m, re)) << c.out;
    const double printed = std::stod(m[1]);
    EXPECT_EQ(formats::readLut(dir + "/edit.cube").purpose, LutPurpose::Raw);
    const auto cpu = test::ocioFileProcessor(dir + "/edit.cube");
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double truth = 0.0;
    for (int i = 0; i < 200000; ++i) {
        const glm::dvec3 d(u(rng), u(rng), u(rng));
        float px[3] = {float(d.x), float(d.y), float(d.z)};
        cpu->applyRGB(px);
        const glm::dvec3 want = gameEditOf(game, d);
        for (int ch = 0; ch < 3; ++ch)
            truth = std::max(truth, std::fabs(px[ch] - want[ch]) * 255.0);
    }
    std::printf("[ measured ] convert --target raw of a game LUT: printed max %.3f, truth %.3f "
                "8-bit steps\n",
                printed, truth);
    EXPECT_GE(printed, truth);
}

// apply takes the game's LUT as the edit it makes: every pixel within the printed sampling error
// (and the output's 8-bit rounding) of the game's model; an edit is applied as it is.
TEST(CliPurpose, ApplyAppliesTheGamesLutAsTheEditItMakes) {
    const std::string dir = workDir();
    const Lut3D game = gameLut();
    writeTable(dir + "/g.nutexb", game, std::nullopt);
    const std::string in = randomPicture(dir + "/in.png", 96, 64);
    const auto a = runCli("apply --lut " + shellQuoted(dir + "/g.nutexb") + " " + shellQuoted(in) +
                          " -o " + shellQuoted(dir + "/out.png"));
    ASSERT_EQ(a.exitCode, 0) << a.err;
    EXPECT_TRUE(has(a.err, "is smash (a .nutexb is the game's LUT): used as an edit")) << a.err;
    const double printed = printedMax(a.err);
    ASSERT_GE(printed, 0.0) << a.err;
    const Image src = formats::readImage(in).image,
                out = formats::readImage(dir + "/out.png").image;
    double worst = 0.0;
    for (int y = 0; y < src.height(); ++y)
        for (int x = 0; x < src.width(); ++x) {
            const float* p = src.pixel(x, y);
            const glm::dvec3 want = gameEditOf(game, glm::dvec3(p[0], p[1], p[2]));
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::fabs(out.pixel(x, y)[c] - want[c]) * 255.0);
        }
    EXPECT_LE(worst, printed + 0.5 + 1e-3);
    // --lut-target raw: the table as it is (far from the game's picture)
    ASSERT_EQ(runCli("apply --lut " + shellQuoted(dir + "/g.nutexb") + " --lut-target raw " +
                     shellQuoted(in) + " -o " + shellQuoted(dir + "/raw.png"))
                  .exitCode,
              0);
    EXPECT_NE(fileBytes(dir + "/raw.png"), fileBytes(dir + "/out.png"));
}

// preview --lut EDIT is preview --lut (the .nutexb convert writes from EDIT): one conversion.
TEST(CliPurpose, PreviewOfAnEditIsPreviewOfTheNutexbConvertWrites) {
    const std::string dir = workDir();
    writeTable(dir + "/look.cube", look(17), std::nullopt);
    const std::string shot = randomPicture(dir + "/shot.png", 64, 40);
    ASSERT_EQ(runCli("convert " + shellQuoted(dir + "/look.cube") + " " +
                     shellQuoted(dir + "/look.nutexb"))
                  .exitCode,
              0);
    const auto a = runCli("preview " + shellQuoted(shot) + " -o " + shellQuoted(dir + "/a.png") +
                          " --lut " + shellQuoted(dir + "/look.cube"));
    ASSERT_EQ(a.exitCode, 0) << a.err;
    EXPECT_TRUE(has(a.err, "is raw (the file does not say; --lut-target smash if it is the "
                           "game's LUT): used as the game's LUT"))
        << a.err;
    const auto b = runCli("preview " + shellQuoted(shot) + " -o " + shellQuoted(dir + "/b.png") +
                          " --lut " + shellQuoted(dir + "/look.nutexb"));
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_EQ(formats::readImage(dir + "/a.png").image.pixels(),
              formats::readImage(dir + "/b.png").image.pixels());
}

TEST(CliPurpose, ComposeMixResizeInfoAndExtractHonourIt) {
    const std::string dir = workDir();
    const Lut3D game = gameLut();
    writeTable(dir + "/stage.nutexb", game, std::nullopt);
    writeTable(dir + "/look.cube", look(17), LutPurpose::Raw);
    // compose: the look on the stage's picture is convert --original-lut stage
    const auto c = runCli("compose " + shellQuoted(dir + "/stage.nutexb") + " " +
                          shellQuoted(dir + "/look.cube") + " " + shellQuoted(dir + "/new.nutexb"));
    ASSERT_EQ(c.exitCode, 0) << c.err;
    EXPECT_TRUE(has(c.out, "OUT: smash")) << c.out;
    ASSERT_EQ(runCli("convert " + shellQuoted(dir + "/look.cube") + " " +
                     shellQuoted(dir + "/conv.nutexb") + " --original-lut " +
                     shellQuoted(dir + "/stage.nutexb"))
                  .exitCode,
              0);
    EXPECT_EQ(fileBytes(dir + "/new.nutexb"), fileBytes(dir + "/conv.nutexb"));
    // mix: both made for the result's purpose (A's: smash), the result says so
    const auto m =
        runCli("mix " + shellQuoted(dir + "/stage.nutexb") + " " + shellQuoted(dir + "/look.cube") +
               " " + shellQuoted(dir + "/mixed.cube") + " --strength 0.5");
    ASSERT_EQ(m.exitCode, 0) << m.err;
    EXPECT_TRUE(has(m.out, "convert  B: raw -> smash")) << m.out;
    EXPECT_EQ(formats::readLut(dir + "/mixed.cube").purpose, LutPurpose::Smash);
    // resize keeps what the LUT is for
    ASSERT_EQ(runCli("resize " + shellQuoted(dir + "/mixed.cube") + " " +
                     shellQuoted(dir + "/r.cube") + " --size 33")
                  .exitCode,
              0);
    EXPECT_EQ(formats::readLut(dir + "/r.cube").purpose, LutPurpose::Smash);
    // info says it, as text and JSON
    const auto i = runCli("info " + shellQuoted(dir + "/r.cube"));
    EXPECT_TRUE(has(i.out, "purpose     smash (the file says so: LUTKIT_PURPOSE smash)")) << i.out;
    const auto j = runCli("info " + shellQuoted(dir + "/look.cube") + " --json");
    EXPECT_TRUE(has(j.out, "\"purpose\": \"raw\", \"purpose_source\": \"file\"")) << j.out;
    // extract of a graded strip that says it is the game's: copied, still the game's
    writeTable(dir + "/final.png", game, LutPurpose::Smash);
    const auto x =
        runCli("extract " + shellQuoted(dir + "/final.png") + " " + shellQuoted(dir + "/x.nutexb"));
    ASSERT_EQ(x.exitCode, 0) << x.err;
    EXPECT_EQ(formats::readLut(dir + "/x.nutexb").cube->entries(), game.entries());
}

// Compose names the stage its conversion was made on: A when B's edit is made into the game's LUT
// on the picture A gives, the neutral game when the composed edit is (A and B both edits).
TEST(CliPurpose, ComposeNamesTheStageOfItsConversion) {
    const std::string dir = workDir();
    writeTable(dir + "/stage.nutexb", gameLut(), std::nullopt);
    writeTable(dir + "/look.cube", look(17), LutPurpose::Raw);
    writeTable(dir + "/look2.cube", look(9), LutPurpose::Raw);
    const auto staged =
        runCli("compose " + shellQuoted(dir + "/stage.nutexb") + " " +
               shellQuoted(dir + "/look.cube") + " " + shellQuoted(dir + "/s.nutexb"));
    ASSERT_EQ(staged.exitCode, 0) << staged.err;
    EXPECT_TRUE(has(staged.out, "convert  B on A's picture: raw -> smash")) << staged.out;
    EXPECT_TRUE(has(staged.out, "(stage LUT: " + dir + "/stage.nutexb;")) << staged.out;
    const auto neutral =
        runCli("compose " + shellQuoted(dir + "/look.cube") + " " +
               shellQuoted(dir + "/look2.cube") + " " + shellQuoted(dir + "/n.nutexb"));
    ASSERT_EQ(neutral.exitCode, 0) << neutral.err;
    EXPECT_TRUE(has(neutral.out, "convert  result: raw -> smash")) << neutral.out;
    EXPECT_TRUE(has(neutral.out, "(stage LUT: neutral;")) << neutral.out;
    EXPECT_FALSE(has(neutral.out, "stage LUT: A")) << neutral.out;
}
