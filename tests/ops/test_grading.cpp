// SPDX-License-Identifier: Apache-2.0
// The grading tools added to lut/ops/Adjust.h (tone curves, hue curves, colour wheels, LUT
// strength) against float64 formulas written out here, plus identity, extreme and clipping
// checks.
#include "OpsTestUtil.h"

#include "lut/ops/Adjust.h"
#include "lut/ops/Clipping.h"
#include "lut/ops/Compose.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

using namespace lut;
using namespace lut::opstest;
using glm::dvec3;

namespace {

const dvec3 kLuma{0.2126, 0.7152, 0.0722};

std::vector<dvec3> sampleColors() {
    std::vector<dvec3> v = {{0.9, 0.2, 0.1}, {0.1, 0.8, 0.3}, {0.2, 0.3, 0.9},  {0.7, 0.6, 0.1},
                            {0.6, 0.1, 0.7}, {0.1, 0.6, 0.6}, {0.5, 0.45, 0.4}, {1, 0, 0}};
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 200; ++i)
        v.push_back({u(rng), u(rng), u(rng)});
    return v;
}

void expectNear(dvec3 a, dvec3 b, double tol, const char* what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(a[c], b[c], tol) << what << " channel " << c;
}

} // namespace

TEST(Grading, ToneCurvesMasterThenChannel) {
    // Two-point curves are straight lines: master y = 0.1 + 0.8 x, red y = 0.5 x, blue y = 1 - x.
    const Curve master(CurveKind::Tone, {{0, 0.1}, {1, 0.9}});
    const Curve red(CurveKind::Tone, {{0, 0}, {1, 0.5}});
    const Curve blue(CurveKind::Tone, {{0, 1}, {1, 0}});
    for (dvec3 e : sampleColors()) {
        const dvec3 m = 0.1 + 0.8 * e;
        const dvec3 want{0.5 * m.x, m.y, 1.0 - m.z};
        expectNear(adjustCurves(e, master, red, Curve(), blue), want, 1e-14, "curves");
    }
    // A three-point curve against the value derived by hand in test_curve.cpp.
    const Curve bend(CurveKind::Tone, {{0, 0}, {0.5, 0.25}, {1, 1}});
    expectNear(adjustCurves(dvec3(0.25), bend, Curve(), Curve(), Curve()), dvec3(0.09375), 1e-15,
               "bend");
}

TEST(Grading, HueVsHueRotatesHsvHue) {
    // A constant curve (one point) shifts every hue by 30 degrees keeping HSV S and V.
    const Curve shift(CurveKind::Hue, {{0, 30}});
    for (dvec3 e : sampleColors()) {
        const dvec3 hsv = rgbToHsv(e);
        expectNear(adjustHueCurves(e, shift, Curve(CurveKind::Hue), Curve(CurveKind::Hue)),
                   hsvToRgb(hsv.x + 30.0, hsv.y, hsv.z), 1e-12, "hue shift");
    }
}

TEST(Grading, HueVsSaturationAndLuminance) {
    const Curve none(CurveKind::Hue);
    const Curve halfSat(CurveKind::Hue, {{0, -0.5}});
    const Curve moreLum(CurveKind::Hue, {{0, 0.5}});
    for (dvec3 e : sampleColors()) {
        const double y = glm::dot(e, kLuma);
        expectNear(adjustHueCurves(e, none, halfSat, none), dvec3(y) + 0.5 * (e - y), 1e-14,
                   "hue vs sat");
        const double mx = std::max({e.x, e.y, e.z}), c = mx - std::min({e.x, e.y, e.z});
        const double w = c / std::max(mx, c);
        expectNear(adjustHueCurves(e, none, none, moreLum), e * (1.0 + 0.5 * w), 1e-14,
                   "hue vs lum");
    }
    // A curve that is 1 at red and 0 from yellow to magenta: a green colour (hue 120) is left
    // exactly as it was, a red one (hue 0) gets double saturation.
    const Curve redOnly(CurveKind::Hue, {{0, 1}, {60, 0}, {300, 0}});
    const dvec3 green{0.2, 0.8, 0.2};
    EXPECT_EQ(adjustHueCurves(green, none, redOnly, none), green);
    const dvec3 red{0.8, 0.2, 0.2};
    const double yr = glm::dot(red, kLuma);
    expectNear(adjustHueCurves(red, none, redOnly, none), dvec3(yr) + 2.0 * (red - yr), 1e-14,
               "red only");
}

