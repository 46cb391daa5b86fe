// SPDX-License-Identifier: Apache-2.0
// lutkit atlas build / split / info: a 3-row MultiLUT atlas of three different LUTs and its split
// rows are byte for byte the ReShade strips of those LUTs; sampled with MultiLUT.fx's formula
// (tests/support/ShaderSamplers.h) each row gives its LUT within half an 8-bit step; repeated
// rows, rows of another size and pictures that are no atlas are refused naming the row.
#include "CliTestSupport.h"
#include "ShaderSamplers.h"

#include "lut/formats/ImageIO.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>

using namespace lut;
using namespace lut::test;

namespace {

// An n^3 .cube of f, written with 9 digits (read back as the same floats); the table it holds.
Lut3D writeTable(const std::string& path, int n, const std::function<glm::dvec3(glm::dvec3)>& f) {
    Lut3D l(n);
    std::ofstream out(path);
    out.precision(9);
    out << "LUT_3D_SIZE " << n << "\n";
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                l.at(r, g, b) = glm::vec3(f(glm::dvec3(l.latticeInput(r, g, b))));
                const glm::vec3 e = l.at(r, g, b);
                out << e.r << " " << e.g << " " << e.b << "\n";
            }
    return l;
}

glm::dvec3 warm(glm::dvec3 c) {
    return {std::pow(c.x, 0.8), c.y * c.y * (3 - 2 * c.y), 0.9 * std::pow(c.z, 1.2)};
}
glm::dvec3 cool(glm::dvec3 c) {
    return {0.8 * c.y, 0.9 * c.z, 0.1 + 0.9 * c.x};
}
glm::dvec3 sepia(glm::dvec3 c) {
    const double y = 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
    return {std::min(1.0, 1.07 * y), 0.74 * y + 0.1, 0.43 * y + 0.05};
}

using lut::test::shellQuoted;

} // namespace

