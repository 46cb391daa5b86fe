// SPDX-License-Identifier: Apache-2.0
// invert (lut/ops/Invert.h): round trips close to the identity for invertible LUTs, with the
// bound justified from the interpolation error; finite answers and honest reports for LUTs that
// cannot be inverted; 1D monotone inversion against closed forms.
#include "OpsTestUtil.h"

#include "lut/interp/Sampler.h"
#include "lut/ops/Compose.h"
#include "lut/ops/Invert.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace lut;
using namespace lut::opstest;

namespace {

// A smooth, one-to-one grade that maps the cube onto itself: a different monotone tone curve per
// channel (each fixes 0 and 1) plus a crosstalk bump that vanishes on every face. Its Jacobian
// stays near the identity (diagonal 0.7..1.3, bump slopes <= 0.05 pi), so it is invertible and
// every target in [0, 1]^3 has a preimage.
glm::vec3 cubeGrade(glm::vec3 x) {
    const float bump = 0.05f * std::sin(3.14159265f * x.r) * std::sin(3.14159265f * x.g) *
                       std::sin(3.14159265f * x.b);
    return {x.r + 0.3f * x.r * (1 - x.r) + bump, x.g - 0.2f * x.g * (1 - x.g) - bump,
            x.b + 0.1f * x.b * (1 - x.b) + 0.5f * bump};
}

} // namespace

TEST(Invert, IdentityInvertsToItself) {
    for (int n : {2, 17}) {
        const InvertResult r = invert(Lut3D::identity(n));
        EXPECT_LT(r.lut.maxDeviationFromIdentity(), 1e-6f) << n;
        EXPECT_TRUE(r.report.invertible());
        EXPECT_EQ(r.report.points, static_cast<std::size_t>(n * n * n));
        EXPECT_LT(r.report.roundTrip.maxAbs, 1e-6);
        EXPECT_TRUE(r.report.worst.empty());
    }
}

TEST(Invert, AffineLutInvertsToTheClosedForm) {
    // A(x) = 0.6 x + 0.2 per channel: over its output range [0.2, 0.8] the inverse is
    // (y - 0.2) / 0.6 exactly (both are affine, so interpolation adds nothing).
    const Lut3D a = lutFrom(9, [](glm::vec3 x) { return 0.6f * x + 0.2f; });
    InvertOptions o;
    o.outputRangeDomain = true;
    const InvertResult r = invert(a, o);
    EXPECT_NEAR(r.lut.domainMin().x, 0.2f, 1e-7);
    EXPECT_NEAR(r.lut.domainMax().x, 0.8f, 1e-7);
    for (int b = 0; b < 9; ++b)
        for (int g = 0; g < 9; ++g)
            for (int rr = 0; rr < 9; ++rr) {
                const glm::dvec3 y(r.lut.latticeInput(rr, g, b));
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(r.lut.at(rr, g, b)[c], (y[c] - 0.2) / 0.6, 2e-6);
            }
    EXPECT_TRUE(r.report.invertible());
    // Over the default domain [0, 1], targets below 0.2 or above 0.8 have no preimage.
    const InvertResult d = invert(a);
    std::size_t outside = 0; // lattice points of 9 with some channel outside [0.2, 0.8]
    for (int b = 0; b < 9; ++b)
        for (int g = 0; g < 9; ++g)
            for (int rr = 0; rr < 9; ++rr) {
                auto out = [](int i) { return i < 2 || i > 6; }; // i/8 < 0.2 or > 0.8
                outside += out(rr) || out(g) || out(b);
            }
    EXPECT_EQ(d.report.unreachable, outside);
    EXPECT_EQ(d.report.foldedCells, 0u);
    EXPECT_TRUE(allFinite(d.lut));
}