TEST(Grading, HueCurvesLeaveGreysExactly) {
    const Curve h(CurveKind::Hue, {{0, 90}, {180, -40}});
    const Curve s(CurveKind::Hue, {{0, 1}});
    const Curve l(CurveKind::Hue, {{0, -0.7}});
    for (double v : {0.0, 0.18, 0.5, 1.0, 1.7, -0.2})
        EXPECT_EQ(adjustHueCurves(dvec3(v), h, s, l), dvec3(v));
}

TEST(Grading, ColorWheelOffsetKeepsLuminanceAndPointsAtTheHue) {
    for (double hue = 0; hue < 360; hue += 15) {
        const dvec3 d = colorWheelOffset(hue, 0.1);
        EXPECT_NEAR(glm::dot(d, kLuma), 0.0, 1e-15) << hue;
        EXPECT_NEAR(std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)}), 0.1, 1e-15);
        // The offset moves mid grey towards that hue. Luma-preserving offsets of a pure hue are
        // not exactly HSV-hue preserving, but stay within a few degrees of it.
        const dvec3 hsv = rgbToHsv(dvec3(0.5) + d);
        double diff = std::fabs(hsv.x - hue);
        diff = std::min(diff, 360.0 - diff);
        EXPECT_LT(diff, 12.0) << hue;
    }
    EXPECT_EQ(colorWheelOffset(123, 0.0), dvec3(0.0));
    // Used as lift: white stays white, black moves by the offset (lift formula in Adjust.h).
    Adjustments a;
    a.lift = colorWheelOffset(240, 0.05);
    const dvec3 black = adjustColor(dvec3(0.0), a), white = adjustColor(dvec3(1.0), a);
    expectNear(black, a.lift, 1e-15, "black");
    expectNear(white, dvec3(1.0), 1e-15, "white");
}

TEST(Grading, StrengthMixesWithIdentity) {
    const Lut3D base = lutFrom(9, smoothGrade);
    for (double s : {0.0, 0.3, 1.0, 1.5, 2.0}) {
        Adjustments a;
        a.strength = s;
        const Lut3D out = applyAdjustments(base, a);
        for (int b = 0; b < 9; ++b)
            for (int g = 0; g < 9; ++g)
                for (int r = 0; r < 9; ++r) {
                    const dvec3 in(base.latticeInput(r, g, b)), e(base.at(r, g, b));
                    const dvec3 want = (1.0 - s) * in + s * e;
                    for (int c = 0; c < 3; ++c)
                        EXPECT_FLOAT_EQ(out.at(r, g, b)[c], static_cast<float>(want[c]));
                }
        EXPECT_TRUE(sameBits(out, withStrength(base, s))) << s;
    }
    Adjustments zero;
    zero.strength = 0.0;
    EXPECT_TRUE(sameBits(applyAdjustments(base, zero), Lut3D::identity(9)));
    Adjustments clamped;
    clamped.strength = 7.0; // clamped to 2
    Adjustments two;
    two.strength = 2.0;
    EXPECT_TRUE(sameBits(applyAdjustments(base, clamped), applyAdjustments(base, two)));
}

TEST(Grading, NeutralSettingsGiveExactlyTheSameLut) {
    Adjustments a;
    a.curveMaster = Curve(CurveKind::Tone, {{0, 0}, {0.5, 0.5}, {1, 1}});
    a.curveGreen = Curve(CurveKind::Tone, {{0.2, 0.2}, {0.9, 0.9}});
    a.hueVsHue = Curve(CurveKind::Hue, {{0, 0}, {180, 0}});
    a.hueVsSat = Curve(CurveKind::Hue, {{90, 0}});
    a.lift = colorWheelOffset(90, 0.0);
    EXPECT_TRUE(a.isNeutral());
    for (const Lut3D& base : {Lut3D::identity(17), randomLut(9), withNonFinite(randomLut(5))}) {
        const Lut3D out = applyAdjustments(base, a);
        EXPECT_TRUE(sameBits(out, base)) << "size " << base.size(); // NaN entries included
    }
    Adjustments notNeutral = a;
    notNeutral.hueVsLum = Curve(CurveKind::Hue, {{0, 0.1}});
    EXPECT_FALSE(notNeutral.isNeutral());
}

