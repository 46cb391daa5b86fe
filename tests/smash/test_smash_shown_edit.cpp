// SPDX-License-Identifier: Apache-2.0
// What the game shows with a game LUT, as an edit of the neutral game's picture
// (lut/smash/SmashShownEdit.h), against the game's shader in float64 (PipelineTestUtil.h, from
// docs/specs/smash-pipeline.md): for a display colour d, the neutral game's input s showing it is
// found here by bisection on that shader; the entry must be what the shader shows for s with the
// game LUT, clipped to the display and sRGB-encoded.
#include "PipelineTestUtil.h"

#include "lut/smash/SmashAuthoring.h"
#include "lut/smash/SmashShownEdit.h"

#include <gtest/gtest.h>

using namespace lut;
using namespace lut::test;

namespace {

double shaderShows(const Lut3D& game, const double s[3], int c) {
    double x[3], g[3];
    for (int k = 0; k < 3; ++k)
        x[k] = std::pow(s[k], 1.0 / 0.454545);
    refSmashGrade(game, x, 1.0, g);
    return refSrgbEncode(std::clamp(g[c], 0.0, 1.0));
}

} // namespace

TEST(SmashShownEdit, IsWhatTheShaderShows) {
    const Lut3D neutral = Lut3D::identity(16);
    // A game LUT by formula: darker, warmer (trilinear interpolation reproduces it exactly).
    Lut3D game(16);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                const glm::vec3 s = game.latticeInput(r, g, b);
                game.at(r, g, b) = {0.85f * s.r + 0.03f, 0.8f * s.g + 0.01f, 0.75f * s.b};
            }
    for (const Lut3D* lut :
         {static_cast<const Lut3D*>(&neutral), static_cast<const Lut3D*>(&game)}) {
        const Lut3D shown = smashShownEdit(*lut, 9);
        ASSERT_EQ(shown.size(), 9);
        for (int b = 0; b < 9; ++b)
            for (int g = 0; g < 9; ++g)
                for (int r = 0; r < 9; ++r) {
                    const double d[3] = {r / 8.0, g / 8.0, b / 8.0};
                    double s[3];
                    for (int c = 0; c < 3; ++c) { // the smallest neutral input that shows d
                        double lo = 0.0, hi = 1.0;
                        for (int k = 0; k < 80; ++k) {
                            double probe[3] = {0.5 * (lo + hi), 0.5 * (lo + hi), 0.5 * (lo + hi)};
                            (shaderShows(neutral, probe, c) < d[c] - 1e-12 ? lo : hi) = probe[0];
                        }
                        s[c] = 0.5 * (lo + hi);
                    }
                    for (int c = 0; c < 3; ++c) {
                        const double want = lut == &neutral ? d[c] : shaderShows(*lut, s, c);
                        EXPECT_NEAR(shown.at(r, g, b)[c], want, 2e-5) << r << g << b << " " << c;
                    }
                }
    }
}

TEST(SmashShownEdit, ShowsTheEditAGameLutWasMadeFor) {
    // A per-channel edit as a 33^3 LUT; the game LUT made for it shows it back, to the error the
    // game's 16^3 lattice costs (a few 8-bit steps at most, well under one on average).
    Lut3D edit(33);
    for (int b = 0; b < 33; ++b)
        for (int g = 0; g < 33; ++g)
            for (int r = 0; r < 33; ++r) {
                const glm::vec3 d = edit.latticeInput(r, g, b);
                edit.at(r, g, b) = {0.9f * d.r + 0.05f, d.g * d.g * 0.3f + 0.7f * d.g, d.b};
            }
    const Lut3D shown =
        smashShownEdit(authorSmashLutForEdit(edit, Interpolation::Trilinear,
                                             SmashAuthoringOptions{.measure = false})
                           .exact,
                       33);
    double worst = 0.0, mean = 0.0;
    for (std::size_t i = 0; i < edit.entryCount(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double e = 255.0 * std::fabs(shown.entries()[i][c] - edit.entries()[i][c]);
            worst = std::max(worst, e);
            mean += e / (3.0 * edit.entryCount());
        }
    EXPECT_LT(worst, 6.0);
    EXPECT_LT(mean, 0.5);
}
