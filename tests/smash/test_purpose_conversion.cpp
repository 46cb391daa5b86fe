// SPDX-License-Identifier: Apache-2.0
// A LUT made for one purpose turned into another (lut/smash/PurposeConversion.h), against the
// game's model in float64 written here from docs/specs/smash-pipeline.md:
//   - the edit a game LUT makes (smash -> raw): exact at its lattice, and the sampling error it
//     prints is not below the truth measured at 200,000 random colours it did not use;
//   - an edit made into the game's LUT (raw -> smash) shows the edit at the game's lattice; the
//     neutral edit gives the neutral game LUT; a game LUT taken to an edit and back is itself
//     where the display does not clip;
//   - only what is written is computed (the refinement with refine only), the refinement is
//     written only where it won on held-out colours, and the printed maximum of what is written
//     is not below what the game shows at random inputs.
// And the preview recipe (lut/pipeline/PreviewPlan.h): which chain, what is undone, the bloom
// rule, for each kind of picture and preset.
#include "PipelineTestUtil.h"

#include "lut/pipeline/PreviewPlan.h"
#include "lut/smash/PurposeConversion.h"
#include "lut/smash/PurposeOps.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

using namespace lut;
using namespace lut::test;

namespace {

double srgbDecodeRef(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// What the neutral game shows d for: its LUT input s (gamma space), per channel.
double neutralInput(double d) {
    return std::pow(srgbDecodeRef(d), 1.0 / 2.2) / 1.3703;
}

// What the game shows (display-encoded) with LUT `g` at its input s.
void gameShows(const Lut3D& g, const double s[3], double out[3]) {
    double l[3];
    refTrilinear(g, s, l);
    for (int c = 0; c < 3; ++c) {
        const double r = ((l[c] - s[c]) * 0.99961 + s[c]) * 1.3703;
        out[c] = refSrgbEncode(std::min(1.0, std::pow(std::max(r, 0.0), 2.2)));
    }
}

// A steep game LUT: a hard contrast with a clamp, warm; 8-bit as a nutexb holds it.
Lut3D steepGame() {
    Lut3D g(16);
    for (int b = 0; b < 16; ++b)
        for (int gi = 0; gi < 16; ++gi)
            for (int r = 0; r < 16; ++r) {
                const glm::dvec3 s(r / 15.0, gi / 15.0, b / 15.0);
                glm::dvec3 v(std::clamp((s.x - 0.2) * 1.8, 0.0, 1.0), 0.1 + 0.8 * s.y * s.y,
                             0.6 * s.z + 0.25 * s.x);
                for (int c = 0; c < 3; ++c)
                    v[c] = std::round(std::clamp(v[c], 0.0, 1.0) * 255.0) / 255.0;
                g.at(r, gi, b) = glm::vec3(v);
            }
    return g;
}

} // namespace

TEST(PurposeConversion, TheEditOfAGameLutIsExactAtItsLatticeAndItsErrorBoundsTheTruth) {
    for (const Lut3D& game : {makeWarmLut(16), steepGame()}) {
        GameError printed;
        const Lut3D edit = editOfGameLut(game, 33, &printed);
        ASSERT_EQ(edit.size(), 33);
        double atLattice = 0.0;
        for (int b = 0; b < 33; ++b)
            for (int g = 0; g < 33; ++g)
                for (int r = 0; r < 33; ++r) {
                    const double d[3] = {r / 32.0, g / 32.0, b / 32.0};
                    double s[3], want[3];
                    for (int c = 0; c < 3; ++c)
                        s[c] = neutralInput(d[c]);
                    gameShows(game, s, want);
                    for (int c = 0; c < 3; ++c)
                        atLattice =
                            std::max(atLattice, std::fabs(double(edit.at(r, g, b)[c]) - want[c]));
                }
        EXPECT_LT(atLattice * 255.0, 0.01);
        // Between the lattice points: 200,000 random colours the sampling did not use.
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        double truth = 0.0;
        for (int i = 0; i < 200000; ++i) {
            const double d[3] = {u(rng), u(rng), u(rng)};
            double s[3], want[3], got[3];
            for (int c = 0; c < 3; ++c)
                s[c] = neutralInput(d[c]);
            gameShows(game, s, want);
            refTetrahedral(edit, d, got);
            for (int c = 0; c < 3; ++c)
                truth = std::max(truth, std::fabs(got[c] - want[c]) * 255.0);
        }
        std::printf("[ measured ] edit of a game LUT, 33^3: printed max %.3f, truth at 200000 "
                    "random colours %.3f 8-bit steps\n",
                    printed.maxSteps, truth);
        EXPECT_GE(printed.maxSteps, truth);
        EXPECT_GT(truth, 0.0);
    }
}

TEST(PurposeConversion, AnEditMadeIntoTheGamesLutShowsTheEditAtItsLattice) {
    // A per-channel edit of display colours, as a 33^3 LUT (affine: tetrahedral is exact).
    const double a[3] = {0.85, 1.05, 0.7}, o[3] = {0.05, -0.02, 0.1};
    Lut3D edit(33);
    for (int b = 0; b < 33; ++b)
        for (int g = 0; g < 33; ++g)
            for (int r = 0; r < 33; ++r) {
                const double in[3] = {r / 32.0, g / 32.0, b / 32.0};
                edit.at(r, g, b) = glm::vec3(static_cast<float>(a[0] * in[0] + o[0]),
                                             static_cast<float>(a[1] * in[1] + o[1]),
                                             static_cast<float>(a[2] * in[2] + o[2]));
            }
    const PurposeConversion c = convertPurpose(edit, LutPurpose::Raw, LutPurpose::Smash);
    ASSERT_EQ(c.lut.size(), 16);
    const Lut3D neutral = Lut3D::identity(16);
    double worst = 0.0;
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                const double s[3] = {r / 15.0, g / 15.0, b / 15.0};
                double before[3], after[3];
                gameShows(neutral, s, before);
                gameShows(c.lut, s, after);
                for (int ch = 0; ch < 3; ++ch) {
                    const double want = std::clamp(a[ch] * before[ch] + o[ch], 0.0, 1.0);
                    if (before[ch] >= 1.0 - 1e-9 || want <= 0.0)
                        continue; // white (continued above) and black: the display clips
                    worst = std::max(worst, std::fabs(after[ch] - want));
                }
            }
    EXPECT_LT(worst * 255.0, 0.05);
    // Every entry is what a file holds: in [0, 1].
    for (const auto& e : c.lut.entries())
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_TRUE(e[ch] >= 0.0f && e[ch] <= 1.0f);
    // The neutral edit gives the neutral game LUT (the rule above white continues it).
    const PurposeConversion n =
        convertPurpose(Lut3D::identity(33), LutPurpose::Raw, LutPurpose::Smash);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r)
                for (int ch = 0; ch < 3; ++ch)
                    ASSERT_NEAR(n.lut.at(r, g, b)[ch],
                                (ch == 0   ? r
                                 : ch == 1 ? g
                                           : b) /
                                    15.0,
                                2e-6);
    // The same purpose: the table as it is.
    const PurposeConversion same = convertPurpose(edit, LutPurpose::Raw, LutPurpose::Raw);
    EXPECT_FALSE(same.converted());
    EXPECT_EQ(same.lut.entries(), edit.entries());
}

