// SPDX-License-Identifier: Apache-2.0
// The purpose over every pair of formats (issue 40's acceptance): a game LUT (.nutexb) converted
// to writer X, then X to writer Y, then Y back to a .nutexb, is never compensated a second time
// without a warning that names the flag reading it back as the game's (--in-target smash). The
// truth is the game LUT's own entries, written here from a formula: back, every entry within two
// 8-bit codes of them (12-bit and float formats round it, 8-bit ones keep it), or a warning on the
// way. tests/cli/test_purpose_writers.cpp covers one writer at a time with the game's model.
#include "TruthHarness.h"

#include "lut/LutFile.h"
#include "lut/formats/Registry.h"

#include <glm/common.hpp>
#include <gtest/gtest.h>

using namespace lut::truth;

namespace {

// A game LUT: its entries 8-bit, as a .nutexb stores them.
lut::Lut3D gameTable() {
    lut::Lut3D g(16);
    for (int b = 0; b < 16; ++b)
        for (int gi = 0; gi < 16; ++gi)
            for (int r = 0; r < 16; ++r) {
                const glm::dvec3 s(r / 15.0, gi / 15.0, b / 15.0);
                const glm::dvec3 v(std::min(1.0, s.x * 1.12), 0.04 + 0.9 * s.y,
                                   0.75 * s.z + 0.1 * s.x);
                g.at(r, gi, b) = glm::vec3(glm::round(glm::clamp(v, 0.0, 1.0) * 255.0) / 255.0);
            }
    return g;
}

struct Writer {
    const char* format;
    const char* ext;
};
const Writer kWriters[] = {{"cube", ".cube"},   {"strip", ".png"}, {"hald", ".png"},
                           {"spi3d", ".spi3d"}, {"flame", ".3dl"}, {"lustre", ".3dl"},
                           {"csp", ".csp"},     {"clf", ".clf"},   {"ctf", ".ctf"},
                           {"cub", ".cub"},     {"itx", ".itx"},   {"houdini", ".lut"}};

std::string inFormat(const Writer& w) {
    return std::string(w.format) == "hald" ? " --in-format hald" : "";
}

bool warnsWithTheFlag(const lut::test::RunResult& r) {
    const std::string all = r.out + r.err;
    return all.find("warning") != std::string::npos &&
           all.find("--in-target smash") != std::string::npos;
}

} // namespace

bool carriesIt(const Writer& w) {
    const std::string f = w.format;
    return f != "cub" && f != "spi3d" && f != "houdini";
}

class PurposePairs : public ::testing::TestWithParam<Writer> {};

// One test per first writer X (each about 7 s), every second writer Y after it.
TEST_P(PurposePairs, SurvivesOrIsWarnedAbout) {
    lut::formats::registerBuiltinFormats();
    const Writer& x = GetParam();
    const std::string dir = workDir(std::string("purpose-pairs-") + x.format);
    const lut::Lut3D game = gameTable();
    {
        lut::LutFile f;
        f.cube = game;
        lut::formats::writeLut(dir + "/game.nutexb", f);
    }
    int kept = 0, warned = 0;
    const std::string fx = dir + "/x-" + x.format + x.ext;
    const auto wx = lut::test::runCli("convert " + shellQuoted(dir + "/game.nutexb") + " " +
                                      shellQuoted(fx) + " --format " + x.format);
    ASSERT_EQ(wx.exitCode, 0) << wx.err;
    for (const Writer& y : kWriters) {
        const std::string name = std::string(x.format) + "-" + y.format;
        SCOPED_TRACE(name);
        const std::string fy = dir + "/y-" + name + y.ext, back = dir + "/b-" + name + ".nutexb";
        const auto wy = lut::test::runCli("convert " + shellQuoted(fx) + " " + shellQuoted(fy) +
                                          inFormat(x) + " --format " + y.format);
        ASSERT_EQ(wy.exitCode, 0) << wy.err;
        const auto wb =
            lut::test::runCli("convert " + shellQuoted(fy) + " " + shellQuoted(back) + inFormat(y));
        ASSERT_EQ(wb.exitCode, 0) << wb.err;
        const lut::LutFile f = lut::formats::readLut(back);
        ASSERT_TRUE(f.cube && f.cube->size() == 16);
        double codes = 0.0;
        for (std::size_t i = 0; i < game.entryCount(); ++i)
            for (int c = 0; c < 3; ++c)
                codes = std::max(codes, std::fabs(double(f.cube->entries()[i][c]) -
                                                  double(game.entries()[i][c])) *
                                            255.0);
        const bool warning = warnsWithTheFlag(wx) || warnsWithTheFlag(wy) || warnsWithTheFlag(wb);
        EXPECT_TRUE(codes <= 2.0 || warning)
            << "compensated twice, silently: " << codes << " codes\n"
            << wx.out << wy.out << wb.out;
        // a warning only where a file on the way cannot carry it
        EXPECT_EQ(warning, !carriesIt(x) || !carriesIt(y)) << wx.out << wy.out << wb.out;
        (codes <= 2.0 ? kept : warned) += 1;
    }
    std::printf("[ measured ] %s then each of 12 writers: %d back as the game's LUT, %d warned "
                "with the flag\n",
                x.format, kept, warned);
    EXPECT_EQ(kept, carriesIt(x) ? 9 : 0);
}

INSTANTIATE_TEST_SUITE_P(Truth, PurposePairs, ::testing::ValuesIn(kWriters),
                         [](const ::testing::TestParamInfo<Writer>& i) {
                             return std::string(i.param.format);
                         });
