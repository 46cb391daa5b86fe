// SPDX-License-Identifier: Apache-2.0
// The purpose never lost (issue 40): a game LUT written by every writer lutkit has, and by adjust
// and invert, then converted back to a .nutexb, is never compensated a second time without a
// warning that names the flag that reads it back as the game's; the formats with a place for the
// tag keep it (.3dl and .itx in a "#" comment, which OpenColorIO reads past: the same processor
// with and without it). diff compares a game LUT by what the game shows. Oracles: the game's
// model in float64 written here from docs/specs/smash-pipeline.md, OpenColorIO's processor.
#include "CliTestSupport.h"
#include "OcioTestUtil.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/FormatRegistry.h"

#include <OpenColorIO/OpenColorIO.h>
#include <glm/common.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>

namespace OCIO = OCIO_NAMESPACE;
using namespace lut;
using namespace lut::test;

namespace {

// The game's model in float64 (CliTestSupport.h).
using game::gameLut;
using game::gameShows;
using game::srgbDecode;
struct Apart {
    double mean = 0, max = 0;
};
// How far apart the game shows two LUTs, over a 31^3 grid of its inputs, in 8-bit steps.
Apart inGameApart(const Lut3D& a, const Lut3D& b) {
    Apart r;
    double sum = 0;
    int n = 0;
    for (int z = 0; z <= 30; ++z)
        for (int y = 0; y <= 30; ++y)
            for (int x = 0; x <= 30; ++x) {
                const glm::dvec3 s = glm::dvec3(x, y, z) / 30.0;
                const glm::dvec3 d = glm::abs(gameShows(a, s) - gameShows(b, s)) * 255.0;
                for (int c = 0; c < 3; ++c) {
                    sum += d[c];
                    r.max = std::max(r.max, d[c]);
                    ++n;
                }
            }
    r.mean = sum / n;
    return r;
}

Lut3D readGame(const std::string& path) {
    const LutFile f = formats::readLut(path);
    EXPECT_TRUE(f.cube && f.cube->size() == 16) << path;
    return f.cube ? *f.cube : Lut3D(16);
}

constexpr const char* kFlag = "--in-target smash";

} // namespace

TEST(PurposeWriters, EveryWriterKeepsTheGamesLutOrWarnsWithTheFlag) {
    formats::registerBuiltinFormats();
    const std::string dir = workDir();
    const Lut3D game = gameLut();
    {
        LutFile f;
        f.cube = game;
        formats::writeLut(dir + "/game.nutexb", f);
    }
    struct Out {
        std::string format, ext;
    };
    std::vector<Out> outs;
    for (const Format* f : FormatRegistry::instance().all()) {
        if (!f->canWrite() || f->name() == "nutexb")
            continue;
        const auto exts = f->extensions();
        if (f->name() == "strip")
            for (const char* e : {".png", ".tif", ".exr"})
                outs.push_back({"strip", e});
        else
            outs.push_back({f->name(), exts.empty() ? ".png" : exts.front()});
    }
    ASSERT_GE(outs.size(), 14u); // cube, 3 strips, hald, flame, lustre, csp, clf, ctf, cub, itx...
    int kept = 0, warned = 0;
    for (const Out& o : outs) {
        SCOPED_TRACE(o.format + " " + o.ext);
        const std::string file = dir + "/g-" + o.format + o.ext;
        const auto w = runCli("convert " + shellQuoted(dir + "/game.nutexb") + " " +
                              shellQuoted(file) + " --format " + o.format);
        ASSERT_EQ(w.exitCode, 0) << w.err;
        const bool warning = has(w.out + w.err, "warning") && has(w.out + w.err, kFlag);
        const std::string back = dir + "/back-" + o.format + o.ext + ".nutexb";
        const auto r = runCli("convert " + shellQuoted(file) + " " + shellQuoted(back) +
                              (o.format == "hald" ? " --in-format hald" : ""));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const Apart apart = inGameApart(game, readGame(back));
        const bool itself = apart.max < 2.0;
        std::printf("[ measured ] %-7s %-5s: back in game mean %.2f / max %.2f steps from the game "
                    "LUT%s\n",
                    o.format.c_str(), o.ext.c_str(), apart.mean, apart.max,
                    warning ? " (warned)" : "");
        // never compensated twice without a warning naming the flag
        EXPECT_TRUE(itself || warning) << w.out << w.err << r.out;
        EXPECT_FALSE(itself && warning) << "a warning for a file that keeps it: " << w.err;
        if (itself) {
            ++kept;
            EXPECT_TRUE(has(r.out, "smash (the file says so")) << r.out;
            continue;
        }
        ++warned;
        EXPECT_GT(apart.mean, 2.0) << "the warning is needed: compensated twice without the flag";
        // and the flag it names reads it back as the game's
        const std::string again = dir + "/again-" + o.format + o.ext + ".nutexb";
        ASSERT_EQ(runCli("convert " + shellQuoted(file) + " " + shellQuoted(again) + " " + kFlag)
                      .exitCode,
                  0);
        EXPECT_LT(inGameApart(game, readGame(again)).max, 2.0);
    }
    EXPECT_GE(kept, 11);  // cube, 3 strips, hald, flame, lustre, csp, clf, ctf, itx
    EXPECT_EQ(warned, 3); // cub, spi3d, houdini
}

