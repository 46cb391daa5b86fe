// SPDX-License-Identifier: Apache-2.0
// Where a LUT goes (lut/formats/LutDestination.h): the user's flags x the output file's kind ->
// the writer, what the LUT is for and why, the lattice and layout. The expected destinations are
// the rules of docs/purpose.md and `lutkit convert --help`, written out row by row.
#include "lut/Error.h"
#include "lut/LutPurpose.h"
#include "lut/formats/LutDestination.h"
#include "lut/formats/RequestError.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>

using namespace lut;
using namespace lut::formats;

namespace {

constexpr auto kRaw = LutPurpose::Raw;
constexpr auto kSmash = LutPurpose::Smash;

struct Row {
    const char* what;
    LutDestinationRequest request;
    const char* writer; // "" = none writes the path
    std::optional<LutPurpose> purpose;
    DestinationPurpose from;
    int size;
    std::optional<LutLayout> layout;
    bool hald;
};

LutDestinationRequest req(std::string path, std::string format = {},
                          std::optional<LutPurpose> purpose = {}, int size = 0,
                          std::optional<LutLayout> layout = {}, int level = 0) {
    return {std::move(path), std::move(format), purpose, size, layout, level};
}

const Row kRows[] = {
    {"a .cube: as the input", req("out.cube"), "cube", std::nullopt, DestinationPurpose::Input, 0,
     std::nullopt, false},
    {"a .nutexb: the game's LUT", req("color_grading_lut.nutexb"), "nutexb", kSmash,
     DestinationPurpose::GameFormat, 0, std::nullopt, false},
    {"a .nutexb with --target raw", req("x.nutexb", "", kRaw), "nutexb", kRaw,
     DestinationPurpose::Said, 0, std::nullopt, false},
    {"a .cube with --target smash", req("x.cube", "", kSmash), "cube", kSmash,
     DestinationPurpose::Said, 0, std::nullopt, false},
    {"standard output, --format nutexb", req("-", "nutexb"), "nutexb", kSmash,
     DestinationPurpose::GameFormat, 0, std::nullopt, false},
    {"--format nutexb over a .cube name", req("x.cube", "nutexb"), "nutexb", kSmash,
     DestinationPurpose::GameFormat, 0, std::nullopt, false},
    {"--format cube over a .nutexb name: a .cube is written", req("x.nutexb", "cube"), "cube",
     std::nullopt, DestinationPurpose::Input, 0, std::nullopt, false},
    {"a .png strip", req("strip.png"), "strip", std::nullopt, DestinationPurpose::Input, 0,
     std::nullopt, false},
    {"a .png strip, --size 33", req("strip.png", "", {}, 33), "strip", std::nullopt,
     DestinationPurpose::Input, 33, std::nullopt, false},
    {"--layout hald on a .png", req("h.png", "", {}, 16, LutLayout::Hald), "strip", std::nullopt,
     DestinationPurpose::Input, 16, LutLayout::Hald, true},
    {"--level 4 on a .png: 16^3 as hald:4", req("h.png", "", {}, 0, {}, 4), "strip", std::nullopt,
     DestinationPurpose::Input, 16, LutLayout::Hald, true},
    {"--level 3 on a .png with --layout hald", req("h.png", "", {}, 0, LutLayout::Hald, 3), "strip",
     std::nullopt, DestinationPurpose::Input, 9, LutLayout::Hald, true},
    {"--level 4 with --format hald", req("h.png", "hald", {}, 0, {}, 4), "hald", std::nullopt,
     DestinationPurpose::Input, 16, std::nullopt, true},
    {"--level 2 to standard output, --format strip", req("-", "strip", {}, 0, {}, 2), "strip",
     std::nullopt, DestinationPurpose::Input, 4, LutLayout::Hald, true},
    {"--level over --size: the level's N", req("h.png", "", {}, 33, {}, 4), "strip", std::nullopt,
     DestinationPurpose::Input, 16, LutLayout::Hald, true},
    {"an extension no format writes", req("x.unknownext"), "", std::nullopt,
     DestinationPurpose::Input, 0, std::nullopt, false},
    {"a .nutexb --target smash --size 16", req("x.nutexb", "", kSmash, 16), "nutexb", kSmash,
     DestinationPurpose::Said, 16, std::nullopt, false},
};

TEST(LutDestination, FlagsTimesFileKind) {
    for (const Row& row : kRows) {
        SCOPED_TRACE(row.what);
        const LutDestination d = resolveLutDestination(row.request);
        EXPECT_EQ(d.writer ? d.writer->name() : std::string(), row.writer);
        EXPECT_EQ(d.purpose, row.purpose);
        EXPECT_EQ(d.purposeFrom, row.from);
        EXPECT_EQ(d.size, row.size);
        EXPECT_EQ(d.layout, row.layout);
        EXPECT_EQ(d.hald, row.hald);
        EXPECT_EQ(d.forGame(), row.purpose == kSmash);
        EXPECT_EQ(d.gameFormat(), std::string(row.writer) == "nutexb");
    }
}

TEST(LutDestination, PurposeFollowsTheInputWhenNothingFixesIt) {
    const LutDestination cube = resolveLutDestination(req("out.cube"));
    EXPECT_EQ(cube.purposeFor(kRaw), kRaw);
    EXPECT_EQ(cube.purposeFor(kSmash), kSmash);
    const LutDestination game = resolveLutDestination(req("out.nutexb"));
    EXPECT_EQ(game.purposeFor(kRaw), kSmash);
    const LutDestination said = resolveLutDestination(req("out.nutexb", "", kRaw));
    EXPECT_EQ(said.purposeFor(kSmash), kRaw);
}

TEST(LutDestination, AHaldLevelOnlyForALutImage) {
    try {
        (void)resolveLutDestination(req("out.cube", "", {}, 0, {}, 4));
        FAIL() << "a Hald level for a .cube was accepted";
    } catch (const RequestError& e) {
        EXPECT_STREQ(e.what(), "--level is a Hald level; out.cube is not a LUT image (use --size)");
    }
    try {
        (void)resolveLutDestination(req("out.png", "", {}, 0, LutLayout::Pilot, 4));
        FAIL() << "a Hald level with the unreal layout was accepted";
    } catch (const RequestError& e) {
        EXPECT_STREQ(e.what(), "--level is a Hald level; the layout is unreal (use --size)");
    }
    EXPECT_THROW((void)resolveLutDestination(req("out.png", "cube", {}, 0, {}, 4)), RequestError);
}

// A new table's size (lutkit neutral, the editor's export targets): the size asked for, else the
// one the format stores (docs/specs/nutexb.md: 16^3; docs/specs/strip-layouts.md: reshade and
// unity-32 are 1024x32, 32^3), else 16^3 for a LUT image (a 256x16 strip, a level-4 Hald), else
// the caller's.
TEST(LutDestination, ANewTableTakesTheSizeTheFormatFixes) {
    struct Case {
        LutDestinationRequest request;
        int fixed;
        bool image;
        int newSize; // newTableSize(33)
    };
    const Case cases[] = {
        {req("out.nutexb"), 16, false, 16},
        {req("out.nutexb", "", {}, 20), 16, false, 20},
        {req("out.png"), 0, true, 16},
        {req("out.png", "", {}, 0, LutLayout::Reshade), 32, true, 32},
        {req("out.png", "", {}, 0, LutLayout::Unity32), 32, true, 32},
        {req("out.png", "", {}, 0, {}, 5), 0, true, 25},
        {req("out.bin", "hald"), 0, true, 16},
        {req("out.cube"), 0, false, 33},
        {req("out.cube", "", {}, 17), 0, false, 17},
    };
    for (const Case& c : cases) {
        const LutDestination d = resolveLutDestination(c.request);
        SCOPED_TRACE(c.request.path + " " + c.request.format);
        EXPECT_EQ(d.fixedSize, c.fixed);
        EXPECT_EQ(d.image, c.image);
        EXPECT_EQ(d.newTableSize(33), c.newSize);
    }
    EXPECT_EQ(resolveLutDestination(req("out.cube")).newTableSize(0), 0); // the table's own
}

// The game's own format is told by the file (Windows' drop refuses to convert a .nutexb again).
TEST(LutDestination, TheGamesFormatByThePath) {
    EXPECT_TRUE(isGameFormatPath("stage/color_grading_lut.nutexb"));
    EXPECT_TRUE(isGameFormatPath("STAGE.NUTEXB"));
    EXPECT_FALSE(isGameFormatPath("graded.png"));
    EXPECT_FALSE(isGameFormatPath("grade.cube"));
    EXPECT_FALSE(isGameFormatPath("nutexb"));
}

TEST(LutDestination, NoWriterIsSaidWhenTheCommandWrites) {
    const LutDestination d = resolveLutDestination(req("dir/x.unknownext"));
    EXPECT_EQ(d.writer, nullptr);
    try {
        (void)d.requireWriter();
        FAIL() << "no writer, and requireWriter returned";
    } catch (const RequestError&) {
        FAIL() << "an unwritable extension is bad input, not a RequestError";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "dir/x.unknownext: no format writes '.unknownext' files (name the "
                               "output format: --format)");
    }
}

} // namespace
