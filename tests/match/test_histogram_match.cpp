// SPDX-License-Identifier: Apache-2.0
// Histogram matching and its curves, against float64 formulas written here.
#include "lut/Error.h"
#include "lut/match/ChannelCurve.h"
#include "lut/match/HistogramMatch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

using namespace lut;

namespace {

// Every 8-bit code of a smooth ramp, with a sine's worth of uneven counts.
ChannelHistogram codes(const std::function<double(int)>& value, int samplesPerCode = 40) {
    ChannelHistogram h(-0.5 / 255.0, 1.0 + 0.5 / 255.0, 256);
    for (int k = 0; k < 256; ++k) {
        const int n = samplesPerCode + static_cast<int>(20 * std::sin(k * 0.1));
        for (int i = 0; i < n; ++i)
            h.add(value(k));
    }
    return h;
}

double curve(double x) { // a monotone grade of one channel, the oracle
    return 0.03 + 0.94 * std::pow(x, 0.8);
}

} // namespace

TEST(ChannelCurve, EvaluatesInvertsAndExtendsLinearly) {
    const ChannelCurve c(0.0, 1.0, {0.1, 0.3, 0.9}, 0.5, 2.0);
    EXPECT_DOUBLE_EQ(c(0.25), 0.2);
    EXPECT_DOUBLE_EQ(c(0.75), 0.6);
    EXPECT_DOUBLE_EQ(c(-0.2), 0.1 - 0.1);
    EXPECT_DOUBLE_EQ(c(1.5), 0.9 + 1.0);
    for (double x : {-0.3, 0.0, 0.1, 0.5, 0.99, 1.0, 1.7})
        EXPECT_NEAR(c.inverse(c(x)), x, 1e-12) << x;
    EXPECT_DOUBLE_EQ(c(NAN), 0.1);
    EXPECT_DOUBLE_EQ(c.minSlope(), 0.4);
    EXPECT_DOUBLE_EQ(c.maxSlope(), 2.0);
    EXPECT_THROW(ChannelCurve(0.0, 1.0, {0.0}, 1, 1), Error);
    EXPECT_THROW(ChannelCurve(1.0, 1.0, {0.0, 1.0}, 1, 1), Error);
}

TEST(HistogramMatch, RecoversAMonotoneCurveFromUnpairedCodes) {
    // The reference is the source's codes through the curve, stored as 8-bit codes: histogram
    // matching must give back the curve at every code within half a step (plus the smoothing).
    const auto src = codes([](int k) { return k / 255.0; });
    const auto ref = codes([](int k) { return std::round(curve(k / 255.0) * 255.0) / 255.0; });
    CurveNotes notes;
    const ChannelCurve t = matchHistograms(src, ref, {}, &notes);
    double worst = 0.0;
    for (int k = 0; k < 256; ++k)
        worst = std::max(worst, std::fabs(t(k / 255.0) - curve(k / 255.0)) * 255.0);
    EXPECT_LT(worst, 1.0);
    EXPECT_FALSE(notes.slopeLimited);
    EXPECT_GT(t.minSlope(), 0.0);
}

TEST(HistogramMatch, GapsInTheSourceAreBridgedLinearly) {
    // Source codes only below 0.2 and above 0.6; the reference is the same through the curve.
    ChannelHistogram src(-0.5 / 255.0, 1.0 + 0.5 / 255.0, 256), ref = src;
    for (int k = 0; k < 256; ++k) {
        const double x = k / 255.0;
        if (x > 0.2 && x < 0.6)
            continue;
        for (int i = 0; i < 30; ++i) {
            src.add(x);
            ref.add(std::round(curve(x) * 255.0) / 255.0);
        }
    }
    const ChannelCurve t = matchHistograms(src, ref);
    for (double x : {0.1, 0.65, 0.9})
        EXPECT_NEAR(t(x), curve(x), 1.5 / 255.0) << x;
    // across the gap: between the curve's ends, never a step
    EXPECT_GT(t(0.4), curve(0.2));
    EXPECT_LT(t(0.4), curve(0.6));
    EXPECT_LE(t.maxSlope(), 4.0 + 1e-9);
}

