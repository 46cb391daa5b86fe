// SPDX-License-Identifier: Apache-2.0
// A game LUT that does not say what it is for, told by its content (issue 40): Smush-LUT's output
// strip, untagged, is the game's LUT; preview shows it as the game does (not compensated a second
// time), with a warning naming the evidence and the flag; a dark edit strip stays an edit. The
// truth is the game's model in float64 written here from docs/specs/smash-pipeline.md, run on the
// scene's own inputs; the game LUT is made by Smush-LUT's formula, also written here.
#include "CliTestSupport.h"

#include "lut/Quantize.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <glm/common.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>

using namespace lut;
using namespace lut::test;

namespace {

// The game's model in float64 (CliTestSupport.h).
using game::gameShows;
using game::srgbDecode;
using game::srgbEncode;

using Edit = std::function<glm::dvec3(glm::dvec3)>;
// Smush-LUT's game LUT for an edit of the neutral stage's screenshot (its formula), 8-bit.
Lut3D smushGameLut(const Edit& e) {
    Lut3D t(16);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                const glm::dvec3 s = glm::dvec3(r, g, b) / 15.0;
                glm::dvec3 shown;
                for (int c = 0; c < 3; ++c)
                    shown[c] = srgbEncode(std::min(1.0, std::pow(1.3703 * s[c], 2.2)));
                const glm::dvec3 w = glm::clamp(e(shown), 0.0, 1.0);
                for (int c = 0; c < 3; ++c) {
                    const double l =
                        (std::pow(srgbDecode(w[c]), 1 / 2.2) / 1.3703 - s[c]) / 0.99961 + s[c];
                    t.at(r, g, b)[c] = fromUnorm8(toUnorm8(static_cast<float>(l)));
                }
            }
    return t;
}

struct Scene {
    std::vector<glm::dvec3> s; // the game's LUT input per pixel (below the white point)
    std::string shot;          // the neutral game's screenshot of it, 8-bit
};
Scene makeScene(const std::string& dir, int w, int h) {
    Scene sc;
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // 8-bit screenshot values below white, and the input each shows exactly
            const glm::dvec3 d(std::round(250.0 * x / (w - 1)), std::round(250.0 * y / (h - 1)),
                               std::round(250.0 * ((x + 2 * y) % w) / (w - 1)));
            glm::dvec3 s;
            for (int c = 0; c < 3; ++c) {
                s[c] = std::pow(srgbDecode(d[c] / 255.0), 1 / 2.2) / 1.3703;
                img.pixel(x, y)[c] = static_cast<float>(d[c] / 255.0);
            }
            img.pixel(x, y)[3] = 1.0f;
            sc.s.push_back(s);
        }
    sc.shot = dir + "/shot.png";
    formats::ImageWriteOptions o;
    o.alpha = false;
    formats::writeImage(sc.shot, img, o);
    return sc;
}

// Mean 8-bit steps between a preview and what the game shows with `game` at each pixel's input.
double meanFrom(const std::string& preview, const Scene& sc, const Lut3D& game) {
    const Image out = formats::readImage(preview).image;
    double sum = 0;
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x) {
            const glm::dvec3 want =
                gameShows(game, sc.s[static_cast<std::size_t>(y) * out.width() + x]);
            for (int c = 0; c < 3; ++c)
                sum += std::fabs(out.pixel(x, y)[c] - want[c]) * 255.0;
        }
    return sum / (3.0 * out.width() * out.height());
}

} // namespace

TEST(PurposeContent, PreviewOfAnUntaggedGameStripShowsWhatTheGameShows) {
    formats::registerBuiltinFormats();
    const std::string dir = workDir();
    const Scene sc = makeScene(dir, 96, 64);
    const Edit warm = [](glm::dvec3 c) {
        return glm::dvec3(0.95 * c.x + 0.04, 0.9 * c.y, 0.75 * c.z + 0.05 * c.x);
    };
    const Lut3D game = smushGameLut(warm);
    LutFile f;
    f.cube = game; // says nothing: Smush-LUT writes no tag
    formats::writeLut(dir + "/game.png", f);
    const auto p =
        runCli("preview " + shellQuoted(sc.shot) + " -o " + shellQuoted(dir + "/seen.png") +
               " --lut " + shellQuoted(dir + "/game.png"));
    ASSERT_EQ(p.exitCode, 0) << p.err;
    EXPECT_TRUE(has(p.err, "warning") && has(p.err, "taken as the game's LUT") &&
                has(p.err, "--lut-target raw"))
        << p.err;
    const double seen = meanFrom(dir + "/seen.png", sc, game);
    // with the flag, the same; as an edit (the flag's other answer), compensated a second time
    ASSERT_EQ(runCli("preview " + shellQuoted(sc.shot) + " -o " + shellQuoted(dir + "/raw.png") +
                     " --lut " + shellQuoted(dir + "/game.png") + " --lut-target raw")
                  .exitCode,
              0);
    const double twice = meanFrom(dir + "/raw.png", sc, game);
    std::printf("[ measured ] preview of an untagged Smush-LUT game strip vs the game's model: "
                "mean %.3f steps (as an edit, --lut-target raw: %.2f)\n",
                seen, twice);
    EXPECT_LT(seen, 1.0);
    EXPECT_GT(twice, 5.0);
}

TEST(PurposeContent, ADarkEditStripStaysAnEdit) {
    formats::registerBuiltinFormats();
    const std::string dir = workDir();
    const Scene sc = makeScene(dir, 64, 48);
    // a strong darkening grade: every value under 186 too, but not flat above the white point
    Lut3D dark = Lut3D::identity(16);
    for (auto& e : dark.entries())
        e = glm::vec3(glm::round(glm::vec3(0.6f * e.x, 0.55f * e.y, 0.7f * e.z) * 255.0f) / 255.0f);
    LutFile f;
    f.cube = dark;
    formats::writeLut(dir + "/dark.png", f);
    const auto p =
        runCli("preview " + shellQuoted(sc.shot) + " -o " + shellQuoted(dir + "/seen.png") +
               " --lut " + shellQuoted(dir + "/dark.png"));
    ASSERT_EQ(p.exitCode, 0) << p.err;
    EXPECT_FALSE(has(p.err, "taken as the game's LUT")) << p.err;
    // as an edit: the preview shows the edit of the screenshot
    const Image shot = formats::readImage(sc.shot).image;
    const Image out = formats::readImage(dir + "/seen.png").image;
    double sum = 0;
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                const double k = c == 0 ? 0.6 : c == 1 ? 0.55 : 0.7;
                sum += std::fabs(out.pixel(x, y)[c] - k * shot.pixel(x, y)[c]) * 255.0;
            }
    const double mean = sum / (3.0 * out.width() * out.height());
    std::printf("[ measured ] preview of a dark edit strip vs the edit: mean %.3f steps\n", mean);
    EXPECT_LT(mean, 1.0);
}
