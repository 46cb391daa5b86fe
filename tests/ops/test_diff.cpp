// SPDX-License-Identifier: Apache-2.0
// LUT diffs (lut/ops/Diff.h) and heat maps (lut/ops/HeatMap.h) against float64 references
// written here: per-channel 8-bit steps by plain loops, ΔE2000 by the Sharma-checked function
// (test_delta_e.cpp) applied to the known outputs.
#include "OpsTestUtil.h"

#include "lut/Error.h"
#include "lut/ops/ColorDifference.h"
#include "lut/ops/Diff.h"
#include "lut/ops/HeatMap.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace lut;
using namespace lut::opstest;

namespace {

double refDeltaE(glm::dvec3 a, glm::dvec3 b) {
    return deltaE2000(srgbToLab(a), srgbToLab(b));
}

} // namespace

TEST(Diff, ALutAgainstItselfIsExactlyZero) {
    for (const Lut3D& a :
         {lutFrom(17, smoothGrade), withNonFinite(randomLut(9)), Lut3D::identity(2)}) {
        const DiffReport r = diffLuts(a, a);
        EXPECT_TRUE(r.identical());
        EXPECT_EQ(r.maxDeltaE, 0.0);
        EXPECT_EQ(r.meanDeltaE, 0.0);
        EXPECT_EQ(r.p95DeltaE, 0.0);
        EXPECT_EQ(r.meanSteps8, glm::dvec3(0.0));
        EXPECT_EQ(r.count, a.entryCount());
        const std::vector<glm::vec3> colors = {{0.1f, 0.2f, 0.3f}, {2.0f, -1.0f, NAN}};
        EXPECT_TRUE(diffLutsOnColors(a, a, colors).identical());
    }
    EXPECT_EQ(diffLuts(withNonFinite(randomLut(9)), randomLut(9)).sanitizedEntriesA, 3u);
}

TEST(Diff, TwoKnownLutsMatchAFloat64Reference) {
    // A: a smooth grade; B: A with a channel-dependent offset and gain (same lattice, so the
    // entries are compared directly).
    const int n = 17;
    const Lut3D a = lutFrom(n, smoothGrade);
    const Lut3D b = lutFrom(n, [](glm::vec3 x) {
        const glm::vec3 s = smoothGrade(x);
        return glm::vec3(s.r * 1.03f + 0.01f, s.g - 0.02f * x.b, s.b);
    });
    glm::dvec3 maxSteps(0.0), sumSteps(0.0);
    double maxDe = 0.0, sumDe = 0.0;
    glm::vec3 worstIn(0.0f);
    std::vector<double> des;
    for (int bl = 0; bl < n; ++bl)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::dvec3 va(a.at(r, g, bl)), vb(b.at(r, g, bl));
                for (int c = 0; c < 3; ++c) {
                    const double s = std::fabs(va[c] - vb[c]) * 255.0;
                    maxSteps[c] = std::max(maxSteps[c], s);
                    sumSteps[c] += s;
                }
                const double de = refDeltaE(va, vb);
                des.push_back(de);
                sumDe += de;
                if (de > maxDe) {
                    maxDe = de;
                    worstIn = a.latticeInput(r, g, bl);
                }
            }
    const double count = static_cast<double>(n * n * n);
    const DiffReport rep = diffLuts(a, b);
    ASSERT_EQ(rep.count, static_cast<std::size_t>(count));
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(rep.maxSteps8[c], maxSteps[c], 1e-9);
        EXPECT_NEAR(rep.meanSteps8[c], sumSteps[c] / count, 1e-9);
    }
    EXPECT_NEAR(rep.maxDeltaE, maxDe, 1e-12);
    EXPECT_NEAR(rep.meanDeltaE, sumDe / count, 1e-9);
    EXPECT_EQ(rep.worst.input, worstIn);
    std::sort(des.begin(), des.end());
    EXPECT_NEAR(rep.p95DeltaE, des[static_cast<std::size_t>(std::ceil(0.95 * count)) - 1], 1e-6);
    EXPECT_FALSE(rep.identical());
}