TEST(CliAtlas, MultiLutAtlasRowsAreTheReshadeStripsAndSampleAsTheLuts) {
    const std::string dir = workDir();
    const std::vector<Lut3D> luts = {writeTable(dir + "/warm.cube", 32, warm),
                                     writeTable(dir + "/cool.cube", 32, cool),
                                     writeTable(dir + "/sepia.cube", 32, sepia)};
    const char* names[] = {"warm", "cool", "sepia"};
    for (const char* n : names)
        ASSERT_EQ(runCli("convert " + shellQuoted(dir + "/" + n + ".cube") + " " +
                         shellQuoted(dir + "/" + n + ".png") + " --layout reshade")
                      .exitCode,
                  0);
    RunResult r = runCli("atlas build " + shellQuoted(dir + "/warm.cube") + " " +
                         shellQuoted(dir + "/cool.cube") + " " + shellQuoted(dir + "/sepia.cube") +
                         " -o " + shellQuoted(dir + "/atlas.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("3 rows of 32^3 in the reshade layout"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("fLUT_LutAmount 3"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("ui_items=\"warm\\0cool\\0sepia\\0\""), std::string::npos) << r.out;

    // MultiLUT.fx's formula on the atlas, row by row: each LUT within half an 8-bit step (plus
    // float rounding of v * 255 at a tie).
    const Texture atlas = load(dir + "/atlas.png");
    ASSERT_EQ(atlas.w, 1024);
    ASSERT_EQ(atlas.h, 96);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 3; ++k) {
        double worst = 0;
        for (int i = 0; i < 4000; ++i) {
            const glm::dvec3 c = i < 1000 ? glm::dvec3(i % 32, (i / 32) % 32, (i * 7) % 32) / 31.0
                                          : glm::dvec3(u(rng), u(rng), u(rng));
            const auto got = reshadeSample(atlas, c, k, 3);
            const auto want = trilinear(luts[static_cast<std::size_t>(k)], c);
            for (int ch = 0; ch < 3; ++ch)
                worst = std::max(worst, std::fabs(got[ch] - want[ch]) * 255.0);
        }
        EXPECT_LE(worst, 0.5 + 1e-4) << names[k];
    }

    // Split again: one strip per row, byte for byte the strips convert wrote.
    std::filesystem::create_directories(dir + "/rows");
    r = runCli("atlas split " + shellQuoted(dir + "/atlas.png") + " -o " +
               shellQuoted(dir + "/rows/"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (int k = 0; k < 3; ++k) {
        const std::string row = dir + "/rows/atlas-0" + std::to_string(k) + ".png";
        ASSERT_TRUE(std::filesystem::exists(row)) << r.out;
        EXPECT_EQ(fileBytes(row), fileBytes(dir + "/" + names[k] + ".png")) << row;
        EXPECT_EQ(formats::readImage(row).image.pixels(),
                  formats::readImage(dir + "/" + names[k] + ".png").image.pixels());
    }
    // The rows exist now: a second split refuses them without -y, replaces them with it.
    EXPECT_EQ(runCli("atlas split " + shellQuoted(dir + "/atlas.png") + " -o " +
                     shellQuoted(dir + "/rows/"))
                  .exitCode,
              1);
    EXPECT_EQ(runCli("atlas split " + shellQuoted(dir + "/atlas.png") + " -o " +
                     shellQuoted(dir + "/rows/") + " -y")
                  .exitCode,
              0);

    r = runCli("atlas info " + shellQuoted(dir + "/atlas.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("rows     3 (32^3 each)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("layout   reshade (detected"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("repeats  none"), std::string::npos) << r.out;
}

TEST(CliAtlas, NeutralFirstResamplesToTheLayoutsSizeAndSaysTheError) {
    const std::string dir = workDir();
    writeTable(dir + "/warm.cube", 33, warm);
    writeTable(dir + "/cool.cube", 17, cool);
    RunResult r = runCli("atlas build " + shellQuoted(dir + "/warm.cube") + " " +
                         shellQuoted(dir + "/cool.cube") + " -o " + shellQuoted(dir + "/a.png") +
                         " --neutral-first");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("row 0  (neutral)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("33^3 resampled to 32^3 (tetrahedral): max"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("17^3 resampled to 32^3"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("ui_items=\"Neutral\\0warm\\0cool\\0\""), std::string::npos) << r.out;
    r = runCli("atlas info " + shellQuoted(dir + "/a.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("rows     3"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("neutral  row 0"), std::string::npos) << r.out;
    // The neutral row samples as the identity.
    const Texture tex = load(dir + "/a.png");
    double worst = 0;
    for (int i = 0; i <= 30; ++i) {
        const glm::dvec3 c(i / 30.0, 1 - i / 30.0, (i * 11 % 31) / 30.0);
        const auto got = reshadeSample(tex, c, 0, 3);
        for (int ch = 0; ch < 3; ++ch)
            worst = std::max(worst, std::fabs(got[ch] - c[ch]) * 255.0);
    }
    EXPECT_LE(worst, 0.5 + 1e-4);
}

TEST(CliAtlas, RepeatedRowsAndOtherSizesAreRefusedNamingTheRow) {
    const std::string dir = workDir();
    writeTable(dir + "/a.cube", 16, warm);
    writeTable(dir + "/b.cube", 16, cool);
    writeTable(dir + "/c.cube", 17, sepia);
    writeTable(dir + "/n.cube", 16, [](glm::dvec3 c) { return c; });
    const std::string out = shellQuoted(dir + "/x.png");
    RunResult r =
        runCli("atlas build " + shellQuoted(dir + "/a.cube") + " " + shellQuoted(dir + "/b.cube") +
               " " + shellQuoted(dir + "/a.cube") + " -o " + out + " --layout unreal");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(
        r.err.find("row 2 (" + dir + "/a.cube) stores the same LUT as row 0 (" + dir + "/a.cube)"),
        std::string::npos)
        << r.err;
    // A neutral file after --neutral-first is the neutral row again.
    r = runCli("atlas build " + shellQuoted(dir + "/n.cube") + " -o " + out +
               " --layout unreal --neutral-first");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("row 1 (" + dir + "/n.cube) stores the same LUT as row 0 (neutral)"),
              std::string::npos)
        << r.err;
    // 16^3 and 17^3 rows: refused unless --size asks for resampling.
    r = runCli("atlas build " + shellQuoted(dir + "/a.cube") + " " + shellQuoted(dir + "/c.cube") +
               " -o " + out + " --layout unreal");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("row 1 (" + dir + "/c.cube) is 17^3, the atlas's rows are 16^3"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/x.png"));
    r = runCli("atlas build " + shellQuoted(dir + "/a.cube") + " " + shellQuoted(dir + "/c.cube") +
               " -o " + out + " --layout unreal --size 16");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("17^3 resampled to 16^3"), std::string::npos) << r.out;
    EXPECT_EQ(formats::readImageInfo(dir + "/x.png").height, 32);
    // The output is never an input.
    r = runCli("atlas build " + shellQuoted(dir + "/x.png") + " -o " + out + " -y");
    EXPECT_EQ(r.exitCode, 1) << r.err;
}

TEST(CliAtlas, InfoSaysHowManyRowsAndRefusesPartialRows) {
    const std::string dir = workDir();
    // A 1024x100 picture: 3 rows of 32 and 4 pixels.
    formats::writeImage(dir + "/cut.png", Image(1024, 100, 0.5f), {8, false, true});
    RunResult r = runCli("atlas info " + shellQuoted(dir + "/cut.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("3 rows and 4 pixels: row 3 is cut short"), std::string::npos) << r.err;
    formats::writeImage(dir + "/wide.png", Image(1000, 32, 0.5f), {8, false, true});
    r = runCli("atlas info " + shellQuoted(dir + "/wide.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("its width must be N^2"), std::string::npos) << r.err;
    // A Unity atlas of two rows is read as unity-32, found from its rows.
    writeTable(dir + "/a.cube", 32, warm);
    writeTable(dir + "/b.cube", 32, sepia);
    ASSERT_EQ(runCli("atlas build " + shellQuoted(dir + "/a.cube") + " " +
                     shellQuoted(dir + "/b.cube") + " -o " + shellQuoted(dir + "/u.png") +
                     " --layout unity-32")
                  .exitCode,
              0);
    r = runCli("atlas info " + shellQuoted(dir + "/u.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("rows     2"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("layout   unity-32 (detected"), std::string::npos) << r.out;
}

TEST(CliAtlas, BadUsageExitsTwo) {
    const std::string dir = workDir();
    writeTable(dir + "/a.cube", 4, warm);
    for (const std::string& line : std::vector<std::string>{
             "atlas stack a.cube -o x.png", "atlas build -o " + shellQuoted(dir + "/x.png"),
             "atlas build " + shellQuoted(dir + "/a.cube"),
             "atlas split a.png b.png -o " + shellQuoted(dir + "/"), "atlas info a.png --size 16",
             "atlas build " + shellQuoted(dir + "/a.cube") + " -o " + shellQuoted(dir + "/x.png") +
                 " --layout reshade --size 16",
             "atlas build " + shellQuoted(dir + "/a.cube") + " -o " + shellQuoted(dir + "/x.png") +
                 " --layout hald"}) {
        const RunResult r = runCli(line);
        EXPECT_EQ(r.exitCode, 2) << line << ": " << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir + "/x.png"));
}

// `atlas split -o rows/` makes the folder when it is missing, as `apply -o DIR/` does (issue 43:
// it refused it); a file in the way is refused, and a bad atlas leaves no folder behind.
TEST(CliAtlas, SplitMakesAMissingFolder) {
    const std::string dir = workDir();
    writeTable(dir + "/warm.cube", 8, warm);
    writeTable(dir + "/cool.cube", 8, cool);
    ASSERT_EQ(runCli("atlas build " + shellQuoted(dir + "/warm.cube") + " " +
                     shellQuoted(dir + "/cool.cube") + " -o " + shellQuoted(dir + "/atlas.png"))
                  .exitCode,
              0);
    for (const std::string out : {"rows/", "more/rows"}) {
        SCOPED_TRACE(out);
        const RunResult r = runCli("atlas split " + shellQuoted(dir + "/atlas.png") + " -o " +
                                   shellQuoted(dir + "/" + out));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_TRUE(std::filesystem::is_directory(dir + "/" + out));
        EXPECT_TRUE(std::filesystem::exists(dir + "/" + out + "/atlas-00.png"));
        EXPECT_TRUE(std::filesystem::exists(dir + "/" + out + "/atlas-01.png"));
    }
    std::ofstream(dir + "/file") << "x";
    RunResult r = runCli("atlas split " + shellQuoted(dir + "/atlas.png") + " -o " +
                         shellQuoted(dir + "/file"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("not a folder"), std::string::npos) << r.err;
    r = runCli("atlas split " + shellQuoted(dir + "/missing.png") + " -o " +
               shellQuoted(dir + "/none/"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_FALSE(std::filesystem::exists(dir + "/none"));
}

// A row from the game's LUT (a .nutexb, builtin:smash-default) is stored as it is, with a warning
// naming it: an engine applies an atlas row to its picture, where the game's compensation for
// its brighten pass would show brighter than the edit. An edit's row says nothing of the kind.
TEST(CliAtlas, AGameLutRowIsStoredAsItIsWithAWarning) {
    const std::string dir = workDir();
    writeTable(dir + "/warm.cube", 32, warm);
    RunResult r = runCli("atlas build " + shellQuoted(dir + "/warm.cube") +
                         " builtin:smash-default -o " + shellQuoted(dir + "/a.png") + " --size 32");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("builtin:smash-default: warning: what it is for: smash"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("--target raw` gives the edit it makes"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("warm.cube: warning: what it is for"), std::string::npos) << r.err;
}