TEST(PurposeConversion, AGameLutToAnEditAndBackIsItselfBelowWhite) {
    const Lut3D game = makeWarmLut(16);
    const Lut3D edit = editOfGameLut(game, 65);
    const PurposeConversion back = convertPurpose(edit, LutPurpose::Raw, LutPurpose::Smash);
    double worst = 0.0;
    for (int b = 0; b < 11; ++b) // s = i/15 <= 10/15: the neutral game does not clip
        for (int g = 0; g < 11; ++g)
            for (int r = 0; r < 11; ++r)
                for (int c = 0; c < 3; ++c)
                    worst = std::max(
                        worst, std::fabs(double(back.lut.at(r, g, b)[c]) - game.at(r, g, b)[c]));
    EXPECT_LT(worst * 255.0, 1.0); // the 65^3 edit's interpolation, under an 8-bit step
}

TEST(PurposeConversion, OnlyWhatIsWrittenIsComputedAndTheRefinementShipsOnlyWhereItWins) {
    // bounds' rule kept in the one conversion: without refine the refinement is not computed and
    // the exact composition (clamped) is written; with refine it is written only when it beat
    // the exact composition on colours it was not fitted on. Either way the printed maximum of
    // what is written bounds what the game shows (the float64 model above) at 20,000 random
    // inputs, the 8-bit LUT as the file holds it.
    const double a[3] = {1.2, 0.9, 1.1}, o[3] = {-0.04, 0.03, -0.02};
    Lut3D edit(33);
    for (int b = 0; b < 33; ++b)
        for (int g = 0; g < 33; ++g)
            for (int r = 0; r < 33; ++r) {
                const double in[3] = {r / 32.0, g / 32.0, b / 32.0};
                for (int c = 0; c < 3; ++c)
                    edit.at(r, g, b)[c] = static_cast<float>(a[c] * in[c] + o[c]);
            }
    for (const bool refine : {false, true}) {
        SCOPED_TRACE(refine ? "refine" : "exact");
        PurposeOptions po;
        po.measure = true;
        po.refine = refine;
        const PurposeConversion c = convertPurpose(edit, LutPurpose::Raw, LutPurpose::Smash, po);
        const SmashAuthoringResult& r = c.authoring;
        EXPECT_EQ(r.refinementComputed, refine);
        EXPECT_EQ(r.decision.empty(), !refine);
        if (r.refined) {
            EXPECT_LT(r.heldOutRefined.meanSteps, r.heldOutExact.meanSteps);
        } else {
            for (std::size_t i = 0; i < c.lut.entryCount(); ++i)
                for (int ch = 0; ch < 3; ++ch)
                    ASSERT_EQ(c.lut.entries()[i][ch],
                              std::clamp(r.exact.entries()[i][ch], 0.0f, 1.0f));
        }
        Lut3D file = c.lut; // the 8-bit entries the .nutexb holds
        for (auto& e : file.entries())
            for (int ch = 0; ch < 3; ++ch)
                e[ch] = static_cast<float>(std::round(double(e[ch]) * 255.0) / 255.0);
        const Lut3D neutral = Lut3D::identity(16);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        double worst = 0.0;
        for (int i = 0; i < 20000; ++i) {
            const double in[3] = {u(rng), u(rng), u(rng)};
            double before[3], after[3];
            gameShows(neutral, in, before);
            gameShows(file, in, after);
            for (int ch = 0; ch < 3; ++ch) {
                const double want = a[ch] * before[ch] + o[ch];
                if (before[ch] >= 1.0 - 1e-9 || want <= 0.0 || want >= 1.0)
                    continue; // the display clips
                worst = std::max(worst, std::fabs(after[ch] - want) * 255.0);
            }
        }
        const GameError& printed = r.refined ? r.refinedError : r.exactError;
        std::printf("[ measured ] %s: written %s, true max %.3f, printed max %.3f 8-bit steps\n",
                    refine ? "--refine" : "exact", r.refined ? "refined" : "exact", worst,
                    printed.maxSteps);
        EXPECT_LE(worst, printed.maxSteps);
    }
}

