// SPDX-License-Identifier: Apache-2.0
// lutkit FILE... with no command: the drop (cli/Drop.h, what Windows does for files dropped on
// lutkit.exe). Each file becomes what `lutkit convert FILE color_grading_lut.nutexb` writes
// (that command, run here, is the oracle), beside the file; a .nutexb there is never replaced.
#include "TestSupport.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using lut::test::fileBytes;
using lut::test::runCli;
using lut::test::shellQuoted;
using ::testing::HasSubstr;

namespace {

void writeFile(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

std::string workDir() {
    const std::string d = lut::test::tempDir() + "-drop";
    fs::remove_all(d);
    fs::create_directories(d + "/mod one");
    fs::create_directories(d + "/stage two");
    return d;
}

// An edited strip: a grade stated plainly as a 2^3 .cube, written as a 16^3 strip.
std::string editedStrip(const std::string& dir) {
    const std::string cube = dir + "/swap.cube";
    std::string text = "LUT_3D_SIZE 2\n";
    for (int b = 0; b < 2; ++b)
        for (int g = 0; g < 2; ++g)
            for (int r = 0; r < 2; ++r)
                text += std::to_string(b * 0.9) + " " + std::to_string(g * 0.8 + 0.1) + " " +
                        std::to_string(r * 0.7) + "\n";
    writeFile(cube, text);
    const std::string strip = dir + "/mod one/edited strip.png";
    EXPECT_EQ(
        runCli("convert " + shellQuoted(cube) + " " + shellQuoted(strip) + " --size 16").exitCode,
        0);
    return strip;
}

} // namespace

TEST(CliDrop, FilesAloneBecomeTheGameLutBesideEach) {
    const std::string dir = workDir();
    const std::string strip = editedStrip(dir);
    const std::string cube = dir + "/stage two/look.cube";
    fs::copy_file(dir + "/swap.cube", cube);
    ASSERT_EQ(
        runCli("convert " + shellQuoted(strip) + " " + shellQuoted(dir + "/ref.nutexb")).exitCode,
        0);
    ASSERT_EQ(
        runCli("convert " + shellQuoted(cube) + " " + shellQuoted(dir + "/ref2.nutexb")).exitCode,
        0);

    const auto r = runCli(shellQuoted(strip) + " " + shellQuoted(cube));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string out1 = dir + "/mod one/color_grading_lut.nutexb";
    const std::string out2 = dir + "/stage two/color_grading_lut.nutexb";
    EXPECT_EQ(fileBytes(out1), fileBytes(dir + "/ref.nutexb"));
    EXPECT_EQ(fileBytes(out2), fileBytes(dir + "/ref2.nutexb"));
    EXPECT_THAT(r.out, HasSubstr(strip + " -> " + out1 + "\n"));
    EXPECT_THAT(r.out, HasSubstr("in game")); // convert's report, for each
    EXPECT_THAT(r.out, HasSubstr("2 of 2 dropped files written as the game's LUT"));
}

TEST(CliDrop, AGameLutBesideIsNeverReplaced) {
    const std::string dir = workDir();
    const std::string strip = editedStrip(dir);
    const std::string first = dir + "/mod one/color_grading_lut.nutexb";
    writeFile(first, "the modder's own file");
    const auto r = runCli(shellQuoted(strip));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(fileBytes(first), "the modder's own file");
    const std::string second = dir + "/mod one/color_grading_lut (2).nutexb";
    EXPECT_TRUE(fs::exists(second));
    EXPECT_THAT(r.out, HasSubstr("-> " + second + " (" + first + " is there already and is kept"));
    const auto again = runCli(shellQuoted(strip));
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_TRUE(fs::exists(dir + "/mod one/color_grading_lut (3).nutexb"));
    EXPECT_EQ(fileBytes(second), fileBytes(dir + "/mod one/color_grading_lut (3).nutexb"));
}

TEST(CliDrop, WhatIsNotAStripOrCubeIsRefusedAndTheRestDone) {
    const std::string dir = workDir();
    const std::string strip = editedStrip(dir);
    const std::string game = dir + "/stage two/old.nutexb";
    ASSERT_EQ(runCli("neutral " + shellQuoted(game)).exitCode, 0);
    const auto r = runCli(shellQuoted(game) + " " + shellQuoted(strip));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr(game + ": is a game LUT (.nutexb) already"));
    EXPECT_TRUE(fs::exists(dir + "/mod one/color_grading_lut.nutexb"));
    EXPECT_FALSE(fs::exists(dir + "/stage two/color_grading_lut.nutexb"));
    EXPECT_THAT(r.out, HasSubstr("1 of 2 dropped files written"));
}

TEST(CliDrop, OnlyFilesAloneAreADrop) {
    const std::string dir = workDir();
    const std::string strip = editedStrip(dir);
    // An option with the file: bad usage, nothing written.
    const auto opt = runCli(shellQuoted(strip) + " -y");
    EXPECT_EQ(opt.exitCode, 2);
    EXPECT_THAT(opt.err, HasSubstr("with options: lutkit convert FILE OUT [OPTIONS]"));
    // A file that is not there: bad usage, said so.
    const auto missing = runCli(shellQuoted(dir + "/graded.png"));
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_THAT(missing.err, HasSubstr("and no file of that name"));
    EXPECT_FALSE(fs::exists(dir + "/mod one/color_grading_lut.nutexb"));
    // No arguments: how to use it, and the commands.
    const auto none = runCli("");
    EXPECT_EQ(none.exitCode, 2);
    EXPECT_THAT(none.err, HasSubstr("drop it on lutkit (lutkit.exe on Windows)"));
    EXPECT_THAT(none.err, HasSubstr("A subcommand is required"));
}
