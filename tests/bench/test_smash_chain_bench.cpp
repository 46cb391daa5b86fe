// SPDX-License-Identifier: Apache-2.0
// lut/bench/SmashChainBench.h (bench/support): the scene and LUT the smash-chain benchmarks run
// on must be what their comments promise, or the timings measure something else.
#include "lut/Error.h"
#include "lut/bench/SmashChainBench.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace lut;

TEST(SmashChainBench, LutIsAGame16CubeAndNotAnIdentity) {
    const Lut3D lut = makeSmashBenchLut();
    EXPECT_EQ(lut.size(), 16);
    // An identity would let the grading take a shortcut: the bench LUT moves entries visibly.
    EXPECT_GT(lut.maxDeviationFromIdentity(), 0.05f);
    for (const glm::vec3& e : lut.entries())
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(e[c], 0.0f);
            EXPECT_LE(e[c], 1.0f);
        }
    // Warm: at mid grey red ends above blue.
    const glm::vec3 mid = lut.at(8, 8, 8);
    EXPECT_GT(mid.r, mid.b);
}

TEST(SmashChainBench, SceneHasBackgroundBandAndHighlightsAboveTheBloomThreshold) {
    const Image scene = makeSmashBenchScene(320, 180);
    ASSERT_EQ(scene.width(), 320);
    ASSERT_EQ(scene.height(), 180);
    float brightest = 0.0f;
    for (int y = 0; y < scene.height(); ++y)
        for (int x = 0; x < scene.width(); ++x) {
            const float* p = scene.pixel(x, y);
            EXPECT_EQ(p[3], y < 18 ? 0.0f : 1.0f) << x << "," << y;
            brightest = std::max(brightest, p[0]);
        }
    EXPECT_GT(brightest, 3.0f); // HDR highlights, far above the bloom threshold 0.4625
}

TEST(SmashChainBench, TimingCountsItsRunsInOrder) {
    const SmashChainTiming t = benchmarkSmashChain(64, 36, 3, 1);
    EXPECT_EQ(t.runs, 3);
    EXPECT_LE(t.bestMs, t.medianMs);
    EXPECT_LE(t.medianMs, t.worstMs);
    EXPECT_GT(t.bestMs, 0.0);
    EXPECT_THROW(benchmarkSmashChain(0, 36, 1), Error);
    EXPECT_THROW(benchmarkSmashChain(64, -1, 1), Error);
}
