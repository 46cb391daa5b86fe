// SPDX-License-Identifier: Apache-2.0
// Monotone curves (lut/ops/Curve.h) against values derived by hand from the Fritsch-Carlson
// construction and against the properties it promises (through the points, monotone, no
// overshoot, periodic hue curves).
#include "lut/Error.h"
#include "lut/ops/Curve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using lut::Curve;
using lut::CurveKind;

TEST(Curve, HandComputedFritschCarlsonValue) {
    // Secants 0.5 and 1.5; tangents 0.5 (end), 1.0 (mean of the secants), 1.5 (end); at x = 0.25
    // (t = 0.5, h = 0.5) the Hermite basis is (0.5, 0.125, 0.5, -0.125):
    // 0.125 * 0.5 * 0.5 + 0.5 * 0.25 - 0.125 * 0.5 * 1.0 = 0.09375.
    const Curve c(CurveKind::Tone, {{0, 0}, {0.5, 0.25}, {1, 1}});
    EXPECT_NEAR(c(0.25), 0.09375, 1e-15);
    // Second segment, t = 0.5: 0.5 * 0.25 + 0.125 * 0.5 * 1.0 + 0.5 * 1 - 0.125 * 0.5 * 1.5
    EXPECT_NEAR(c(0.75), 0.125 + 0.0625 + 0.5 - 0.09375, 1e-15);
}

TEST(Curve, TangentsAreLimitedSoSteepDataStaysMonotone) {
    // Secants 0.1 and 10: the mean 5.05 is 50.5 times the first secant, far outside the circle
    // of radius 3, so Fritsch-Carlson scales it down; without that the first segment dips below 0.
    const Curve c(CurveKind::Tone, {{0, 0}, {0.5, 0.05}, {0.6, 1.05}});
    double prev = -1.0;
    for (int i = 0; i <= 6000; ++i) {
        const double v = c(i / 10000.0);
        EXPECT_GE(v, prev) << "at x = " << i / 10000.0;
        EXPECT_GE(v, 0.0);
        prev = v;
    }
}

TEST(Curve, PassesThroughPointsMonotoneWithoutOvershoot) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 50; ++trial) {
        // Random non-monotone data: every segment must stay within its two points' values.
        std::vector<glm::dvec2> pts;
        const int n = 2 + trial % 7;
        for (int i = 0; i < n; ++i)
            pts.push_back({static_cast<double>(i) / (n - 1), u(rng)});
        const Curve c(CurveKind::Tone, pts);
        for (int i = 0; i + 1 < n; ++i) {
            const auto a = pts[static_cast<std::size_t>(i)],
                       b = pts[static_cast<std::size_t>(i) + 1];
            EXPECT_NEAR(c(a.x), a.y, 1e-15);
            double prev = a.y;
            for (int k = 1; k <= 200; ++k) {
                const double x = a.x + (b.x - a.x) * k / 200.0;
                const double v = c(x);
                EXPECT_GE(v, std::min(a.y, b.y));
                EXPECT_LE(v, std::max(a.y, b.y));
                // Monotone in the direction of the segment.
                if (b.y >= a.y)
                    EXPECT_GE(v, prev - 1e-15);
                else
                    EXPECT_LE(v, prev + 1e-15);
                prev = v;
            }
        }
    }
}

TEST(Curve, FlatRunStaysFlatAndLinearDataGivesTheLine) {
    const Curve flat(CurveKind::Tone, {{0, 0}, {0.3, 0.4}, {0.7, 0.4}, {1, 1}});
    for (int i = 0; i <= 100; ++i)
        EXPECT_EQ(flat(0.3 + 0.4 * i / 100.0), 0.4);
    const Curve line(CurveKind::Tone, {{0, 0.1}, {0.25, 0.3}, {1, 0.9}}); // y = 0.1 + 0.8 x
    for (int i = -20; i <= 120; ++i) {
        const double x = i / 100.0; // includes the straight extensions beyond both ends
        EXPECT_NEAR(line(x), 0.1 + 0.8 * x, 1e-15);
    }
}

TEST(Curve, NeutralityAndExtension) {
    EXPECT_TRUE(Curve(CurveKind::Tone).isNeutral());
    EXPECT_TRUE(Curve(CurveKind::Tone, {{0, 0}, {0.4, 0.4}, {1, 1}}).isNeutral());
    EXPECT_FALSE(Curve(CurveKind::Tone, {{0, 0}, {0.4, 0.41}, {1, 1}}).isNeutral());
    EXPECT_EQ(Curve(CurveKind::Tone)(0.37), 0.37);
    // Beyond the last point the curve continues with the end tangent (the last secant, 2).
    const Curve c(CurveKind::Tone, {{0, 0}, {0.5, 0.0}, {1, 1}});
    EXPECT_NEAR(c(1.5), 1.0 + 2.0 * 0.5, 1e-15);
    EXPECT_TRUE(Curve(CurveKind::Hue, {{0, 0}, {120, 0}}).isNeutral());
    EXPECT_EQ(Curve(CurveKind::Hue)(42.0), 0.0);
}

TEST(Curve, HueCurvesArePeriodic) {
    const Curve c(CurveKind::Hue, {{0, 10}, {120, -20}, {240, 5}});
    EXPECT_NEAR(c(120), -20, 1e-12);
    EXPECT_NEAR(c(360), 10, 1e-12);
    EXPECT_NEAR(c(-120), 5, 1e-12);
    for (double h = 0; h < 360; h += 7.3) {
        EXPECT_NEAR(c(h), c(h + 360), 1e-9);
        EXPECT_NEAR(c(h), c(h - 720), 1e-9);
    }
    // Continuous across the wrap: the segment 240 -> 360 joins the first point.
    EXPECT_NEAR(c(359.9999), c(0.0001), 1e-3);
    // Every segment stays within its points' values (no overshoot across the wrap either).
    for (double h = 240; h < 360; h += 0.5) {
        EXPECT_GE(c(h), 5 - 1e-12);
        EXPECT_LE(c(h), 10 + 1e-12);
    }
    // Points given past 360 wrap; one point is a constant.
    const Curve wrapped(CurveKind::Hue, {{360 + 60, 3}, {-60, 1}});
    ASSERT_EQ(wrapped.points().size(), 2u);
    EXPECT_EQ(wrapped.points()[0].x, 60.0);
    EXPECT_EQ(wrapped.points()[1].x, 300.0);
    EXPECT_EQ(Curve(CurveKind::Hue, {{200, 0.25}})(17.0), 0.25);
    EXPECT_EQ(c(std::nan("")), 0.0);
}

TEST(Curve, RefusesBadPoints) {
    EXPECT_THROW(Curve(CurveKind::Tone, {{0, 0}, {0, 1}}), lut::Error);
    EXPECT_THROW(Curve(CurveKind::Tone, {{0.5, 0.5}}), lut::Error);
    EXPECT_THROW(Curve(CurveKind::Tone, {{0, 0}, {1, INFINITY}}), lut::Error);
    EXPECT_THROW(Curve(CurveKind::Hue, {{10, 0}, {370, 1}}), lut::Error); // same hue after wrap
}
