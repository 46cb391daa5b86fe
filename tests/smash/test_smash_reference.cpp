// SPDX-License-Identifier: Apache-2.0
// Every Smash stage against the float64 reference in PipelineTestUtil.h (written from
// docs/specs/smash-pipeline.md, not from lutlib), on small odd-sized frames, to 1e-5.
#include "PipelineTestUtil.h"

#include "lut/interp/Sampler.h"
#include "lut/pipeline/Pipeline.h"
#include "lut/pipeline/Transfer.h"
#include "lut/smash/SmashGrading.h"

#include <gtest/gtest.h>

using namespace lut;
using namespace lut::test;

namespace {

struct Size {
    int w, h;
};
const Size kSizes[] = {{64, 48}, {37, 23}, {7, 5}, {3, 2}, {130, 9}};

double maxRelErrRgb(const Image& got, const RefImg& want) {
    double e = 0;
    for (int y = 0; y < got.height(); ++y)
        for (int x = 0; x < got.width(); ++x)
            for (int c = 0; c < 3; ++c)
                e = std::max(e, relErr(got.pixel(x, y)[c], want.at(x, y, c)));
    return e;
}

} // namespace

TEST(SmashReference, BloomStageMatchesFloat64Reference) {
    for (const Size s : kSizes) {
        const Image scene = makeScene(s.w, s.h, 11 + s.w);
        const RefImg sceneRef = toRef(scene);
        const RefImg bloom = refSmashBloom(sceneRef);
        RefImg want(s.w, s.h);
        double maxBloom = 0;
        for (int y = 0; y < s.h; ++y)
            for (int x = 0; x < s.w; ++x)
                for (int c = 0; c < 3; ++c) {
                    want.at(x, y, c) = sceneRef.at(x, y, c) + bloom.at(x, y, c);
                    maxBloom = std::max(maxBloom, bloom.at(x, y, c));
                }
        if (s.w >= 37) {
            ASSERT_GT(maxBloom, 1e-3) << "scene must produce bloom";
        }
        Image got = scene;
        auto stage = makeStage("smash-bloom");
        stage->process(got.view());
        EXPECT_LT(maxRelErrRgb(got, want), 1e-5) << s.w << "x" << s.h;
        for (int y = 0; y < s.h; ++y)
            for (int x = 0; x < s.w; ++x)
                EXPECT_EQ(got.pixel(x, y)[3], scene.pixel(x, y)[3]);
    }
}

TEST(SmashReference, GradeStageMatchesFloat64Reference) {
    const Lut3D lut = makeWarmLut(16);
    for (const Size s : kSizes) {
        const Image scene = makeScene(s.w, s.h, 5 + s.h, 300.0f);
        Image got = scene;
        auto stage = makeStage("smash-grade");
        Pipeline p(Preset::Smash);
        p.setLut(std::make_shared<Lut3D>(lut));
        p.stage("smash-grade").process(got.view());
        RefImg want(s.w, s.h);
        for (int y = 0; y < s.h; ++y)
            for (int x = 0; x < s.w; ++x) {
                const float* q = scene.pixel(x, y);
                const double in[3] = {q[0], q[1], q[2]};
                double o[3];
                refSmashGrade(lut, in, q[3], o);
                for (int c = 0; c < 3; ++c)
                    want.at(x, y, c) = o[c];
            }
        EXPECT_LT(maxRelErrRgb(got, want), 1e-5) << s.w << "x" << s.h;
    }
}

TEST(SmashReference, DisplayStageMatchesPiecewiseSrgb) {
    Image img(37, 23);
    Rng r(3);
    for (auto& v : img.pixels())
        v = static_cast<float>(-0.2 + 3.0 * r.uniform() * r.uniform());
    const Image in = img;
    makeStage("display")->process(img.view());
    for (int y = 0; y < 23; ++y)
        for (int x = 0; x < 37; ++x)
            for (int c = 0; c < 4; ++c) {
                const double want = c == 3 ? in.pixel(x, y)[3] : refSrgbEncode(in.pixel(x, y)[c]);
                EXPECT_LT(relErr(img.pixel(x, y)[c], want), 1e-5);
            }
}

