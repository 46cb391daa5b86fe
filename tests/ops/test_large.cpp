// SPDX-License-Identifier: Apache-2.0
// The LUT maths at the largest size a LUT may have (256^3 entries, 200 MB of floats): results
// still exact where they must be and finite everywhere. Times are printed, never asserted.
#include "OpsTestUtil.h"

#include "lut/ops/Clipping.h"
#include "lut/ops/Compose.h"
#include "lut/ops/Diff.h"
#include "lut/ops/Invert.h"
#include "lut/ops/Plot.h"
#include "lut/ops/Smooth.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

using namespace lut;
using namespace lut::opstest;

namespace {

double since(std::chrono::steady_clock::time_point t0) {
    return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Cheap to build at 256^3 and one-to-one: a little contrast per channel plus crosstalk.
glm::vec3 cheapGrade(glm::vec3 x) {
    const glm::vec3 t = x + 0.2f * x * (1.0f - x) * (x - 0.5f);
    return {0.9f * t.r + 0.1f * t.g, 0.05f * t.r + 0.9f * t.g + 0.05f * t.b,
            0.1f * t.g + 0.9f * t.b};
}

} // namespace

TEST(LargeLuts, Size256) {
    auto t0 = std::chrono::steady_clock::now();
    const Lut3D a = lutFrom(256, cheapGrade);
    std::printf("[large] build 256^3: %.0f ms\n", since(t0));

    t0 = std::chrono::steady_clock::now();
    const DiffReport same = diffLuts(a, a);
    std::printf("[large] diff(A, A): %.0f ms\n", since(t0));
    EXPECT_TRUE(same.identical());
    EXPECT_EQ(same.count, a.entryCount());

    t0 = std::chrono::steady_clock::now();
    const ClipCount clip = countOutOfRange(a);
    std::printf("[large] countOutOfRange: %.1f ms\n", since(t0));
    EXPECT_EQ(clip.entries, a.entryCount());

    // Composing with the 2-point identity changes nothing (entries are inside [0, 1]).
    t0 = std::chrono::steady_clock::now();
    const OpResult c = compose(a, Lut3D::identity(2));
    std::printf("[large] compose at 256: %.0f ms, %s\n", since(t0), c.error.str().c_str());
    ASSERT_EQ(c.lut.size(), 256);
    for (std::size_t i = 0; i < a.entryCount(); i += 9973)
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(c.lut.entries()[i][ch], a.entries()[i][ch], 1e-6);

    t0 = std::chrono::steady_clock::now();
    const OpResult s = smooth(Lut3D::identity(256), 1.0);
    std::printf("[large] smooth identity at 256: %.0f ms\n", since(t0));
    EXPECT_TRUE(sameBits(s.lut, Lut3D::identity(256)));

    t0 = std::chrono::steady_clock::now();
    InvertOptions o;
    o.size = 9;
    const InvertResult inv = invert(a, o);
    std::printf("[large] invert 256 -> 9: %.0f ms, unreachable %zu, round trip %s\n", since(t0),
                inv.report.unreachable, inv.report.roundTrip.str().c_str());
    EXPECT_TRUE(allFinite(inv.lut));
    EXPECT_EQ(inv.report.foldedCells, 0u);

    t0 = std::chrono::steady_clock::now();
    const Plot p = plotLut(a);
    std::printf("[large] plot 256: %.0f ms\n", since(t0));
    for (float v : p.image.pixels())
        ASSERT_TRUE(std::isfinite(v));
}
