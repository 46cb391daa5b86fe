// SPDX-License-Identifier: Apache-2.0
// Screenshot "deprocess": undoing display encode + grading with the original LUT, then grading
// with a new LUT, matches grading the scene with the new LUT directly (bloom off: it cannot be
// undone).
#include "PipelineTestUtil.h"

#include "lut/pipeline/Pipeline.h"
#include "lut/pipeline/PreviewPlan.h"
#include "lut/smash/SmashGrading.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>

using namespace lut;
using namespace lut::test;

namespace {

Image preview(const Image& scene, const std::shared_ptr<const Lut3D>& lut) {
    PipelineSettings s;
    s.preset = Preset::Smash;
    s.lut = lut;
    s.bloom = false;
    Pipeline p(s);
    Image out = scene;
    p.run(out.view());
    return out;
}

Image sceneInGamut(int w, int h, std::uint64_t seed, bool alphaMix) {
    // Linear values whose graded output stays where the LUTs are invertible (s <= 1 / 1.3703 /
    // a little headroom): up to ~0.45 linear, alpha as given.
    Image img(w, h);
    Rng r(seed);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = static_cast<float>(0.45 * r.uniform() * r.uniform() +
                                          0.45 * (c == 1) * r.uniform() * 0.5);
            p[3] = alphaMix ? static_cast<float>(r.uniform() < 0.2   ? 0.0
                                                 : r.uniform() < 0.5 ? 1.0
                                                                     : r.uniform())
                            : 1.0f;
        }
    return img;
}

// A screenshot's preparation for the game's chain (lut/pipeline/PreviewPlan.h, as preview and
// the editor run it): sRGB decode, then the grading undone with the stage LUT (null: neutral).
Diagnostics undoScreenshot(const ImageView& shot, const Lut3D* stageLut) {
    PreviewPlan plan;
    plan.decode = true;
    plan.undoGrading = true;
    return preparePreviewFrame(plan, shot, stageLut);
}

double maxDiff(const Image& a, const Image& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i)
        d = std::max(d, std::fabs(double(a.pixels()[i]) - b.pixels()[i]));
    return d;
}

} // namespace

TEST(Deprocess, RegradingAScreenshotMatchesGradingTheScene) {
    const auto L0 = std::make_shared<const Lut3D>(makeWarmLut(16, 1.0));
    const auto L1 = std::make_shared<const Lut3D>(makeWarmLut(16, -1.5));
    for (bool alphaMix : {false, true}) {
        const Image x = sceneInGamut(37, 23, alphaMix ? 5 : 6, alphaMix);
        Image shot = preview(x, L0);
        const Diagnostics notes = undoScreenshot(shot.view(), L0.get());
        ASSERT_FALSE(notes.empty());
        EXPECT_NE(notes.front().message.find("bloom cannot be undone"), std::string::npos);
        const Image regraded = preview(shot, L1);
        const Image direct = preview(x, L1);
        EXPECT_LT(maxDiff(regraded, direct), 2e-5) << "alphaMix " << alphaMix;
        // The recovered scene itself.
        EXPECT_LT(maxDiff(shot, x), 2e-5);
    }
}

TEST(Deprocess, NeutralOriginalLutIsExact) {
    const auto L1 = std::make_shared<const Lut3D>(makeWarmLut(16));
    const Image x = sceneInGamut(20, 10, 9, false);
    Image shot = preview(x, nullptr);
    undoScreenshot(shot.view(), nullptr);
    EXPECT_LT(maxDiff(shot, x), 1e-5);
    EXPECT_LT(maxDiff(preview(shot, L1), preview(x, L1)), 2e-5);
}

TEST(Deprocess, NeutralUngradeOfAFrameIsThePerPixelInverseBitForBit) {
    // smashUngrade remembers the neutral inverse per channel value (a screenshot has at most 256
    // per channel); every pixel must still get exactly smashGradeInverse's bits, with repeated
    // values, values beyond 1, NaN, and alpha below 1 (the iterative path) mixed in.
    const int w = 256, h = 6;
    Image frame(w, h);
    Rng r(11);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = frame.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = y < 3 ? float(((x * 7 + c * 31 + y * 5) % 256) / 255.0)
                             : float(2.0 * r.uniform() - 0.2);
            p[3] = y == 4 ? float(r.uniform()) : 1.0f;
        }
    frame.pixel(3, 5)[1] = std::numeric_limits<float>::quiet_NaN();
    frame.pixel(4, 5)[2] = 70000.0f;
    const Image before = frame;
    const Lut3D neutral = Lut3D::identity(16);
    const auto sampler = makeSampler(neutral, Interpolation::Trilinear);
    smashUngrade(frame.view(), nullptr, Interpolation::Trilinear, 2);
    int differ = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float* p = before.pixel(x, y);
            const glm::vec3 want =
                smashGradeInverse(glm::vec3(p[0], p[1], p[2]), p[3], *sampler, true);
            const float* got = frame.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                differ += std::memcmp(&got[c], &want[c], sizeof(float)) != 0;
        }
    EXPECT_EQ(differ, 0);
}

TEST(Deprocess, ScalarInverseSolvesTheGrading) {
    const Lut3D lut = makeWarmLut(16, 1.0);
    const auto s = makeSampler(lut, Interpolation::Trilinear);
    Rng r(4);
    for (int i = 0; i < 500; ++i) {
        const glm::vec3 x(float(0.4 * r.uniform()), float(0.4 * r.uniform()),
                          float(0.4 * r.uniform()));
        const float a = i % 3 == 0 ? 1.0f : float(r.uniform());
        const glm::vec3 y = smashGradeMix(x, a, *s);
        bool ok = false;
        const glm::vec3 back = smashGradeInverse(y, a, *s, false, &ok);
        EXPECT_TRUE(ok);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(back[c], x[c], 2e-5) << i;
    }
}

TEST(Deprocess, UnreachableColourIsReportedNotNaN) {
    // A LUT that maps everything to mid grey cannot produce pure red.
    Lut3D flat(16);
    for (auto& e : flat.entries())
        e = glm::vec3(0.5f);
    Image shot(2, 1, 1.0f);
    shot.pixel(0, 0)[1] = shot.pixel(0, 0)[2] = 0.0f;
    const UngradeResult r = smashUngrade(shot.view(), &flat);
    EXPECT_GE(r.unconverged, 1u);
    for (float v : shot.pixels())
        EXPECT_TRUE(std::isfinite(v));
}