TEST(Diff, DifferentSizesAreComparedOnTheLargerLattice) {
    // Affine LUTs interpolate exactly, so B = 0.9 * identity on a 33 lattice against the 5-point
    // identity differs by 0.1 x per channel: max 25.5 steps (at x = 1), mean 12.75 steps.
    const Lut3D a = Lut3D::identity(5);
    const Lut3D b = lutFrom(33, [](glm::vec3 x) { return 0.9f * x; });
    const DiffReport r = diffLuts(a, b);
    EXPECT_EQ(r.count, 33u * 33u * 33u);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(r.maxSteps8[c], 25.5, 1e-4);
        EXPECT_NEAR(r.meanSteps8[c], 12.75, 1e-4);
    }
    DiffOptions small;
    small.size = 2;
    const DiffReport r2 = diffLuts(a, b, small);
    EXPECT_EQ(r2.count, 8u);
    EXPECT_NEAR(r2.meanSteps8.x, 12.75, 1e-4); // 4 of 8 corners have red 1
}

TEST(Diff, RegionsSayWhereTheDifferenceIs) {
    // B changes only colours in the red hue sector (inputs), by +0.1 on red.
    const int n = 17;
    const Lut3D a = Lut3D::identity(n);
    Lut3D b = a;
    std::size_t changed = 0;
    for (int bl = 0; bl < n; ++bl)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                if (classifyRegion(a.latticeInput(r, g, bl)).hue == Region::Red) {
                    b.at(r, g, bl).r -= 0.1f;
                    ++changed;
                }
    ASSERT_GT(changed, 0u);
    const DiffReport rep = diffLuts(a, b);
    const auto ranked = rep.rankedRegions();
    ASSERT_FALSE(ranked.empty());
    EXPECT_EQ(ranked.front().region, Region::Red);
    EXPECT_EQ(rep.regions[static_cast<int>(Region::Red)].count, changed);
    EXPECT_EQ(rep.regions[static_cast<int>(Region::Green)].maxDeltaE, 0.0);
    EXPECT_EQ(rep.regions[static_cast<int>(Region::Neutrals)].maxDeltaE, 0.0);
    EXPECT_EQ(classifyRegion(rep.worst.input).hue, Region::Red);
    // Each colour is in one tone band and one hue sector (or the neutrals).
    std::size_t tones = 0, hues = 0;
    for (const auto& reg : rep.regions)
        (reg.region <= Region::Highlights ? tones : hues) += reg.count;
    EXPECT_EQ(tones, rep.count);
    EXPECT_EQ(hues, rep.count);
}

TEST(Diff, OverAnImagesColours) {
    const Lut3D a = lutFrom(9, smoothGrade);
    const Lut3D b = lutFrom(9, [](glm::vec3 x) { return smoothGrade(x) + 0.02f; });
    Image img(2, 2, 1.0f);
    const glm::vec3 px[4] = {
        {0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, {0.5f, 0.5f, 0.5f}, {0.25f, 0.5f, 0.75f}};
    for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c)
            img.pixel(i % 2, i / 2)[c] = px[i][c];
    const DiffReport r = diffLutsOnImage(a, b, img.view());
    EXPECT_EQ(r.count, 4u);
    // Affine offset entries: B(x) = A(x) + 0.02 exactly where A interpolates, so 5.1 steps.
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(r.maxSteps8[c], 5.1, 1e-4);
    double worst = 0.0;
    for (const auto& p : px) {
        const glm::dvec3 va(
            a.at(static_cast<int>(p.r * 8), static_cast<int>(p.g * 8), static_cast<int>(p.b * 8)));
        worst = std::max(worst, refDeltaE(va, va + 0.02));
    }
    EXPECT_NEAR(r.maxDeltaE, worst, 1e-4);
}

