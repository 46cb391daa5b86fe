// SPDX-License-Identifier: Apache-2.0
// Smash authoring (lut/smash/SmashAuthoring.h) against the game written out in float64 from
// docs/specs/smash-pipeline.md ("The Smush compensation"): the exact composition at the 16^3
// lattice, the least-squares refinement over the colours that occur, and the error both report.
#include "PipelineTestUtil.h"

#include "lut/smash/SmashAuthoring.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

using namespace lut;
using namespace lut::test;

namespace {

double clampUnit(double v) {
    return std::clamp(v, 0.0, 1.0);
}
double srgbDec(double v) {
    v = clampUnit(v);
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
// What the display shows for the game's LUT input s when the LUT returns l (float64, the spec).
double shown(double l, double s) {
    const double r = ((l - s) * 0.99961 + s) * 1.3703;
    return refSrgbEncode(clampUnit(std::pow(std::max(r, 0.0), 2.2)));
}

// A display edit as a 33^3 LUT: per-channel curves, a little cross-talk and a clamp (a kink).
Lut3D displayEdit() {
    Lut3D e(33);
    for (int b = 0; b < 33; ++b)
        for (int g = 0; g < 33; ++g)
            for (int r = 0; r < 33; ++r) {
                const double R = r / 32.0, G = g / 32.0, B = b / 32.0;
                const double y = 0.2126 * R + 0.7152 * G + 0.0722 * B;
                e.at(r, g, b) =
                    glm::vec3(static_cast<float>(clampUnit(std::pow(R, 0.85) * 1.1 - 0.02)),
                              static_cast<float>(clampUnit(G + 0.15 * (G - y))),
                              static_cast<float>(clampUnit(0.05 + 0.85 * B + 0.1 * y * y)));
            }
    return e;
}

// The exact composition in float64, written from the spec: L = g_s^-1(srgb^-1(E(shown0(s)))),
// and where E is white, the neutral stage's own entry s when it shows white too (the rule above
// white: every entry from g_s^-1(white) up shows white).
Lut3D referenceExact(const Lut3D& edit) {
    Lut3D out(16);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                const double s[3] = {r / 15.0, g / 15.0, b / 15.0};
                double d[3], e[3];
                for (int c = 0; c < 3; ++c)
                    d[c] = shown(s[c], s[c]); // the neutral game
                refTrilinear(edit, d, e);
                for (int c = 0; c < 3; ++c) {
                    const double t = std::pow(srgbDec(clampUnit(e[c])), 1.0 / 2.2);
                    double l = (t / 1.3703 - s[c]) / 0.99961 + s[c];
                    if (e[c] >= 1.0 - 1e-6)
                        l = std::max(l, s[c]);
                    out.at(r, g, b)[c] = static_cast<float>(l);
                }
            }
    return out;
}

struct Stats {
    double max = 0.0, mean = 0.0, rms = 0.0;
};

// What the game shows with the 8-bit `lut` against the edit of what it showed, over inputs on the
// 61^3 grid (the points a refinement is fitted on) or, with `centres`, its 60^3 cell centres
// (the held-out inputs the authoring reports its mean and p99 over).
Stats gameError(const Lut3D& lut, const Lut3D& edit, bool centres = false) {
    Lut3D shipped = lut;
    for (auto& v : shipped.entries())
        for (int c = 0; c < 3; ++c)
            v[c] = static_cast<float>(std::lround(clampUnit(v[c]) * 255.0) / 255.0);
    Stats st;
    double sum = 0.0, sum2 = 0.0;
    std::size_t n = 0;
    const int m = centres ? 60 : 61;
    const double offset = centres ? 0.5 : 0.0;
    for (int b = 0; b < m; ++b)
        for (int g = 0; g < m; ++g)
            for (int r = 0; r < m; ++r) {
                const double s[3] = {(r + offset) / 60.0, (g + offset) / 60.0, (b + offset) / 60.0};
                double d[3], want[3], l[3];
                for (int c = 0; c < 3; ++c)
                    d[c] = shown(s[c], s[c]);
                refTrilinear(edit, d, want);
                refTrilinear(shipped, s, l);
                for (int c = 0; c < 3; ++c) {
                    const double e = std::fabs(shown(l[c], s[c]) - clampUnit(want[c])) * 255.0;
                    st.max = std::max(st.max, e);
                    sum += e;
                    sum2 += e * e;
                    ++n;
                }
            }
    st.mean = sum / double(n);
    st.rms = std::sqrt(sum2 / double(n));
    return st;
}

} // namespace