// The tag is a "#" comment OpenColorIO skips: the tagged .3dl and .itx give OCIO's processor
// exactly the same values as the same bytes without the line.
TEST(PurposeWriters, TheTaggedCommentFilesReadIdenticallyInOpenColorIO) {
    const std::string dir = workDir();
    LutFile f;
    f.cube = gameLut();
    f.purpose = LutPurpose::Smash;
    for (const char* name : {"g.3dl", "g.itx"}) {
        SCOPED_TRACE(name);
        const std::string path = dir + "/" + name;
        formats::writeLut(path, f);
        const std::string bytes = fileBytes(path);
        ASSERT_EQ(bytes.rfind("# LUTKIT_PURPOSE smash\n", 0), 0u) << bytes.substr(0, 80);
        EXPECT_EQ(formats::readLut(path).purpose, LutPurpose::Smash);
        const std::string bare = dir + "/bare-" + name;
        {
            std::ofstream out(bare, std::ios::binary);
            out << bytes.substr(bytes.find('\n') + 1);
        }
        const auto tagged = ocioFileProcessor(path);
        const auto plain = ocioFileProcessor(bare);
        std::mt19937 rng(5);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        for (int i = 0; i < 2000; ++i) {
            const glm::vec3 v(u(rng), u(rng), u(rng));
            ASSERT_EQ(ocioEval(tagged, v), ocioEval(plain, v)) << i;
        }
        // and ociochecklut, the program, reads it as it reads the bare file
        const auto a = runCommand("ociochecklut " + shellQuoted(path) + " 0.3 0.6 0.9");
        const auto b = runCommand("ociochecklut " + shellQuoted(bare) + " 0.3 0.6 0.9");
        EXPECT_EQ(a.exitCode, 0) << a.err;
        EXPECT_EQ(a.out, b.out);
    }
}

// adjust and invert keep what the LUT is for: a game LUT adjusted (or inverted) and converted
// back to a .nutexb is not compensated a second time.
TEST(PurposeWriters, AdjustAndInvertKeepTheGamesLut) {
    const std::string dir = workDir();
    const Lut3D game = gameLut();
    LutFile f;
    f.cube = game;
    formats::writeLut(dir + "/game.nutexb", f);
    {
        std::ofstream list(dir + "/neutral.txt");
        list << "# lutkit adjustment list 1\nexposure 0\n";
    }
    const auto a = runCli("adjust " + shellQuoted(dir + "/game.nutexb") + " --adjustments " +
                          shellQuoted(dir + "/neutral.txt") + " " + shellQuoted(dir + "/adj.cube"));
    ASSERT_EQ(a.exitCode, 0) << a.err;
    EXPECT_EQ(formats::readLut(dir + "/adj.cube").purpose, LutPurpose::Smash);
    ASSERT_EQ(
        runCli("convert " + shellQuoted(dir + "/adj.cube") + " " + shellQuoted(dir + "/adj.nutexb"))
            .exitCode,
        0);
    const Apart adj = inGameApart(game, readGame(dir + "/adj.nutexb"));
    std::printf("[ measured ] adjust (neutral list) -> .cube -> .nutexb: in game mean %.3f, max "
                "%.2f steps from the game LUT\n",
                adj.mean, adj.max);
    EXPECT_LT(adj.max, 2.0);

    const auto i = runCli("invert " + shellQuoted(dir + "/game.nutexb") + " " +
                          shellQuoted(dir + "/inv.cube"));
    ASSERT_EQ(i.exitCode, 0) << i.err;
    EXPECT_EQ(formats::readLut(dir + "/inv.cube").purpose, LutPurpose::Smash);
    const auto c = runCli("convert " + shellQuoted(dir + "/inv.cube") + " " +
                          shellQuoted(dir + "/inv.nutexb"));
    ASSERT_EQ(c.exitCode, 0) << c.err;
    EXPECT_TRUE(has(c.out, "in:  smash (the file says so")) << c.out;
    EXPECT_FALSE(has(c.out, "exact composition")) << c.out; // copied, not compensated
}