TEST(Invert, SmoothGradeRoundTripIsCloseToIdentity) {
    // compose(A, invert(A)) differs from the identity by interpolation only: the entries are
    // solved to 1e-5 or better. A is the tetrahedral interpolant of cubeGrade on an N lattice;
    // its exact inverse is piecewise linear with slope jumps of O(h) (h = 1/(N-1)) across A's
    // cells, and sampling that on an N lattice and interpolating again costs O(h^2): about
    // h^2/8 * (|f''| of the inverse, <= 0.6 / 0.7^3 = 1.75 for x + 0.3 x (1 - x), plus the
    // bump's 0.05 pi^2) per axis, ~2e-4 per channel at N = 33. We assert 1e-3 (a quarter of an
    // 8-bit step) and the second order: halving h (N = 17 -> 33) must cut the error at least
    // 2.5 times (4 in the limit). (With A fixed, a finer inverse alone only gains O(h): its
    // target has A's kinks.)
    const Lut3D a = lutFrom(33, cubeGrade);
    const InvertResult r33 = invert(a);
    const InvertResult r17 = invert(lutFrom(17, cubeGrade));
    InvertOptions o;
    o.size = 65;
    const InvertResult r65 = invert(a, o);
    std::printf("[invert] cube grade 33: %s, residual max %.3g, unreachable %zu, "
                "least squares %zu, %.1f ms\n",
                r33.report.roundTrip.str().c_str(), r33.report.maxResidual, r33.report.unreachable,
                r33.report.leastSquares, 1e3 * r33.report.seconds);
    std::printf("[invert] cube grade 17: %s; 33 -> 65: %s, %.1f ms\n",
                r17.report.roundTrip.str().c_str(), r65.report.roundTrip.str().c_str(),
                1e3 * r65.report.seconds);
    EXPECT_TRUE(r33.report.invertible());
    EXPECT_LE(r33.report.maxResidual, 1e-5);
    EXPECT_LE(r33.report.roundTrip.maxAbs, 1e-3);
    EXPECT_LE(r33.report.roundTrip.maxAbs, r17.report.roundTrip.maxAbs / 2.5);
    EXPECT_LT(r65.report.roundTrip.maxAbs, r33.report.roundTrip.maxAbs);
    // The same measure, computed here with the samplers: the report is the truth at its probes.
    const auto fa = makeSampler(a, Interpolation::Tetrahedral);
    const auto fi = makeSampler(r33.lut, Interpolation::Tetrahedral);
    double worst = 0.0;
    for (int k = 0; k <= 64; ++k) {
        const glm::vec3 x(k / 64.0f, 1.0f - k / 64.0f, 0.5f);
        const glm::vec3 back = fi->sample(fa->sample(x));
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, static_cast<double>(std::fabs(back[c] - x[c])));
    }
    EXPECT_LE(worst, r33.report.roundTrip.maxAbs + 1e-7);
    // compose() gives the LUT the report describes.
    const OpResult c = compose(a, r33.lut);
    EXPECT_LE(c.lut.maxDeviationFromIdentity(), r33.report.roundTrip.maxAbs + 1e-6);
}

TEST(Invert, OutsideTheGamutIsLeastSquaresAndReported) {
    // A grade with crosstalk maps the cube onto a warped solid: the inverse's lattice over the
    // bounding box of its outputs has corners no input reaches. Those get the closest reachable
    // answer and are counted; everything is finite.
    const Lut3D a = lutFrom(17, smoothGrade);
    InvertOptions o;
    o.outputRangeDomain = true;
    const InvertResult r = invert(a, o);
    EXPECT_GT(r.report.unreachable, 0u);
    EXPECT_LT(r.report.unreachable, r.report.points);
    EXPECT_EQ(r.report.foldedCells, 0u);
    EXPECT_TRUE(allFinite(r.lut));
    // Inside the gamut (the reached points) the solution is exact.
    const auto fa = makeSampler(a, Interpolation::Tetrahedral);
    const glm::vec3 y = r.lut.latticeInput(8, 8, 8);
    const glm::vec3 back = fa->sample(r.lut.at(8, 8, 8));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(back[c], y[c], 1e-5);
    std::printf("[invert] smooth grade 17 over its output box: %zu of %zu unreachable, %.1f ms\n",
                r.report.unreachable, r.report.points, 1e3 * r.report.seconds);
}

TEST(Invert, CrushedChannelGivesFiniteLeastSquaresAndAReport) {
    // Red is clipped at 0.5: no input reaches a red above 0.5 (and all red inputs above 0.5 give
    // the same output, so cells there are flat).
    const int n = 17;
    const Lut3D a =
        lutFrom(n, [](glm::vec3 x) { return glm::vec3(std::min(x.r, 0.5f), x.g, x.b); });
    const InvertResult r = invert(a);
    EXPECT_TRUE(allFinite(r.lut));
    EXPECT_FALSE(r.report.invertible());
    // Targets with red input 9/16 .. 16/16 (8 of 17 values) are unreachable.
    EXPECT_EQ(r.report.unreachable, static_cast<std::size_t>(8 * n * n));
    EXPECT_EQ(r.report.foldedCells, static_cast<std::size_t>(8 * 16 * 16));
    ASSERT_FALSE(r.report.worst.empty());
    EXPECT_NEAR(r.report.worst.front().residual, 0.5, 1e-6); // red target 1 vs reachable 0.5
    EXPECT_NEAR(r.report.worst.front().reached.r, 0.5f, 1e-6);
    // The least-squares answer is as close as A gets: red output 0.5, green/blue exact.
    const auto fa = makeSampler(a, Interpolation::Tetrahedral);
    for (int b = 0; b < n; b += 4)
        for (int g = 0; g < n; g += 4) {
            const glm::vec3 out = fa->sample(r.lut.at(n - 1, g, b));
            const glm::vec3 target = r.lut.latticeInput(n - 1, g, b);
            EXPECT_NEAR(out.r, 0.5f, 1e-5);
            EXPECT_NEAR(out.g, target.g, 1e-5);
            EXPECT_NEAR(out.b, target.b, 1e-5);
        }
    // Where: each unreachable target counted in its tone band and its hue sector (or neutrals).
    RegionCounts want{};
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int rr = 9; rr < n; ++rr) {
                const RegionOf where = classifyRegion(r.lut.latticeInput(rr, g, b));
                ++want[static_cast<std::size_t>(where.tone)];
                ++want[static_cast<std::size_t>(where.hue)];
            }
    EXPECT_EQ(r.report.unreachableByRegion, want);
}