TEST(SmashAuthoring, ExactCompositionMatchesTheSpecInFloat64) {
    const Lut3D edit = displayEdit();
    SmashAuthoringOptions o;
    o.measure = false;
    const SmashAuthoringResult r = authorSmashLutForEdit(edit, Interpolation::Trilinear, o);
    const Lut3D ref = referenceExact(edit);
    double worst = 0.0;
    for (std::size_t i = 0; i < ref.entryCount(); ++i)
        for (int c = 0; c < 3; ++c)
            worst =
                std::max(worst, std::fabs(double(r.exact.entries()[i][c]) - ref.entries()[i][c]));
    EXPECT_LT(worst, 2e-6);
    // a neutral edit gives the neutral LUT, above white too (the rule above white keeps the
    // stage's own entries where the edit keeps white)
    SmashAuthoringOptions m;
    const SmashAuthoringResult id =
        authorSmashLutForEdit(Lut3D::identity(33), Interpolation::Trilinear, m);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int rr = 0; rr < 16; ++rr)
                for (int c = 0; c < 3; ++c) {
                    const double s = (c == 0 ? rr : c == 1 ? g : b) / 15.0;
                    EXPECT_NEAR(id.lut.at(rr, g, b)[c], s, 1e-5);
                }
    EXPECT_EQ(id.clampedEntries, 0u);
}

TEST(SmashAuthoring, RefinementLowersWhatTheGameShowsOverTheColours) {
    const Lut3D edit = displayEdit();
    SmashAuthoringOptions o;
    o.refine = true;
    const SmashAuthoringResult r = authorSmashLutForEdit(edit, Interpolation::Trilinear, o);
    ASSERT_TRUE(r.refinementComputed);
    ASSERT_TRUE(r.refined) << r.decision;
    const Stats exact = gameError(r.exact, edit, true);
    const Stats refined = gameError(r.lut, edit, true);
    const Stats refinedOnGrid = gameError(r.lut, edit);
    std::printf(
        "[ measured ] game vs edit over the 61^3 inputs: exact max %.2f mean %.3f rms %.3f, "
        "refined max %.2f mean %.3f rms %.3f (reported exact %s; refined %s)\n",
        exact.max, exact.mean, exact.rms, refined.max, refined.mean, refined.rms,
        r.exactError.str().c_str(), r.refinedError.str().c_str());
    // what it reports is what the game shows at inputs it was not fitted on (the grid's cell
    // centres), its maximum bounding every input (the grid it was fitted on included)
    EXPECT_GE(r.exactError.maxSteps, exact.max - 1e-6);
    EXPECT_NEAR(r.exactError.meanSteps, exact.mean, 0.01);
    EXPECT_GE(r.refinedError.maxSteps, refined.max - 1e-6);
    EXPECT_GE(r.refinedError.maxSteps, refinedOnGrid.max - 1e-6);
    EXPECT_NEAR(r.refinedError.meanSteps, refined.mean, 0.01);
    // it was chosen on those held-out inputs
    EXPECT_NEAR(r.heldOutRefined.meanSteps, refined.mean, 0.01);
    EXPECT_NEAR(r.heldOutExact.meanSteps, exact.mean, 0.01);
    // least squares: the squared error falls, and with it the mean
    EXPECT_LT(refined.rms, exact.rms);
    EXPECT_LE(refined.mean, exact.mean);
    // the refinement ships 8-bit values in [0,1]
    for (const auto& v : r.lut.entries())
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(v[c], 0.0f);
            EXPECT_LE(v[c], 1.0f);
            EXPECT_NEAR(v[c] * 255.0f, std::round(v[c] * 255.0f), 1e-3f);
        }
}