// diff compares a game LUT by what the game shows: a graded strip and the .nutexb convert made of
// it are what the game model shows to be a fraction of a step apart; on a screenshot, two game
// LUTs are compared at the colours the game shows for each pixel (as preview shows it), the
// printed mean per channel within 0.02 steps of the model's.
TEST(PurposeWriters, DiffComparesWhatTheGameShows) {
    formats::registerBuiltinFormats();
    const std::string dir = workDir();
    const Lut3D game = gameLut();
    LutFile f;
    f.cube = game;
    formats::writeLut(dir + "/a.nutexb", f);
    Lut3D other = game;
    for (auto& e : other.entries())
        e = glm::vec3(
            glm::round(glm::clamp(e * glm::vec3(1.0f, 0.97f, 1.03f), 0.0f, 1.0f) * 255.0f) /
            255.0f);
    f.cube = other;
    formats::writeLut(dir + "/b.nutexb", f);
    // a screenshot: random colours, a quarter of them white in a channel
    Image shot(256, 128);
    std::mt19937 rng(9);
    std::uniform_int_distribution<int> u(0, 255);
    for (std::size_t k = 0; k < shot.pixels().size(); ++k)
        shot.pixels()[k] = k % 4 == 3 ? 1.0f : (u(rng) < 64 ? 1.0f : u(rng) / 255.0f);
    formats::ImageWriteOptions wo;
    wo.alpha = false;
    formats::writeImage(dir + "/shot.png", shot, wo);
    const auto d =
        runCli("diff " + shellQuoted(dir + "/a.nutexb") + " " + shellQuoted(dir + "/b.nutexb") +
               " --image " + shellQuoted(dir + "/shot.png"));
    ASSERT_EQ(d.exitCode, 0) << d.err;
    EXPECT_TRUE(has(d.out, "what the player sees")) << d.out;
    std::smatch m;
    const std::regex re(R"(mean\s+R ([0-9.e-]+)\s+G ([0-9.e-]+)\s+B ([0-9.e-]+))");
    ASSERT_TRUE(std::regex_search(d.out, m, re)) << d.out;
    // the model: what the game shows for each pixel with A and with B; a pixel's input s is
    // where the neutral game shows its colour (white where it starts: 1/1.3703)
    glm::dvec3 sum(0.0);
    for (int y = 0; y < shot.height(); ++y)
        for (int x = 0; x < shot.width(); ++x) {
            glm::dvec3 s;
            for (int c = 0; c < 3; ++c)
                s[c] = std::pow(srgbDecode(shot.pixel(x, y)[c]), 1 / 2.2) / 1.3703;
            sum += glm::abs(gameShows(game, s) - gameShows(other, s)) * 255.0;
        }
    const glm::dvec3 mean = sum / double(shot.width() * shot.height());
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(std::stod(m[c + 1]), mean[c], 0.02) << c;
    std::printf("[ measured ] diff --image of two game LUTs: printed mean %s %s %s, the model "
                "%.3f %.3f %.3f steps\n",
                m[1].str().c_str(), m[2].str().c_str(), m[3].str().c_str(), mean.x, mean.y, mean.z);
}