TEST(HistogramMatch, TwoFlatColoursBecomeABoundedRamp) {
    ChannelHistogram src(0.0, 1.0, 4096), ref(0.0, 1.0, 4096);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        src.add(u(rng));
        ref.add(i % 2 ? 0.2 : 0.8);
    }
    CurveLimits limits;
    limits.smoothing = 1.0 / 256.0;
    CurveNotes notes;
    const ChannelCurve t = matchHistograms(src, ref, limits, &notes);
    EXPECT_TRUE(notes.slopeLimited);
    EXPECT_GT(notes.steepestAsked, 10.0);
    EXPECT_LE(t.maxSlope(), limits.maxSlope * (1 + 1e-9));
    EXPECT_GE(t.minSlope(), limits.minSlope * (1 - 1e-9));
    for (double x = -0.5; x <= 1.5; x += 0.01)
        EXPECT_TRUE(std::isfinite(t(x))) << x;
    // still the two colours far from the step
    EXPECT_NEAR(t(0.05), 0.2, 0.05);
    EXPECT_NEAR(t(0.95), 0.8, 0.05);
}

TEST(HistogramMatch, EmptyInputsGiveTheIdentity) {
    ChannelHistogram empty(0.0, 1.0, 16), some(0.0, 1.0, 16);
    some.add(0.3);
    some.add(0.7);
    CurveNotes notes;
    const ChannelCurve a = matchHistograms(empty, some, {}, &notes);
    EXPECT_TRUE(notes.emptySource);
    EXPECT_DOUBLE_EQ(a(0.4), 0.4);
    const ChannelCurve b = matchHistograms(some, empty, {}, &notes);
    EXPECT_TRUE(notes.emptyReference);
    EXPECT_DOUBLE_EQ(b(0.4), 0.4);
}

TEST(HistogramMatch, QuantilesOfADequantisedHistogram) {
    ChannelHistogram h(0.0, 4.0, 4);
    h.add(0.5, 1.0);
    h.add(2.5, 1.0); // bins 0 and 2 hold mass, bin 1 is a gap
    EXPECT_DOUBLE_EQ(h.cdf(0.5), 0.25);
    EXPECT_DOUBLE_EQ(h.cdf(1.5), 0.5);
    EXPECT_DOUBLE_EQ(h.quantile(0.5), 1.0);      // where the mass below ends
    EXPECT_DOUBLE_EQ(h.upperQuantile(0.5), 2.0); // where the mass above starts
    EXPECT_DOUBLE_EQ(h.quantile(0.75), 2.5);
}

// An atom: a source with 3/4 of its pixels at black (a letterbox's bars) and the rest spread
// over the codes, a reference with a few pixels at black and dark greys and the bars' graded
// colour at code 24. Optimal 1D transport sends the atom to the reference's mean over the
// lowest 3/4 of its mass, written here as a float64 sum over the reference's sorted values;
// before, the curve put black halfway between the reference's black and code 24 (12).
TEST(HistogramMatch, AnAtomLandsOnTheReferencesMeanOverItsShare) {
    ChannelHistogram src(-0.5 / 255.0, 1.0 + 0.5 / 255.0, 256),
        ref(-0.5 / 255.0, 1.0 + 0.5 / 255.0, 256);
    std::vector<double> refValues;
    const int bars = 30000;
    for (int i = 0; i < bars; ++i)
        src.add(0.0);
    for (int k = 1; k < 256; ++k)
        for (int i = 0; i < 40; ++i)
            src.add(k / 255.0); // 10200 pixels
    auto addRef = [&](int code, int n) {
        for (int i = 0; i < n; ++i) {
            ref.add(code / 255.0);
            refValues.push_back(code / 255.0);
        }
    };
    addRef(0, 120);
    addRef(8, 150);
    addRef(9, 200);
    addRef(24, bars - 470 + 100);
    for (int k = 25; k < 256; ++k)
        addRef(k, 10100 / 231);
    std::sort(refValues.begin(), refValues.end());
    // the reference's values over the share of the source's atom, each a code value
    const double share = static_cast<double>(bars) / src.total();
    const std::size_t n = static_cast<std::size_t>(share * static_cast<double>(refValues.size()));
    double mean = 0.0;
    for (std::size_t i = 0; i < n; ++i)
        mean += refValues[i];
    mean /= static_cast<double>(n);
    const ChannelCurve t = matchHistograms(src, ref);
    EXPECT_NEAR(t(0.0) * 255.0, mean * 255.0, 0.5) << "the oracle: " << mean * 255.0;
}
