// SPDX-License-Identifier: Apache-2.0
// The LUT that cancels Smash's brighten step for the preview (lut/smash/SmashCompensation.h)
// against the game's shader evaluated in float64 (PipelineTestUtil.h, from
// docs/specs/smash-pipeline.md).
#include "PipelineTestUtil.h"

#include "lut/pipeline/Pipeline.h"
#include "lut/smash/SmashCompensation.h"

#include <gtest/gtest.h>

using namespace lut;
using namespace lut::test;

namespace {

// Nearest lattice entry, in double.
void refNearest(const Lut3D& lut, const double in[3], double out[3]) {
    const int n = lut.size();
    int i[3];
    for (int c = 0; c < 3; ++c)
        i[c] = static_cast<int>(std::lround(std::clamp(in[c], 0.0, 1.0) * (n - 1)));
    for (int c = 0; c < 3; ++c)
        out[c] = lut.at(i[0], i[1], i[2])[c];
}

double refSrgbDecode(double e) {
    return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}

void refInterp(Interpolation m, const Lut3D& lut, const double in[3], double out[3]) {
    if (m == Interpolation::Tetrahedral)
        refTetrahedral(lut, in, out);
    else if (m == Interpolation::Nearest)
        refNearest(lut, in, out);
    else
        refTrilinear(lut, in, out);
}

} // namespace

TEST(SmashCompensation, WithoutBrightenShowsTheLutAloneBetweenLatticePoints) {
    // Scene values in [0,1] at random (not lattice) points; the smash chain without bloom grades
    // with smashWithoutBrighten(L). Undoing the sRGB display and the 2.2 decode of the output (in
    // double) must give back L(s), s = x^0.454545, interpolated as the pipeline does.
    const Lut3D lut = makeWarmLut(17, 1.5);
    Image scene(61, 7);
    Rng rng(42);
    for (float& v : scene.pixels())
        v = static_cast<float>(0.002 + 0.998 * rng.uniform());
    for (int y = 0; y < scene.height(); ++y)
        for (int x = 0; x < scene.width(); ++x)
            scene.pixel(x, y)[3] = 1.0f;
    for (Interpolation m :
         {Interpolation::Trilinear, Interpolation::Tetrahedral, Interpolation::Nearest}) {
        PipelineSettings settings;
        settings.preset = Preset::Smash;
        settings.bloom = false;
        settings.interpolation = m;
        settings.lut = std::make_shared<const Lut3D>(smashWithoutBrighten(lut));
        const Image got = Pipeline(settings).run(scene);
        double worst = 0;
        for (int y = 0; y < scene.height(); ++y)
            for (int x = 0; x < scene.width(); ++x) {
                double s[3], l[3];
                for (int c = 0; c < 3; ++c)
                    s[c] = std::pow(double(scene.pixel(x, y)[c]), 0.454545);
                refInterp(m, lut, s, l);
                for (int c = 0; c < 3; ++c) {
                    const double shown =
                        std::pow(refSrgbDecode(double(got.pixel(x, y)[c])), 1 / 2.2);
                    worst = std::max(worst, std::abs(shown - l[c]));
                }
            }
        const double bound = smashWithoutBrightenError(lut, m);
        EXPECT_LT(worst, bound + 2e-6) << toString(m);
        if (m == Interpolation::Nearest) {
            // The bound is what nearest really shows, not a loose guess: 1.3703 * 0.00039 / 32.
            EXPECT_NEAR(bound, 1.3703 * (1 - 0.99961) / 32, 1e-9);
            EXPECT_GT(worst, bound / 2);
        } else {
            EXPECT_EQ(bound, 0.0);
        }
    }
}
