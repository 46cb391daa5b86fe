// SPDX-License-Identifier: Apache-2.0
// HDR up to 1e4, negatives, NaN and Inf: defined (finite) output everywhere, and a NaN pixel does
// not spread through the blurs.
#include "PipelineTestUtil.h"

#include "lut/pipeline/Pipeline.h"
#include "lut/pipeline/Transfer.h"
#include "lut/smash/SmashGrading.h"

#include <gtest/gtest.h>

using namespace lut;
using namespace lut::test;

namespace {

Pipeline everything(Preset pr) {
    Pipeline p(pr);
    for (const auto& n : stageNames())
        p.setEnabled(n, true);
    return p;
}

bool allFinite(const Image& img) {
    for (float v : img.pixels())
        if (!std::isfinite(v))
            return false;
    return true;
}

} // namespace

TEST(PipelineStability, ExtremeValuesGiveFiniteOutput) {
    Image img = makeScene(40, 24, 8, 1.0e4f);
    const float specials[] = {NAN,   INFINITY, -INFINITY, 1e30f,  -1e30f,
                              -5.0f, 1e4f,     -0.0f,     1e-40f, 65504.0f};
    int k = 0;
    for (int y = 0; y < 24; y += 3)
        for (int x = 0; x < 40; x += 5)
            img.pixel(x, y)[k % 4] = specials[k % 10], ++k;
    for (Preset pr : {Preset::Smash, Preset::Pilot, Preset::Lecture, Preset::None}) {
        Image a = img;
        everything(pr).run(a.view());
        EXPECT_TRUE(allFinite(a)) << toString(pr);
        Image b = img;
        Pipeline(pr).run(b.view());
        EXPECT_TRUE(allFinite(b)) << toString(pr);
    }
}

TEST(PipelineStability, NanPixelDoesNotSpreadThroughBloom) {
    for (Preset pr : {Preset::Smash, Preset::Pilot, Preset::Lecture}) {
        Image scene = makeScene(64, 48, 12, 30.0f);
        Image withNan = scene, withZero = scene;
        for (int c = 0; c < 3; ++c) {
            withNan.pixel(30, 20)[c] = NAN;
            withZero.pixel(30, 20)[c] = 0.0f;
        }
        Pipeline p(pr);
        p.run(withNan.view());
        p.run(withZero.view());
        // Sanitize maps NaN to 0 first, so the frame with a NaN equals the frame with a 0.
        EXPECT_EQ(withNan.pixels(), withZero.pixels()) << toString(pr);
        EXPECT_TRUE(allFinite(withNan));
    }
}

TEST(PipelineStability, InfPixelBloomStaysBoundedAndLocal) {
    Image scene(64, 48, 0.1f);
    scene.pixel(32, 24)[0] = INFINITY;
    Pipeline p(Preset::Smash);
    p.setLut(nullptr);
    Image out = scene;
    p.run(out.view());
    ASSERT_TRUE(allFinite(out));
    // Smash bloom clamps its source to [0,1]: the highlight adds at most a bloom of 1 anywhere.
    Image bound(1, 1, 1.1f);
    bound.pixel(0, 0)[3] = 1.0f;
    Pipeline nb(Preset::Smash);
    nb.setBloom(false);
    nb.run(bound.view());
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            if (x != 32 || y != 24) {
                ASSERT_LE(out.pixel(x, y)[0], bound.pixel(0, 0)[0] + 1e-6f) << x << "," << y;
            }
}

TEST(PipelineStability, PowOfNegativesIsDefined) {
    const auto s = makeSampler(Lut3D::identity(16), Interpolation::Trilinear);
    for (float v : {-1.0f, -1e-30f, -0.0f, NAN, -INFINITY, INFINITY}) {
        const glm::vec3 g = smashGrade(glm::vec3(v, 0.5f, v), *s);
        EXPECT_TRUE(std::isfinite(g.x) && std::isfinite(g.y) && std::isfinite(g.z)) << v;
        EXPECT_GE(g.x, 0.0f);
        EXPECT_TRUE(std::isfinite(srgbEncode(v)));
        EXPECT_TRUE(std::isfinite(srgbDecode(v)));
        EXPECT_EQ(gammaEncode(std::min(v, 0.0f), 2.2f), 0.0f);
    }
    EXPECT_EQ(smashEncode(-4.0f), 0.0f);
    EXPECT_EQ(smashDecode(-4.0f), 0.0f);
    EXPECT_FLOAT_EQ(srgbEncode(-0.5f), -srgbEncode(0.5f));
}

TEST(PipelineStability, HdrTenThousandMatchesReference) {
    // 1e4 is inside the sanitize range: the grading follows the formula exactly.
    const Lut3D lut = makeWarmLut(16);
    const auto s = makeSampler(lut, Interpolation::Trilinear);
    Image img(4, 1, 1.0e4f);
    Pipeline p(Preset::Smash);
    p.setLut(std::make_shared<Lut3D>(lut));
    p.setBloom(false);
    p.setEnabled("display", false);
    p.run(img.view());
    const double x[3] = {1e4, 1e4, 1e4};
    double want[3];
    refSmashGrade(lut, x, 1.0, want);
    for (int c = 0; c < 3; ++c)
        EXPECT_LT(relErr(img.pixel(0, 0)[c], want[c]), 1e-5);
}
