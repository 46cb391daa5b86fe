// SPDX-License-Identifier: Apache-2.0
// LUT authoring adjustments against plain float64 formulas written out here, independently of
// lutlib/src/ops/Adjust.cpp (which composes, clamps and skips neutral steps).
#include "lut/Limits.h"
#include "lut/ops/Adjust.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using glm::dvec3;

double spowRef(double x, double p) {
    return x < 0 ? -std::pow(-x, p) : std::pow(x, p);
}

dvec3 refExposure(dvec3 e, double stops) {
    dvec3 o;
    for (int c = 0; c < 3; ++c)
        o[c] = spowRef(spowRef(e[c], 2.2) * std::pow(2.0, stops), 1 / 2.2);
    return o;
}

dvec3 refWhiteBalance(dvec3 e, double t, double n) {
    const double gr = std::pow(2.0, 0.25 * t), gg = std::pow(2.0, -0.25 * n),
                 gb = std::pow(2.0, -0.25 * t);
    const double norm = 0.2126 * gr + 0.7152 * gg + 0.0722 * gb;
    const double g[3] = {gr / norm, gg / norm, gb / norm};
    dvec3 o;
    for (int c = 0; c < 3; ++c)
        o[c] = spowRef(spowRef(e[c], 2.2) * g[c], 1 / 2.2);
    return o;
}

dvec3 refContrast(dvec3 e, double k) {
    dvec3 o;
    for (int c = 0; c < 3; ++c)
        o[c] = (e[c] - 0.5) * (1 + k) + 0.5;
    return o;
}

dvec3 refLgg(dvec3 e, dvec3 lift, dvec3 gamma, dvec3 gain) {
    dvec3 o;
    for (int c = 0; c < 3; ++c)
        o[c] = spowRef(gain[c] * (e[c] + lift[c] * (1 - e[c])), 1 / gamma[c]);
    return o;
}

dvec3 refSaturation(dvec3 e, double s) {
    const double y = 0.2126 * e.x + 0.7152 * e.y + 0.0722 * e.z;
    return {y + s * (e.x - y), y + s * (e.y - y), y + s * (e.z - y)};
}

void expectNear(dvec3 a, dvec3 b, double tol = 1e-12) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(a[c], b[c], tol) << "channel " << c;
}

const dvec3 kColors[] = {{0, 0, 0},       {1, 1, 1},         {0.5, 0.25, 0.75},
                         {0.1, 0.9, 0.3}, {-0.05, 0.2, 1.3}, {2.0, 0.001, 0.6}};

} // namespace

TEST(Adjust, SingleOperationsMatchFloat64Formulas) {
    for (dvec3 e : kColors) {
        expectNear(lut::adjustExposure(e, 1.5), refExposure(e, 1.5));
        expectNear(lut::adjustExposure(e, -2.0), refExposure(e, -2.0));
        expectNear(lut::adjustWhiteBalance(e, 0.6, -0.3), refWhiteBalance(e, 0.6, -0.3));
        expectNear(lut::adjustContrast(e, 0.4), refContrast(e, 0.4));
        expectNear(lut::adjustSaturation(e, 0.3), refSaturation(e, 0.3));
        const dvec3 lift{0.05, -0.02, 0.1}, gamma{1.2, 0.8, 1.0}, gain{1.1, 0.9, 1.3};
        expectNear(lut::adjustLiftGammaGain(e, lift, gamma, gain), refLgg(e, lift, gamma, gain));
    }
}

TEST(Adjust, KnownValues) {
    // One stop up doubles linear light: 0.5 encoded -> 0.5 * 2^(1/2.2).
    EXPECT_NEAR(lut::adjustExposure({0.5, 0.5, 0.5}, 1.0).x, 0.5 * std::pow(2.0, 1 / 2.2), 1e-12);
    // Contrast keeps mid grey; saturation 0 gives luma; warm white balance keeps white's luma.
    EXPECT_DOUBLE_EQ(lut::adjustContrast({0.5, 0.5, 0.5}, 0.7).y, 0.5);
    EXPECT_NEAR(lut::adjustSaturation({1, 0, 0}, 0.0).z, 0.2126, 1e-15);
    const dvec3 g = lut::whiteBalanceGains(1.0, 0.0);
    EXPECT_GT(g.x, 1.0);
    EXPECT_LT(g.z, 1.0);
    EXPECT_NEAR(0.2126 * g.x + 0.7152 * g.y + 0.0722 * g.z, 1.0, 1e-15);
}

