// SPDX-License-Identifier: Apache-2.0
// resample / resampleWithError / compareLuts / quantize8 / toUnorm / ErrorStats against float64
// references written here.
#include "LutTestUtil.h"
#include "lut/ErrorStats.h"
#include "lut/Quantize.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/CompareLuts.h"
#include "lut/ops/QuantizeLut.h"
#include "lut/ops/Resample.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace lut;

namespace {

// A function trilinear interpolation reproduces exactly (linear in each variable separately).
glm::dvec3 multilinear(glm::dvec3 c) {
    return {0.1 + 0.5 * c.x * c.y + 0.2 * c.z, 0.3 * c.x + 0.4 * c.y * c.z - 0.1 * c.x * c.y * c.z,
            0.25 + 0.5 * c.x * c.z + 0.125 * c.y};
}
// A function tetrahedral (and trilinear) interpolation reproduces exactly: affine.
glm::dvec3 affine(glm::dvec3 c) {
    return {0.8 * c.x + 0.15 * c.y + 0.05 * c.z, 0.1 * c.x + 0.85 * c.y + 0.05 * c.z + 0.01,
            -0.05 * c.x + 0.1 * c.y + 0.9 * c.z};
}

template <class F>
Lut3D sampled(int n, F f, glm::vec3 lo = glm::vec3(0), glm::vec3 hi = glm::vec3(1)) {
    Lut3D l(n);
    l.setDomain(lo, hi);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                l.at(r, g, b) = glm::vec3(f(glm::dvec3(l.latticeInput(r, g, b))));
    return l;
}

// Float64 trilinear evaluation of a LUT, written independently of the library.
glm::dvec3 trilinear64(const Lut3D& l, glm::dvec3 in) {
    const int n = l.size();
    double t[3];
    int i[3];
    for (int c = 0; c < 3; ++c) {
        const double lo = l.domainMin()[c], hi = l.domainMax()[c];
        double x = (in[c] - lo) / (hi - lo) * (n - 1);
        x = std::clamp(x, 0.0, static_cast<double>(n - 1));
        i[c] = std::min(static_cast<int>(x), n - 2);
        t[c] = x - i[c];
    }
    glm::dvec3 acc(0.0);
    for (int corner = 0; corner < 8; ++corner) {
        double w = 1;
        int idx[3];
        for (int c = 0; c < 3; ++c) {
            const int bit = (corner >> c) & 1;
            w *= bit ? t[c] : 1 - t[c];
            idx[c] = i[c] + bit;
        }
        acc += w * glm::dvec3(l.at(idx[0], idx[1], idx[2]));
    }
    return acc;
}

} // namespace

TEST(Resample, TrilinearReproducesMultilinearFunctions) {
    const Lut3D src = sampled(5, multilinear);
    for (int n : {2, 3, 9, 17, 33}) {
        const Lut3D out = resample(src, n, Interpolation::Trilinear);
        ASSERT_EQ(out.size(), n);
        for (int b = 0; b < n; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r) {
                    const glm::dvec3 want = multilinear(glm::dvec3(out.latticeInput(r, g, b)));
                    for (int c = 0; c < 3; ++c)
                        ASSERT_NEAR(out.at(r, g, b)[c], want[c], 1e-6) << n;
                }
    }
}

TEST(Resample, TetrahedralReproducesAffineFunctionsOnAnyDomain) {
    const glm::vec3 lo(-0.25f, 0.0f, 0.5f), hi(1.25f, 2.0f, 1.0f);
    const Lut3D src = sampled(4, affine, lo, hi);
    for (int n : {2, 7, 33}) {
        const Lut3D out = resample(src, n, Interpolation::Tetrahedral, 1);
        EXPECT_EQ(out.domainMin(), lo);
        EXPECT_EQ(out.domainMax(), hi);
        for (int b = 0; b < n; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r) {
                    const glm::dvec3 want = affine(glm::dvec3(out.latticeInput(r, g, b)));
                    for (int c = 0; c < 3; ++c)
                        ASSERT_NEAR(out.at(r, g, b)[c], want[c], 2e-6);
                }
    }
}