TEST(PurposeConversion, ComposeOnTheStagesPictureIsTheStagedCompensation) {
    // B after A with A the game's LUT and a game LUT result: B's edit on A's picture, which is
    // what convert --original-lut A makes of B; at the lattice the game shows B(A's picture).
    const Lut3D stage = makeWarmLut(16);
    Lut3D look = Lut3D::identity(17);
    for (auto& e : look.entries())
        e = glm::vec3(0.9f * e.x + 0.05f, e.y * e.y, 0.8f * e.z + 0.1f);
    const PurposeOpResult r =
        composeForPurpose({&stage, LutPurpose::Smash}, {&look, LutPurpose::Raw}, LutPurpose::Smash);
    EXPECT_FALSE(r.tableOp);
    double worst = 0.0;
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int ri = 0; ri < 16; ++ri) {
                const double s[3] = {ri / 15.0, g / 15.0, b / 15.0};
                double before[3], after[3];
                gameShows(stage, s, before);
                gameShows(r.result.lut, s, after);
                const double want[3] = {0.9 * before[0] + 0.05, before[1] * before[1],
                                        0.8 * before[2] + 0.1};
                for (int c = 0; c < 3; ++c)
                    if (before[c] < 1.0 - 1e-9) // white: continued above, the display clips
                        worst = std::max(worst, std::fabs(after[c] - want[c]));
            }
    EXPECT_LT(worst * 255.0, 0.6); // the look is a 17^3 table: its own interpolation
    // Both edits: the table composition, an edit.
    const PurposeOpResult e =
        composeForPurpose({&look, LutPurpose::Raw}, {&look, LutPurpose::Raw}, LutPurpose::Raw);
    EXPECT_TRUE(e.tableOp);
    EXPECT_TRUE(e.conversions.empty());
    // mix brings both to the result's purpose first
    const PurposeOpResult m =
        mixForPurpose({&look, LutPurpose::Raw}, {&stage, LutPurpose::Smash}, 0.5, LutPurpose::Raw);
    ASSERT_EQ(m.conversions.size(), 1u);
    EXPECT_EQ(m.conversions[0].first, "B");
}

