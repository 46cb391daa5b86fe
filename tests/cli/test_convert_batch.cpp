// SPDX-License-Identifier: Apache-2.0
// lutkit convert DIR/ -o OUTDIR/: every LUT file of a folder (a modder's edited strips), each
// under its own name, as one convert of that file would write it, with its in-game error; a bad
// file is listed and the others are still written; existing outputs follow -y/-n.
#include "CliTestSupport.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace lut;
using namespace lut::test;

namespace {

// A graded 256x16 strip (unreal layout), as an image editor saves it: 8-bit.
void writeStrip(const std::string& path, double warmth) {
    Lut3D l(16);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                const glm::vec3 in = l.latticeInput(r, g, b);
                l.at(r, g, b) = glm::vec3(std::min(1.0, in.r * (1 + warmth) + 0.02),
                                          std::pow(in.g, 1.1), in.b * (1 - warmth));
            }
    LutFile f;
    f.cube = l;
    formats::writeLut(path, f, {});
}

} // namespace

TEST(CliConvertBatch, AFolderOfEditedStripsBecomesTheGamesLuts) {
    const std::string dir = workDir();
    std::filesystem::create_directories(dir + "/strips");
    writeStrip(dir + "/strips/arena.png", 0.1);
    writeStrip(dir + "/strips/beach.png", 0.25);
    std::ofstream(dir + "/strips/notes.txt") << "not a LUT\n";
    // The in-game error measured over a small screenshot's colours (--screenshot, as for one
    // file): over the default 61^3 grid it takes seconds per file.
    Image shot(16, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 4; ++c)
                shot.pixel(x, y)[c] =
                    c == 3 ? 1.0f : static_cast<float>((x * 13 + y * 29 + c * 71) % 256) / 255.0f;
    formats::writeImage(dir + "/shot.png", shot, {8, false, false});
    const std::string measured = " --screenshot '" + dir + "/shot.png'";
    const RunResult r = runCli("convert '" + dir + "/strips' -o '" + dir + "/out/'" + measured);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* name : {"arena", "beach"}) {
        const std::string out = dir + "/out/" + name + ".nutexb";
        ASSERT_TRUE(std::filesystem::exists(out)) << r.out;
        EXPECT_NE(r.out.find(std::string(name) + ".png -> " + out + ": in game max"),
                  std::string::npos)
            << r.out;
    }
    // The file one convert writes, byte for byte, with the same in-game error.
    const RunResult one =
        runCli("convert '" + dir + "/strips/beach.png' '" + dir + "/beach_one.nutexb'" + measured);
    ASSERT_EQ(one.exitCode, 0) << one.err;
    EXPECT_EQ(fileBytes(dir + "/out/beach.nutexb"), fileBytes(dir + "/beach_one.nutexb"));
    const std::string key = "exact composition:";
    const std::size_t at = one.out.find(key);
    ASSERT_NE(at, std::string::npos) << one.out;
    std::string error = one.out.substr(at + key.size(), one.out.find('\n', at) - at - key.size());
    error = error.substr(error.find_first_not_of(' '));
    error = error.substr(0, error.find("  ")); // without "(written)"
    EXPECT_NE(r.out.find("beach.nutexb: in game " + error), std::string::npos) << r.out << "\n"
                                                                               << one.out;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out/notes.nutexb"));
    // Again: the outputs exist, refused without -y (nothing written), skipped with -n.
    RunResult again = runCli("convert '" + dir + "/strips' -o '" + dir + "/out/'" + measured);
    EXPECT_EQ(again.exitCode, 1);
    EXPECT_NE(again.err.find("pass -y/--overwrite"), std::string::npos) << again.err;
    again = runCli("convert '" + dir + "/strips' -o '" + dir + "/out/' -n" + measured);
    EXPECT_EQ(again.exitCode, 0) << again.err;
}

TEST(CliConvertBatch, OtherFormatsKeepNamesAndABadFileIsListed) {
    const std::string dir = workDir();
    std::filesystem::create_directories(dir + "/in");
    writeStrip(dir + "/in/a.png", 0.1);
    std::filesystem::copy_file(samplePath("sample_grade.cube"), dir + "/in/b.cube");
    std::ofstream(dir + "/in/c.cube") << "LUT_3D_SIZE 2\n0 0 0\n"; // truncated
    const RunResult r = runCli("convert '" + dir + "/in/' -o '" + dir + "/out/' --format cube");
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("c.cube"), std::string::npos) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir + "/out/a.cube"));
    ASSERT_TRUE(std::filesystem::exists(dir + "/out/b.cube"));
    EXPECT_FALSE(std::filesystem::exists(dir + "/out/c.cube"));
    EXPECT_NE(r.out.find("b.cube -> " + dir + "/out/b.cube: storage max 0"), std::string::npos)
        << r.out;
    // The .cube written from the .cube is its table exactly.
    EXPECT_EQ(formats::readLut(dir + "/out/b.cube").cube->entries(),
              formats::readLut(samplePath("sample_grade.cube")).cube->entries());
    // The strip read as a LUT and written as a .cube: the strip's 8-bit values.
    EXPECT_EQ(formats::readLut(dir + "/out/a.cube").cube->entries(),
              formats::readLut(dir + "/in/a.png").cube->entries());
}

// --strength on a folder: every file's line says the strength it was made at (it did not), and
// each file is what the one-file convert writes at that strength.
TEST(CliConvertBatch, EveryLineSaysTheStrength) {
    const std::string dir = workDir();
    std::filesystem::create_directories(dir + "/in");
    std::filesystem::copy_file(samplePath("sample_grade.cube"), dir + "/in/b.cube");
    const RunResult r =
        runCli("convert '" + dir + "/in/' -o '" + dir + "/out/' --format cube --strength 0.5");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("b.cube -> " + dir + "/out/b.cube: strength 0.5"), std::string::npos)
        << r.out;
    const RunResult one =
        runCli("convert '" + dir + "/in/b.cube' '" + dir + "/one.cube' --strength 0.5 -q");
    ASSERT_EQ(one.exitCode, 0) << one.err;
    EXPECT_EQ(formats::readLut(dir + "/out/b.cube").cube->entries(),
              formats::readLut(dir + "/one.cube").cube->entries());
}

TEST(CliConvertBatch, UsageAndEmptyFolders) {
    const std::string dir = workDir();
    std::filesystem::create_directories(dir + "/empty");
    RunResult r = runCli("convert '" + dir + "/empty' -o '" + dir + "/out/'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("holds no LUT files"), std::string::npos) << r.err;
    std::filesystem::create_directories(dir + "/in");
    writeStrip(dir + "/in/a.png", 0.1);
    r = runCli("convert '" + dir + "/in' '" + dir + "/x.cube' -o '" + dir + "/y.cube'");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    r = runCli("convert '" + dir + "/in' -o '" + dir + "/out/' --json");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    r = runCli("convert '" + dir + "/in/a.png'");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    // A folder IN with a file OUT is a folder given for a LUT file: refused (robust_tests
    // SpecialFiles: "is a directory" for folder.cube), nothing written.
    r = runCli("convert '" + dir + "/in' '" + dir + "/one.cube'");
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(dir + "/in: "), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/one.cube"));
}