TEST(Resample, SameSizeIsACopyAndMetadataIsKept) {
    Lut3D src = test::randomLut(9);
    src.setTitle("grade");
    src.comments().push_back("hello");
    const Lut3D out = resample(src, 9, Interpolation::Tetrahedral);
    EXPECT_EQ(out.entries(), src.entries());
    EXPECT_EQ(out.title(), "grade");
    ASSERT_EQ(out.comments().size(), 1u);
    // Thread count does not change the result.
    EXPECT_EQ(resample(src, 20, Interpolation::Trilinear, 1).entries(),
              resample(src, 20, Interpolation::Trilinear, 3).entries());
}

TEST(Resample, DownAndUpKeepLatticeValuesWhereLatticesCoincide) {
    // 33 -> 17: every 17-lattice point is a 33-lattice point, so entries are copied exactly.
    const Lut3D src = test::randomLut(33, 17);
    const Lut3D out = resample(src, 17, Interpolation::Tetrahedral);
    for (int b = 0; b < 17; ++b)
        for (int g = 0; g < 17; ++g)
            for (int r = 0; r < 17; ++r)
                ASSERT_EQ(out.at(r, g, b), src.at(2 * r, 2 * g, 2 * b));
}

TEST(Resample, WithErrorBoundsAFloat64Reference) {
    // The reported maximum bounds |source - result| over every input (lut/ops/ErrorBound.h):
    // measured here on 100,000 random inputs (none on a grid lutkit chose), both LUTs evaluated
    // in float64. The mean is a midpoint rule over the held-out points: close to the mean here.
    const Lut3D src = test::smoothLut(33);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int n : {5, 9, 17}) {
        const ResampleResult res = resampleWithError(src, n, Interpolation::Trilinear);
        double maxAbs = 0, sum = 0;
        std::size_t count = 0;
        for (int i = 0; i < 100000; ++i) {
            const glm::dvec3 in(u(rng), u(rng), u(rng));
            const glm::dvec3 a = trilinear64(src, in), b = trilinear64(res.lut, in);
            for (int c = 0; c < 3; ++c) {
                const double d = std::fabs(a[c] - b[c]);
                maxAbs = std::max(maxAbs, d);
                sum += d;
                ++count;
            }
        }
        const double mean = sum / static_cast<double>(count);
        EXPECT_TRUE(res.error.bounded);
        EXPECT_GE(res.error.maxAbs, maxAbs) << n;
        EXPECT_LE(res.error.maxAbs, 1.2 * maxAbs + 1e-6) << n;
        EXPECT_NEAR(res.error.meanAbs, mean, 0.05 * mean) << n;
        EXPECT_GT(res.error.maxAbs, 1e-4)
            << "a 33 -> " << n << " resample of a curved grade must lose something";
        EXPECT_GE(res.error.seconds, 0.0);
    }
    // Finer target, smaller error.
    EXPECT_LT(resampleWithError(src, 17, Interpolation::Trilinear).error.maxAbs,
              resampleWithError(src, 9, Interpolation::Trilinear).error.maxAbs);
}

TEST(Resample, CompareLutsIsZeroForEqualAndSymmetric) {
    const Lut3D a = test::randomLut(9, 1), b = test::randomLut(9, 2);
    EXPECT_EQ(compareLuts(a, a, Interpolation::Tetrahedral).maxAbs, 0.0);
    const ErrorStats ab = compareLuts(a, b, Interpolation::Trilinear),
                     ba = compareLuts(b, a, Interpolation::Trilinear);
    EXPECT_DOUBLE_EQ(ab.maxAbs, ba.maxAbs);
    EXPECT_NEAR(ab.meanAbs, ba.meanAbs, 1e-12);
    EXPECT_GT(ab.maxAbs, 0.1);
    EXPECT_EQ(compareLuts(a, b, Interpolation::Nearest, 5).count, 5u * 5 * 5 * 3);
}