TEST(PreviewPlan, OneRecipeForEveryPictureAndPreset) {
    const SceneEvidence png8{false, 8, "", "png"}, png16{false, 16, "", "png"},
        exr{true, 32, "", "openexr"}, linear16{false, 16, "Linear", "tiff"};
    PreviewRequest q;
    q.evidence = png8;
    PreviewPlan p = planPreview(q);
    EXPECT_EQ(p.chain, PreviewChain::Game);
    EXPECT_TRUE(p.decode && p.undoGrading && !p.displayEncode);
    EXPECT_FALSE(p.bloomAdded); // a screenshot has the game's bloom
    EXPECT_EQ(p.lutPurpose, LutPurpose::Smash);
    EXPECT_NE(p.notes.front().message.find("no bloom added"), std::string::npos);
    q.enable = {"bloom"};
    EXPECT_TRUE(planPreview(q).bloomAdded);
    q.enable.clear();
    q.evidence = png16;
    EXPECT_EQ(planPreview(q).chain, PreviewChain::Game);
    q.evidence = exr;
    p = planPreview(q);
    EXPECT_TRUE(!p.decode && !p.undoGrading && p.bloomAdded);
    q.bloom = false;
    EXPECT_FALSE(planPreview(q).bloomAdded);
    q.bloom = true;
    q.evidence = linear16; // tagged linear: a scene, not decoded
    p = planPreview(q);
    EXPECT_EQ(p.scene.kind, SceneKind::Scene);
    EXPECT_FALSE(p.decode);
    // Another preset: a screenshot gets the LUT on its stored values, a scene the chain.
    q.preset = Preset::Pilot;
    q.evidence = png8;
    p = planPreview(q);
    EXPECT_EQ(p.chain, PreviewChain::EncodedLut);
    EXPECT_TRUE(!p.decode && !p.undoGrading && !p.displayEncode);
    EXPECT_EQ(p.lutPurpose, LutPurpose::Raw);
    q.evidence = exr;
    EXPECT_EQ(planPreview(q).chain, PreviewChain::EngineScene);
    q.preset = Preset::None;
    p = planPreview(q);
    EXPECT_EQ(p.chain, PreviewChain::EncodedLut);
    EXPECT_TRUE(p.displayEncode && !p.decode);
    // A stage LUT a scene cannot use is said.
    q.preset = Preset::Smash;
    p = planPreview(q, true);
    EXPECT_EQ(p.notes.size(), 2u);
    EXPECT_NE(p.notes.back().message.find("--original-lut is ignored"), std::string::npos);
    // Distinct preparations have distinct keys.
    PreviewRequest a, b;
    a.evidence = png8;
    b.evidence = png8;
    b.preset = Preset::None;
    EXPECT_NE(preparationKey(planPreview(a)), preparationKey(planPreview(b)));
    b.forced = SceneKind::Scene;
    b.preset = Preset::Smash;
    EXPECT_NE(preparationKey(planPreview(a)), preparationKey(planPreview(b)));
}
