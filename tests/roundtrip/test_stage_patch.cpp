// SPDX-License-Identifier: Apache-2.0
// embed --original-lut: the patch holds the colours the game displays for its 16^3 LUT inputs with
// the stage's LUT, so extract reads the edit exactly where the compensation needs it. Checked
// against the game written out in float64 from docs/specs/smash-pipeline.md.
#include "RoundtripTestUtil.h"
#include "TruthOracle.h"

#include "lut/roundtrip/Embed.h"
#include "lut/roundtrip/Extract.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace lut;
using namespace lut::rt;

namespace {

Lut3D warmStageLut() {
    Lut3D warm = Lut3D::identity(16);
    for (auto& e : warm.entries())
        e = glm::vec3(std::min(1.0f, e.x * 1.05f + 0.02f), e.y * 0.97f + 0.01f, e.z * 0.92f);
    return warm;
}

// The game's display (float64) for its lattice input s = (r,g,b)/15 when the LUT holds `l`.
double shown(double l, double s) {
    const double r = ((l - s) * 0.99961 + s) * 1.3703;
    return srgbEnc(clamp01(std::pow(std::max(r, 0.0), 2.2)));
}

// What the game shows with the 8-bit `lut` against the edit of what it showed with `stage`, at
// the 16^3 lattice points (8-bit display steps).
double worstAtLattice(const Lut3D& lut, const Lut3D& stage, const Edit& edit, double* mean) {
    double worst = 0.0, sum = 0.0;
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                const int idx[3] = {r, g, b};
                glm::dvec3 before;
                for (int c = 0; c < 3; ++c)
                    before[c] = shown(stage.at(r, g, b)[c], idx[c] / 15.0);
                const glm::dvec3 want = edit(before);
                for (int c = 0; c < 3; ++c) {
                    const double l = fromUnorm8(toUnorm8(lut.at(r, g, b)[c]));
                    const double e = std::fabs(shown(l, idx[c] / 15.0) - clamp01(want[c])) * 255.0;
                    worst = std::max(worst, e);
                    sum += e;
                }
            }
    *mean = sum / (3.0 * 4096.0);
    return worst;
}

// What the game shows with the 8-bit `lut` against the edit of what it showed with `stage`, over
// inputs s on the 61^3 grid (both LUTs sampled trilinearly in float64).
Summary overallTruth(const Lut3D& lut, const Lut3D& stage, const Edit& edit) {
    const Lut3D shipped = rounded8(lut);
    std::vector<double> all;
    for (int b = 0; b <= 60; ++b)
        for (int g = 0; g <= 60; ++g)
            for (int r = 0; r <= 60; ++r) {
                const glm::dvec3 s = glm::dvec3(r, g, b) / 60.0;
                const glm::dvec3 l0 = trilinear(stage, s), l = trilinear(shipped, s);
                glm::dvec3 before;
                for (int c = 0; c < 3; ++c)
                    before[c] = shown(l0[c], s[c]);
                const glm::dvec3 want = edit(before);
                for (int c = 0; c < 3; ++c)
                    all.push_back(std::fabs(shown(l[c], s[c]) - clamp01(want[c])) * 255.0);
            }
    return summarise(all);
}

} // namespace

TEST(StagePatch, ReadsTheEditWhereTheCompensationNeedsIt) {
    const Lut3D warm = warmStageLut();
    const std::pair<const char*, Edit> edits[] = {{"curves", curvesEdit()},
                                                  {"gradient map", warmGradientMap()},
                                                  {"hue shift", hueShiftEdit(40.0)}};
    for (const auto& [name, edit] : edits) {
        // the stage patch, extracted without being told the stage LUT
        Image shot = syntheticScreenshot(kShotWidth, kShotHeight, 8);
        EmbedOptions eo;
        eo.originalLut = &warm;
        embedPatch(shot.view(), eo);
        applyEdit(shot, edit, 8);
        const ExtractResult stage = extractLut(shot.view(), {});
        ASSERT_EQ(stage.target, LutPurpose::Smash);
        double stageMean = 0.0;
        const double stageMax = worstAtLattice(stage.lut, warm, edit, &stageMean);
        // the neutral patch interpolated at the stage's colours (the way without --original-lut)
        Image old = syntheticScreenshot(kShotWidth, kShotHeight, 8);
        embedPatch(old.view(), EmbedOptions{});
        applyEdit(old, edit, 8);
        ExtractOptions o;
        o.originalLut = &warm;
        const ExtractResult interpolated = extractLut(old.view(), o);
        double oldMean = 0.0;
        const double oldMax = worstAtLattice(interpolated.lut, warm, edit, &oldMean);
        std::printf("[ measured ] stage LUT, %-12s game vs edit at the 16^3 points: stage patch "
                    "max %.2f mean %.3f, neutral 12^3 patch interpolated max %.2f mean %.3f 8-bit "
                    "steps\n",
                    name, stageMax, stageMean, oldMax, oldMean);
        // the 8-bit rounding of the patch's input (times the edit's slope), of its output and
        // of the LUT: one to two steps
        EXPECT_LE(stageMax, 2.0) << name;
        EXPECT_LE(stageMean, 0.5) << name;
        EXPECT_LE(stageMax, oldMax + 1e-9) << name;
        // and the printed bounds hold, at the lattice and between its points
        EXPECT_LE(stageMax, stage.expected.atLattice.maxSteps) << name;
        EXPECT_LE(stageMean, stage.expected.atLattice.meanSteps) << name;
        const Summary all = overallTruth(stage.lut, warm, edit);
        std::printf("[ measured ] stage LUT, %-12s over all inputs: true max %.2f mean %.3f p99 "
                    "%.2f, printed %s\n",
                    name, all.max, all.mean, all.p99, stage.expected.overall.str().c_str());
        EXPECT_LE(all.max, stage.expected.overall.maxSteps) << name;
        EXPECT_LE(all.mean, stage.expected.overall.meanSteps) << name;
        EXPECT_LE(all.p99, stage.expected.overall.p99Steps) << name;
        // between the grid's points too: 200,000 random inputs
        const Summary rnd = smashTruthRandom(stage.lut, edit, &warm);
        std::printf("[ measured ] stage LUT, %-12s random inputs: true max %.2f mean %.3f p99 "
                    "%.2f\n",
                    name, rnd.max, rnd.mean, rnd.p99);
        EXPECT_LE(rnd.max, stage.expected.overall.maxSteps) << name;
        EXPECT_LE(rnd.mean, stage.expected.overall.meanSteps) << name;
        EXPECT_LE(rnd.p99, stage.expected.overall.p99Steps) << name;
    }
}