TEST(Grading, ExtremeSettingsStayFinite) {
    Adjustments a;
    a.exposure = 1e9;
    a.contrast = 1e9;
    a.saturation = -1e300;
    a.temperature = INFINITY;
    a.gammaMaster = 0.0;
    a.gain = dvec3(1e300);
    a.curveMaster = Curve(CurveKind::Tone, {{0, -1e6}, {1e-9, 1e6}, {1, 1e12}});
    a.curveRed = Curve(CurveKind::Tone, {{0, 1}, {1, 0}});
    a.hueVsHue = Curve(CurveKind::Hue, {{0, 1e6}, {1, -1e6}});
    a.hueVsSat = Curve(CurveKind::Hue, {{0, 1e9}, {180, -1e9}});
    a.hueVsLum = Curve(CurveKind::Hue, {{10, 1e12}});
    a.strength = NAN;
    for (const Lut3D& base : {withNonFinite(randomLut(5)), Lut3D::identity(2)}) {
        EXPECT_TRUE(allFinite(applyAdjustments(base, a)));
        a.strength = 2.0;
        EXPECT_TRUE(allFinite(applyAdjustments(base, a)));
    }
}

TEST(Grading, ClippingCountMatchesAPlainCount) {
    Adjustments a;
    a.exposure = 0.7;
    a.saturation = 1.6;
    a.curveMaster = Curve(CurveKind::Tone, {{0, -0.05}, {0.5, 0.55}, {1, 1.1}});
    const Lut3D lut = applyAdjustments(Lut3D::identity(33), a);
    std::size_t outside = 0, below = 0, above = 0, redAbove = 0;
    for (const auto& e : lut.entries()) {
        const bool lo = e.x < 0 || e.y < 0 || e.z<0, hi = e.x> 1 || e.y > 1 || e.z > 1;
        outside += lo || hi;
        below += lo;
        above += hi;
        redAbove += e.x > 1;
    }
    const ClipCount c = countOutOfRange(lut);
    EXPECT_GT(outside, 1000u); // the settings really clip
    EXPECT_EQ(c.entries, lut.entryCount());
    EXPECT_EQ(c.outside, outside);
    EXPECT_EQ(c.below, below);
    EXPECT_EQ(c.above, above);
    EXPECT_EQ(c.channelAbove[0], redAbove);
    EXPECT_EQ(c.nonFinite, 0u);
    EXPECT_EQ(countOutOfRange(Lut3D::identity(33)).outside, 0u);
    const ClipCount nf = countOutOfRange(withNonFinite(Lut3D::identity(5)));
    EXPECT_EQ(nf.nonFinite, 3u);
    EXPECT_EQ(nf.outside, 3u);

    // What a slider move costs in the editor: rebuild a 33^3 LUT with every tool on, then count.
    a.hueVsHue = Curve(CurveKind::Hue, {{0, 10}, {120, -10}, {240, 5}});
    a.hueVsSat = Curve(CurveKind::Hue, {{0, 0.2}, {180, -0.3}});
    a.hueVsLum = Curve(CurveKind::Hue, {{60, 0.1}});
    a.lift = colorWheelOffset(200, 0.02);
    a.strength = 0.8;
    const Lut3D base = lutFrom(33, smoothGrade);
    constexpr int kRuns = 20;
    double applySec = 0, countSec = 0;
    for (int i = 0; i < kRuns; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        const Lut3D out = applyAdjustments(base, a);
        const auto t1 = std::chrono::steady_clock::now();
        const ClipCount cc = countOutOfRange(out);
        const auto t2 = std::chrono::steady_clock::now();
        applySec += std::chrono::duration<double>(t1 - t0).count();
        countSec += std::chrono::duration<double>(t2 - t1).count();
        EXPECT_LE(cc.outside, cc.entries);
    }
    std::printf("[timing] 33^3 applyAdjustments (all tools): %.3f ms, countOutOfRange: %.3f ms\n",
                1e3 * applySec / kRuns, 1e3 * countSec / kRuns);
}