TEST(SmashReference, FullChainMatchesReference) {
    const Lut3D lut = makeWarmLut(16);
    for (const Size s : kSizes) {
        const Image scene = makeScene(s.w, s.h, 99 + s.w * 3);
        Pipeline p(Preset::Smash);
        p.setLut(std::make_shared<Lut3D>(lut));
        Image got = scene;
        p.run(got.view());
        const RefImg sceneRef = toRef(scene);
        const RefImg bloom = refSmashBloom(sceneRef);
        RefImg want(s.w, s.h);
        for (int y = 0; y < s.h; ++y)
            for (int x = 0; x < s.w; ++x) {
                double in[3], o[3];
                for (int c = 0; c < 3; ++c)
                    in[c] = sceneRef.at(x, y, c) + bloom.at(x, y, c);
                refSmashGrade(lut, in, sceneRef.at(x, y, 3), o);
                for (int c = 0; c < 3; ++c)
                    want.at(x, y, c) = refSrgbEncode(o[c]);
            }
        EXPECT_LT(maxRelErrRgb(got, want), 1e-5) << s.w << "x" << s.h;
    }
}

TEST(SmashReference, NeutralLutIsLinearTimesBrighten) {
    // docs: a neutral LUT reduces the pass to linear * 1.3703^2.2 (for s in [0,1]).
    const Lut3D id = Lut3D::identity(16);
    const auto sampler = makeSampler(id, Interpolation::Trilinear);
    for (float x : {0.0f, 0.001f, 0.05f, 0.18f, 0.5f, 0.9f, 1.0f}) {
        const glm::vec3 g = smashGrade(glm::vec3(x), *sampler);
        const double want = std::pow(1.3703 * std::pow(double(x), 0.454545), 2.2);
        EXPECT_NEAR(g.x, want, 1e-6 * std::max(1.0, want)) << x;
        EXPECT_NEAR(g.x, x * std::pow(1.3703, 2.2), 2e-5) << x;
    }
}

TEST(SmashReference, ScalarGradeMatchesReferenceWithAlpha) {
    const Lut3D lut = makeWarmLut(16);
    const auto sampler = makeSampler(lut, Interpolation::Trilinear);
    Rng r(17);
    for (int i = 0; i < 2000; ++i) {
        const double x[3] = {3 * r.uniform(), r.uniform(), r.uniform() * r.uniform()};
        const double a = r.uniform() * 1.4 - 0.2;
        double want[3];
        refSmashGrade(lut, x, a, want);
        const glm::vec3 got =
            smashGradeMix(glm::vec3(float(x[0]), float(x[1]), float(x[2])), float(a), *sampler);
        for (int c = 0; c < 3; ++c)
            EXPECT_LT(relErr(got[c], want[c]), 1e-5);
    }
}

TEST(SmashReference, CompensatedLutReproducesTargetsAtLatticePoints) {
    // Target: a desaturating look given as linear output per lattice input.
    const int n = 16;
    Lut3D target(n);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const double R = r / 15.0, G = g / 15.0, B = b / 15.0;
                const double y = 0.3 * R + 0.6 * G + 0.1 * B;
                const double lin[3] = {std::pow(0.5 * R + 0.5 * y, 2.2),
                                       std::pow(0.5 * G + 0.5 * y, 2.2),
                                       std::pow(0.5 * B + 0.5 * y, 2.2)};
                target.at(r, g, b) = glm::vec3(float(lin[0]), float(lin[1]), float(lin[2]));
            }
    const Lut3D ship = smashCompensateLut(target);
    // Independent check: evaluate the float64 reference grade at x = s^(1/0.454545).
    for (int b = 0; b < n; b += 3)
        for (int g = 0; g < n; g += 5)
            for (int r = 0; r < n; r += 2) {
                const double s[3] = {r / 15.0, g / 15.0, b / 15.0};
                double x[3], out[3];
                for (int c = 0; c < 3; ++c)
                    x[c] = std::pow(s[c], 1 / 0.454545);
                refSmashGrade(ship, x, 1.0, out);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(out[c], target.at(r, g, b)[c], 2e-5);
            }
    // And the closed form of the brighten inverse.
    const glm::vec3 L = smashLutEntryForTarget(glm::vec3(0.25f), glm::vec3(0.4f));
    EXPECT_NEAR(L.x, (std::pow(0.25, 1 / 2.2) / 1.3703 - 0.4) / 0.99961 + 0.4, 1e-6);
}
