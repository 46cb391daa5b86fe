// SPDX-License-Identifier: Apache-2.0
// The Smash LUT for an edit made on the game's picture (the exact composition of
// lut/smash/SmashAuthoring.h) against the game's shader in float64 (PipelineTestUtil.h, from
// docs/specs/smash-pipeline.md): at every lattice input the game, run with the returned LUT, shows
// the edit of what it showed before. Also the screenshot/scene rule (lut/pipeline/SceneKind.h).
#include "PipelineTestUtil.h"

#include "lut/Error.h"
#include "lut/pipeline/SceneKind.h"
#include "lut/smash/SmashAuthoring.h"

#include <gtest/gtest.h>

using namespace lut;
using namespace lut::test;

namespace {

// The game LUT the exact composition gives for `edit` (lut/smash/SmashAuthoring.h): what
// `convert --target smash`, extract and the editor's Smash export ship when not refined.
Lut3D exactGameLut(const Lut3D& edit, const Lut3D* game = nullptr) {
    SmashAuthoringOptions o;
    o.gameLut = game;
    o.measure = false;
    return authorSmashLutForEdit(edit, Interpolation::Trilinear, o).exact;
}

// What the screen shows (sRGB-encoded) for the gamma-space lattice input s with game LUT `game`.
void gameDisplay(const Lut3D& game, const double s[3], double out[3]) {
    double x[3];
    for (int c = 0; c < 3; ++c)
        x[c] = std::pow(s[c], 1.0 / 0.454545); // the shader encodes with pow(x, 0.454545)
    double g[3];
    refSmashGrade(game, x, 1.0, g);
    for (int c = 0; c < 3; ++c)
        out[c] = refSrgbEncode(g[c]);
}

// A per-channel affine edit a*d + b on display colours, as a 33^3 LUT over [0,1] (trilinear
// reproduces it exactly there).
Lut3D affineEdit(const double a[3], const double b[3]) {
    Lut3D e(33);
    for (int z = 0; z < 33; ++z)
        for (int y = 0; y < 33; ++y)
            for (int x = 0; x < 33; ++x) {
                const double in[3] = {x / 32.0, y / 32.0, z / 32.0};
                glm::vec3 v;
                for (int c = 0; c < 3; ++c)
                    v[c] = static_cast<float>(a[c] * in[c] + b[c]);
                e.at(x, y, z) = v;
            }
    return e;
}

// What the edited screenshot shows: the edit of the displayed (clipped) colour, clipped.
double affineRef(double d, double a, double b) {
    return std::clamp(a * std::clamp(d, 0.0, 1.0) + b, 0.0, 1.0);
}

} // namespace

TEST(SmashDisplayEdit, NeutralEditGivesTheGameLutBack) {
    const Lut3D neutral = Lut3D::identity(33);
    const Lut3D id = exactGameLut(neutral);
    ASSERT_EQ(id.size(), 16);
    double worst = 0;
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r)
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::abs(double(id.at(r, g, b)[c]) - (c == 0   ? r
                                                                                  : c == 1 ? g
                                                                                           : b) /
                                                                                     15.0));
    EXPECT_LT(worst, 2e-6); // well inside an 8-bit rounding step: the nutexb is the neutral LUT

    const Lut3D game = makeWarmLut(16);
    const Lut3D back = exactGameLut(neutral, &game);
    worst = 0;
    for (std::size_t i = 0; i < game.entryCount(); ++i)
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst,
                             std::abs(double(back.entries()[i][c]) - double(game.entries()[i][c])));
    EXPECT_LT(worst, 2e-6);
}

TEST(SmashDisplayEdit, GameShowsTheEditOfItsOwnPicture) {
    const double a[3] = {0.8, 1.1, 0.7}, b[3] = {0.1, -0.02, 0.05};
    const Lut3D edit = affineEdit(a, b);
    const Lut3D neutral16 = Lut3D::identity(16);
    const Lut3D warm = makeWarmLut(16);
    for (const Lut3D* game : {&neutral16, &warm}) {
        const Lut3D lut = exactGameLut(edit, game == &neutral16 ? nullptr : game);
        double worst = 0;
        int above = 0;
        for (int k = 0; k < 16; ++k)
            for (int j = 0; j < 16; ++j)
                for (int i = 0; i < 16; ++i) {
                    const double s[3] = {i / 15.0, j / 15.0, k / 15.0};
                    double before[3], after[3];
                    gameDisplay(*game, s, before);
                    gameDisplay(lut, s, after);
                    for (int c = 0; c < 3; ++c) {
                        above += before[c] > 1.0;
                        const double want = affineRef(before[c], a[c], b[c]);
                        if (want <= 0.0)
                            continue; // below black the game clamps: nothing to show
                        worst = std::max(worst, std::abs(std::min(after[c], 1.0) - want));
                    }
                }
        EXPECT_LT(worst, 2e-5) << (game == &neutral16 ? "neutral game" : "warm game");
        EXPECT_GT(above, 0); // colours the display clips were exercised
    }
}

TEST(SceneKind, IntegerFilesAreScreenshotsFloatFilesScenes) {
    EXPECT_EQ(detectSceneKind(false), SceneKind::Screenshot);
    EXPECT_EQ(detectSceneKind(true), SceneKind::Scene);
    for (SceneKind k : {SceneKind::Screenshot, SceneKind::Scene})
        EXPECT_EQ(parseSceneKind(toString(k)), k);
    EXPECT_THROW(parseSceneKind("linear"), Error);
}