TEST(Diff, HeatMapsShowTheDifference) {
    const Lut3D a = lutFrom(9, smoothGrade);
    Image img(3, 1, 1.0f);
    for (int x = 0; x < 3; ++x)
        for (int c = 0; c < 3; ++c)
            img.pixel(x, 0)[c] = 0.25f * (x + 1);
    const HeatMap same = diffHeatMap(a, a, img.view());
    for (int x = 0; x < 3; ++x)
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(same.image.pixel(x, 0)[c], heatMapColor(0.0)[c]);
    const Lut3D b = lutFrom(9, [](glm::vec3 x) { return smoothGrade(x) * 0.9f; });
    HeatMapOptions o;
    o.maxDeltaE = 8.0;
    const HeatMap hm = diffHeatMap(a, b, img.view(), o);
    EXPECT_EQ(hm.maxDeltaE, 8.0);
    for (int x = 0; x < 3; ++x) {
        // 0.25 (x + 1) are lattice inputs of a 9 lattice: both LUTs give their entries there.
        const int i = 2 * (x + 1);
        const double de = refDeltaE(glm::dvec3(a.at(i, i, i)), glm::dvec3(b.at(i, i, i)));
        const glm::vec3 want = heatMapColor(de / 8.0);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(hm.image.pixel(x, 0)[c], want[c], 1e-5) << x;
    }
    // Brighter means larger: the ramp's luminance grows.
    double prev = -1.0;
    for (int k = 0; k <= 20; ++k) {
        const glm::vec3 c = heatMapColor(k / 20.0);
        const double y = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
        EXPECT_GT(y, prev);
        prev = y;
    }
}

TEST(Diff, HeatMapSlicesPutEachInputWhereTheLayoutSays) {
    const Lut3D a = Lut3D::identity(5);
    const Lut3D b = lutFrom(5, [](glm::vec3 x) { return glm::vec3(x.r * 0.5f, x.g, x.b); });
    std::vector<HeatMapSliceLayout> layout;
    HeatMapOptions o;
    o.maxDeltaE = 0.0; // scale to the largest difference
    const HeatMap hm = diffHeatMapSlices(a, b, o, 3, 32, &layout);
    ASSERT_EQ(layout.size(), 3u);
    EXPECT_EQ(layout[1].blue, 0.5f);
    double largest = 0.0;
    for (const auto& l : layout)
        for (int y = 0; y < l.size; y += 7)
            for (int x = 0; x < l.size; x += 5) {
                const glm::dvec3 in(x / 31.0, 1.0 - y / 31.0, l.blue);
                const double de = refDeltaE(in, glm::dvec3(in.x * 0.5, in.y, in.z));
                largest = std::max(largest, de);
                const glm::vec3 want = heatMapColor(de / hm.maxDeltaE);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(hm.image.pixel(l.x + x, l.y + y)[c], want[c], 2e-4)
                        << x << "," << y << " blue " << l.blue;
            }
    EXPECT_GE(hm.maxDeltaE, largest - 1e-4);
    EXPECT_EQ(hm.maxDeltaE, hm.largestDeltaE);
    EXPECT_THROW(diffHeatMapSlices(a, b, o, 0), lut::Error);
}

TEST(Diff, NumericallyStableOnExtremeLuts) {
    // NaN/Inf entries, a discontinuous LUT and size 2: every figure finite.
    const Lut3D step = lutFrom(33, [](glm::vec3 x) {
        return x.r < 0.5f ? glm::vec3(0.0f) : glm::vec3(1.0f, 1e4f, -1e4f);
    });
    for (const auto& [a, b] : {std::pair{withNonFinite(randomLut(9)), randomLut(5)},
                               std::pair{step, Lut3D::identity(2)}}) {
        const DiffReport r = diffLuts(a, b);
        EXPECT_TRUE(std::isfinite(r.maxDeltaE) && std::isfinite(r.meanDeltaE));
        EXPECT_TRUE(std::isfinite(r.maxSteps8.x) && std::isfinite(r.meanSteps8.z));
        const HeatMap hm = diffHeatMapSlices(a, b);
        for (float v : hm.image.pixels())
            ASSERT_TRUE(std::isfinite(v));
    }
}