TEST(Invert, NeverNaNOnExtremeLuts) {
    const Lut3D step = lutFrom(17, [](glm::vec3 x) {
        return x.r < 0.5f ? glm::vec3(0.1f, x.g, x.b) : glm::vec3(0.9f, x.g, x.b);
    });
    const Lut3D folded =
        lutFrom(9, [](glm::vec3 x) { return glm::vec3(4.0f * x.r * (1.0f - x.r), x.b, x.g); });
    for (const Lut3D& l : {withNonFinite(randomLut(9)), step, folded, randomLut(2), Lut3D(2)}) {
        const InvertResult r = invert(l);
        EXPECT_TRUE(allFinite(r.lut)) << l.size();
        EXPECT_TRUE(std::isfinite(r.report.maxResidual));
        EXPECT_TRUE(std::isfinite(r.report.roundTrip.maxAbs));
    }
    EXPECT_EQ(invert(withNonFinite(randomLut(9))).report.sanitizedEntries, 3u);
    EXPECT_GT(invert(folded).report.foldedCells, 0u);
    EXPECT_GT(invert(step).report.unreachable, 0u); // reds strictly between 0.1 and 0.9 jump
}

TEST(Invert, OneDimensionalMonotoneCurves) {
    // y = x^2 (increasing) and y = 1 - x (decreasing) and y = 0.5 (flat) on three channels.
    Lut1D a(257);
    for (int i = 0; i < 257; ++i) {
        const float x = static_cast<float>(i) / 256.0f;
        a[i] = glm::vec3(x * x, 1.0f - x, 0.5f);
    }
    InvertOptions o;
    o.size = 1025;
    const InvertResult1D r = invert(a, o);
    for (int k = 0; k < 1025; ++k) {
        const double y = k / 1024.0;
        // Piecewise-linear x^2 inverted exactly: within the chord error of sqrt at this spacing.
        EXPECT_NEAR(r.lut[k].r, std::sqrt(y), y < 0.01 ? 2e-3 : 1e-4) << y;
        EXPECT_NEAR(r.lut[k].g, 1.0 - y, 1e-6) << y;
    }
    // The flat channel reaches only 0.5: every other target is unreachable.
    EXPECT_EQ(r.report.unreachable, 1024u);
    EXPECT_EQ(r.report.foldedCells, 256u); // the flat channel's 256 segments
    EXPECT_FALSE(r.report.invertible());
    // Non-monotone: first preimage, and a value reached only by dipping after the start.
    Lut1D bump(5);
    const float v[5] = {0.3f, 0.9f, 0.1f, 0.5f, 1.0f};
    for (int i = 0; i < 5; ++i)
        bump[i] = glm::vec3(v[i]);
    const InvertResult1D b = invert(bump, InvertOptions{});
    // Targets 0, 0.25, 0.5, 0.75, 1 (x at 0, 0.25, ..., 1):
    EXPECT_NEAR(b.lut[0].r, 0.5, 1e-6);                  // below every value: closest is 0.1
    EXPECT_NEAR(b.lut[1].r, 0.25 + 0.25 * 0.8125, 1e-6); // reached only on the way down 0.9->0.1
    EXPECT_NEAR(b.lut[2].r, 0.25 / 3.0, 1e-6);           // first preimage, on 0.3 -> 0.9
    EXPECT_NEAR(b.lut[3].r, 0.1875, 1e-6);
    EXPECT_NEAR(b.lut[4].r, 1.0, 1e-6);
    EXPECT_EQ(b.report.unreachable, 3u); // target 0 on each of the three channels
    EXPECT_EQ(b.report.foldedCells, 3u); // the falling segment 0.9 -> 0.1, on each channel
    for (const auto& e : b.lut.entries())
        EXPECT_TRUE(finite3(e));
}

TEST(Invert, SizeTwoAndSpeed) {
    const Lut3D a = lutFrom(2, [](glm::vec3 x) { return 0.8f * x + 0.1f; });
    InvertOptions o;
    o.outputRangeDomain = true;
    const InvertResult r = invert(a, o);
    EXPECT_TRUE(r.report.invertible());
    EXPECT_LT(r.report.roundTrip.maxAbs, 1e-6);
    o.size = 65;
    const InvertResult big = invert(lutFrom(65, cubeGrade), o);
    std::printf("[invert] cube grade 65 -> 65: %.1f ms, %s\n", 1e3 * big.report.seconds,
                big.report.roundTrip.str().c_str());
    EXPECT_EQ(big.report.unreachable, 0u);
}