TEST(Adjust, ComposedOrderOnLutEntries) {
    lut::Adjustments a;
    a.exposure = 0.5;
    a.temperature = -0.4;
    a.tint = 0.2;
    a.contrast = 0.25;
    a.saturation = 1.4;
    a.liftMaster = 0.02;
    a.lift = {0.01, 0.0, -0.01};
    a.gammaMaster = 1.1;
    a.gamma = {1.0, 0.9, 1.05};
    a.gainMaster = 0.95;
    a.gain = {1.0, 1.1, 1.0};
    const lut::Lut3D base = lut::Lut3D::identity(9);
    const lut::Lut3D out = lut::applyAdjustments(base, a, 2);
    ASSERT_EQ(out.size(), 9);
    const dvec3 liftE = dvec3(a.liftMaster) + a.lift, gammaE = a.gammaMaster * a.gamma,
                gainE = a.gainMaster * a.gain;
    for (int b = 0; b < 9; ++b)
        for (int g = 0; g < 9; ++g)
            for (int r = 0; r < 9; ++r) {
                dvec3 e = dvec3(base.at(r, g, b));
                // Reference: WB and exposure are both linear-light gains, applied together.
                dvec3 wb = refWhiteBalance(e, a.temperature, a.tint);
                e = refExposure(wb, a.exposure);
                e = refContrast(e, a.contrast);
                e = refLgg(e, liftE, gammaE, gainE);
                e = refSaturation(e, a.saturation);
                const glm::vec3 got = out.at(r, g, b);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(got[c], e[c], 2e-6);
            }
}

TEST(Adjust, NeutralIsExactAndKeepsMetadata) {
    lut::Lut3D base = lut::Lut3D::identity(17);
    base.setTitle("grade");
    base.comments().push_back("kept");
    base.setDomain(glm::vec3(-0.1f), glm::vec3(1.5f));
    lut::Adjustments a;
    EXPECT_TRUE(a.isNeutral());
    const lut::Lut3D out = lut::applyAdjustments(base, a);
    EXPECT_EQ(out.entries(), base.entries());
    EXPECT_EQ(out.title(), "grade");
    EXPECT_EQ(out.comments().size(), 1u);
    EXPECT_EQ(out.domainMax(), glm::vec3(1.5f));
    // Contrast alone must not touch entries through a decode/encode round trip.
    a.contrast = 0.1;
    EXPECT_FALSE(a.isNeutral());
    const lut::Lut3D c = lut::applyAdjustments(base, a);
    EXPECT_EQ(c.at(8, 8, 8).x, static_cast<float>((base.at(8, 8, 8).x - 0.5) * 1.1 + 0.5));
}

TEST(Adjust, ExtremeEntriesStayFinite) {
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    lut::Adjustments a;
    a.exposure = 3;
    a.contrast = 2;
    a.saturation = 3;
    a.temperature = 1;
    a.gammaMaster = 0.0; // clamped to 0.01
    a.gainMaster = 1e30; // clamped
    for (dvec3 e : {dvec3(nan, 0.5, 0.5), dvec3(inf, -inf, 1e30), dvec3(-1e30, 0, 1)}) {
        const dvec3 o = lut::adjustColor(e, a);
        for (int c = 0; c < 3; ++c) {
            EXPECT_TRUE(std::isfinite(o[c]));
            EXPECT_LE(std::abs(o[c]), lut::limits::kMaxColorValue);
        }
    }
    // NaN parameters fall back to neutral.
    lut::Adjustments bad;
    bad.exposure = nan;
    bad.saturation = nan;
    expectNear(lut::adjustColor({0.3, 0.4, 0.5}, bad), {0.3, 0.4, 0.5});
    // Sizes 2 and 256's entry counts go through the same path.
    lut::Lut3D two = lut::Lut3D::identity(2);
    two.at(1, 1, 1) = glm::vec3(std::numeric_limits<float>::quiet_NaN());
    const lut::Lut3D o2 = lut::applyAdjustments(two, a);
    EXPECT_TRUE(std::isfinite(o2.at(1, 1, 1).x));
}