TEST(SmashAuthoring, AScreenshotsPixelsAreTheColoursThatOccur) {
    // A screenshot of a few flat colours: the refinement only has to get those right.
    Image shot(64, 64, 1.0f);
    const float colours[4][3] = {
        {0.2f, 0.3f, 0.6f}, {0.8f, 0.5f, 0.1f}, {0.45f, 0.45f, 0.45f}, {1.0f, 1.0f, 1.0f}};
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c)
                shot.pixel(x, y)[c] = colours[(x / 32) + 2 * (y / 32)][c];
    const Lut3D edit = displayEdit();
    SmashAuthoringOptions o;
    o.refine = true;
    const ImageView view = shot.view();
    o.screenshot = &view;
    const SmashAuthoringResult r = authorSmashLutForEdit(edit, Interpolation::Trilinear, o);
    EXPECT_NE(r.measuredOver.find("4096 pixels"), std::string::npos) << r.measuredOver;
    EXPECT_NE(r.measuredOver.find("4 distinct colours"), std::string::npos) << r.measuredOver;
    ASSERT_TRUE(r.refinementComputed);
    std::printf("[ measured ] 4 flat colours: exact %s, refined %s; %s\n",
                r.exactError.str().c_str(), r.refinedError.str().c_str(), r.decision.c_str());
    if (r.refined) {
        // it won on the colour it was not fitted on (by at least the printed 0.001 step), then
        // was fitted on all four: a lower mean, the maximum within the rule's half step
        EXPECT_LE(r.heldOutRefined.meanSteps, r.heldOutExact.meanSteps - 0.001);
        EXPECT_LT(r.refinedError.meanSteps, r.exactError.meanSteps);
        EXPECT_LE(r.refinedError.maxSteps, r.exactError.maxSteps + 0.5);
    } else {
        Lut3D clamped = r.exact;
        for (auto& v : clamped.entries())
            for (int c = 0; c < 3; ++c)
                v[c] = std::clamp(v[c], 0.0f, 1.0f);
        EXPECT_EQ(clamped.entries(), r.lut.entries()) << "the exact composition is written";
    }
}

TEST(SmashAuthoring, TheReportHoldsBetweenItsSamples) {
    // The error is reported on the grid the refinement fits and on that grid's cell centres, its
    // largest value bounded between the grid's samples too; on 200k random inputs the game shows
    // no more than reported (both LUTs), and the same mean.
    const Lut3D edit = displayEdit();
    SmashAuthoringOptions o;
    o.refine = true;
    const SmashAuthoringResult r = authorSmashLutForEdit(edit, Interpolation::Trilinear, o);
    Rng rng(5);
    for (const Lut3D* lut : {&r.exact, &r.lut}) {
        Lut3D shipped = *lut;
        for (auto& v : shipped.entries())
            for (int c = 0; c < 3; ++c)
                v[c] = static_cast<float>(std::lround(clampUnit(v[c]) * 255.0) / 255.0);
        double worst = 0.0, sum = 0.0;
        const int n = 200000;
        for (int i = 0; i < n; ++i) {
            const double s[3] = {rng.uniform(), rng.uniform(), rng.uniform()};
            double d[3], want[3], l[3];
            for (int c = 0; c < 3; ++c)
                d[c] = shown(s[c], s[c]);
            refTrilinear(edit, d, want);
            refTrilinear(shipped, s, l);
            for (int c = 0; c < 3; ++c) {
                const double e = std::fabs(shown(l[c], s[c]) - clampUnit(want[c])) * 255.0;
                worst = std::max(worst, e);
                sum += e;
            }
        }
        const GameError& reported = lut == &r.exact ? r.exactError : r.refinedError;
        std::printf("[ measured ] %s: random inputs max %.2f mean %.3f; reported %s\n",
                    lut == &r.exact ? "exact  " : "refined", worst, sum / (3.0 * n),
                    reported.str().c_str());
        EXPECT_LE(worst, reported.maxSteps + 1e-6);
        EXPECT_NEAR(sum / (3.0 * n), reported.meanSteps, 0.01); // the dense grid's mean
    }
}
