// SPDX-License-Identifier: Apache-2.0
// lut/bench/KernelBench.h (bench/support): the analytic grade, its sampled LUTs, the synthetic
// frame and the error measure that `lutkit bench` prints.
#include "lut/bench/KernelBench.h"
#include "lut/interp/Sampler.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lut;

TEST(KernelBench, AnalyticGradeFixesBlackWhiteAndGreys) {
    EXPECT_NEAR(analyticGrade(glm::dvec3(0.0)).r, 0.0, 1e-12);
    EXPECT_NEAR(analyticGrade(glm::dvec3(1.0)).g, 1.0, 1e-12);
    for (double v : {0.1, 0.42, 0.8}) {
        const glm::dvec3 o = analyticGrade(glm::dvec3(v));
        EXPECT_NEAR(o.r, o.g, 1e-12);
        EXPECT_NEAR(o.g, o.b, 1e-12);
    }
    // Contrast: darks darker, lights lighter; saturation: a colour moves away from its grey.
    EXPECT_LT(analyticGrade(glm::dvec3(0.2)).r, 0.2);
    EXPECT_GT(analyticGrade(glm::dvec3(0.8)).r, 0.8);
    const glm::dvec3 c = analyticGrade(glm::dvec3(0.6, 0.4, 0.4));
    EXPECT_GT(c.r - c.g, 0.2);
}

TEST(KernelBench, SampledLutHoldsTheGradeAtLatticePoints) {
    const Lut3D l = sampleAnalyticGrade(9);
    for (int b = 0; b < 9; b += 4)
        for (int g = 0; g < 9; g += 2)
            for (int r = 0; r < 9; ++r) {
                const glm::dvec3 want = analyticGrade(glm::dvec3(l.latticeInput(r, g, b)));
                for (int ch = 0; ch < 3; ++ch)
                    EXPECT_EQ(l.at(r, g, b)[ch], static_cast<float>(want[ch]));
            }
}

TEST(KernelBench, FrameIsDeterministicAndInRange) {
    const Image a = makeBenchFrame(131, 67, 1), b = makeBenchFrame(131, 67, 3);
    ASSERT_EQ(a.pixels(), b.pixels());
    for (std::size_t i = 0; i < a.pixels().size(); ++i) {
        const float v = a.pixels()[i];
        ASSERT_GE(v, 0.0f);
        ASSERT_LE(v, 1.0f);
        if (i % 4 == 3) {
            ASSERT_EQ(v, 1.0f);
        }
    }
}

TEST(KernelBench, ErrorShrinksWithLatticeSizeAndMatchesADirectSum) {
    const Image frame = makeBenchFrame(160, 90);
    const Image ref = analyticReference(frame);
    double previous = INFINITY;
    for (int n : {9, 17, 33, 65}) {
        Image work = frame;
        makeSampler(sampleAnalyticGrade(n), Interpolation::Tetrahedral)->apply(work.view());
        const ErrorStats e = frameError(work, ref);
        double maxAbs = 0, sum = 0;
        for (int y = 0; y < frame.height(); ++y)
            for (int x = 0; x < frame.width(); ++x)
                for (int c = 0; c < 3; ++c) {
                    const double want = analyticGrade(glm::dvec3(
                        frame.pixel(x, y)[0], frame.pixel(x, y)[1], frame.pixel(x, y)[2]))[c];
                    const double d = std::fabs(work.pixel(x, y)[c] - want);
                    maxAbs = std::max(maxAbs, d);
                    sum += d;
                }
        EXPECT_NEAR(e.maxAbs, maxAbs, 1e-6);
        EXPECT_NEAR(e.meanAbs, sum / (3.0 * frame.width() * frame.height()), 1e-7);
        EXPECT_LT(e.maxAbs, previous);
        previous = e.maxAbs;
    }
    EXPECT_LT(previous, 1e-3); // 65^3 tetrahedral: well under an 8-bit step
}

TEST(KernelBench, ParallelCopyAndBestSeconds) {
    const Image a = makeBenchFrame(33, 17);
    Image b(33, 17);
    parallelCopy(a, b, 4);
    EXPECT_EQ(a.pixels(), b.pixels());
    int prepared = 0, ran = 0;
    const double s = bestSeconds(
        3, [&] { ++prepared; }, [&] { ++ran; });
    EXPECT_EQ(prepared, 3);
    EXPECT_EQ(ran, 3);
    EXPECT_GE(s, 0.0);
}