TEST(Quantize, ToUnormRoundsToNearestAndClamps) {
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(toUnorm8(std::nanf("")), 0);
    EXPECT_EQ(toUnorm8(-0.0f), 0);
    EXPECT_EQ(toUnorm8(-1.0f), 0);
    EXPECT_EQ(toUnorm8(-inf), 0);
    EXPECT_EQ(toUnorm8(inf), 255);
    EXPECT_EQ(toUnorm8(1e30f), 255);
    EXPECT_EQ(toUnorm8(1.0f), 255);
    EXPECT_EQ(toUnorm8(0.5f), 128); // 127.5 rounds away from zero
    EXPECT_EQ(toUnorm8(0.49f), 125);
    EXPECT_EQ(toUnorm8(1e-40f), 0);
    for (int i = 0; i <= 255; ++i)
        EXPECT_EQ(toUnorm8(fromUnorm8(static_cast<std::uint8_t>(i))), i);
    EXPECT_EQ(toUnorm16(std::nanf("")), 0);
    EXPECT_EQ(toUnorm16(1.0f), 65535);
    EXPECT_EQ(toUnorm16(2.0f), 65535);
    EXPECT_EQ(toUnorm16(0.5f), 32768);
    for (int i = 0; i <= 65535; i += 7)
        EXPECT_EQ(toUnorm16(fromUnorm16(static_cast<std::uint16_t>(i))), i);
}

TEST(Quantize, ToUnormIsLroundForEveryFloatSampled) {
    // Every 97th float in (0, 1), against std::lround on the product in double.
    std::uint32_t bits = 1;
    const std::uint32_t one = 0x3F800000u;
    for (; bits < one; bits += 97) {
        float v;
        std::memcpy(&v, &bits, 4);
        ASSERT_EQ(toUnorm8(v), std::lround(static_cast<double>(v) * 255.0)) << v;
        ASSERT_EQ(toUnorm16(v), std::lround(static_cast<double>(v) * 65535.0)) << v;
    }
    // The halves themselves.
    for (int i = 0; i < 255; ++i) {
        const float half = static_cast<float>((i + 0.5) / 255.0);
        EXPECT_EQ(toUnorm8(half), std::lround(static_cast<double>(half) * 255.0)) << i;
    }
}

TEST(Quantize, Quantize8ReportsItsError) {
    Lut3D l = test::smoothLut(9);
    l.at(0, 0, 0) = glm::vec3(-0.5f, 1.5f, 0.5f); // clamped: error 0.5
    const Lut3D before = l;
    const ErrorStats e = quantize8(l);
    double maxAbs = 0, sum = 0;
    for (std::size_t i = 0; i < l.entryCount(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float q = l.entries()[i][c];
            EXPECT_EQ(q, fromUnorm8(toUnorm8(q))); // on the 8-bit grid
            const double d = std::fabs(static_cast<double>(q) - before.entries()[i][c]);
            maxAbs = std::max(maxAbs, d);
            sum += d;
        }
    EXPECT_DOUBLE_EQ(e.maxAbs, maxAbs);
    EXPECT_NEAR(e.maxAbs, 0.5, 1e-7);
    EXPECT_NEAR(e.meanAbs, sum / (3.0 * l.entryCount()), 1e-12);
    EXPECT_EQ(e.count, 3 * l.entryCount());
    Lut3D clean = test::smoothLut(5);
    for (auto& v : clean.entries())
        for (int c = 0; c < 3; ++c)
            v[c] = std::clamp(v[c], 0.0f, 1.0f);
    EXPECT_LE(quantize8(clean).maxAbs, 0.5 / 255 + 1e-7);
}

TEST(ErrorStatsTest, AccumulatorAndFormatting) {
    ErrorAccumulator acc;
    acc.add(1.0, 1.5);
    acc.add(-2.0, -2.0);
    acc.add(0.25, 0.0);
    ErrorStats s = acc.result();
    EXPECT_DOUBLE_EQ(s.maxAbs, 0.5);
    EXPECT_DOUBLE_EQ(s.meanAbs, 0.75 / 3);
    EXPECT_EQ(s.count, 3u);
    EXPECT_DOUBLE_EQ(s.maxSteps8(), 127.5);
    EXPECT_EQ(s.str(), "max 0.5 (128 8-bit steps), mean 0.25 (63.8 steps)");
    s.seconds = 0.0123;
    EXPECT_EQ(s.str(), "max 0.5 (128 8-bit steps), mean 0.25 (63.8 steps), 12.3 ms");
    ErrorAccumulator nan;
    nan.add(std::nan(""), std::nan(""));
    EXPECT_EQ(nan.result().maxAbs, 0.0);
    nan.add(std::nan(""), 1.0);
    EXPECT_TRUE(std::isinf(nan.result().maxAbs));
    EXPECT_EQ(ErrorAccumulator().result().meanAbs, 0.0);
}
