// SPDX-License-Identifier: Apache-2.0
// Progress and cancellation of the diffs and heat maps (lut/Progress.h through DiffOptions and
// HeatMapOptions): the editor compares a LUT over a 4K picture on a worker and cancels it from
// the window. The results with a Progress are the results without one, bit for bit; a cancel
// from another thread stops the work with CancelledError.
#include "OpsTestUtil.h"

#include "lut/Image.h"
#include "lut/ops/Diff.h"
#include "lut/ops/HeatMap.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <thread>
#include <vector>

using namespace lut;
using namespace lut::opstest;

namespace {

Image gradientImage(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img.pixel(x, y);
            p[0] = float(x) / float(w - 1);
            p[1] = float(y) / float(h - 1);
            p[2] = float((x * 7 + y * 3) % 256) / 255.0f;
            p[3] = 1.0f;
        }
    return img;
}

} // namespace

TEST(DiffProgress, ReportsUpToOneAndChangesNothing) {
    const Lut3D a = lutFrom(17, smoothGrade), b = randomLut(9);
    const Image img = gradientImage(300, 200);
    std::mutex m;
    std::vector<double> seen;
    Progress p([&](double f) {
        std::lock_guard lock(m);
        seen.push_back(f);
    });
    DiffOptions o;
    o.progress = &p;
    const DiffReport with = diffLutsOnImage(a, b, img.view(), o);
    const DiffReport without = diffLutsOnImage(a, b, img.view());
    EXPECT_EQ(with.maxDeltaE, without.maxDeltaE);
    EXPECT_EQ(with.meanDeltaE, without.meanDeltaE);
    EXPECT_EQ(with.p95DeltaE, without.p95DeltaE);
    EXPECT_EQ(with.maxSteps8, without.maxSteps8);
    ASSERT_FALSE(seen.empty());
    // 60000 colours in blocks of 4096: at least 14 reports, the last one the whole.
    EXPECT_GE(seen.size(), 14u);
    EXPECT_DOUBLE_EQ(*std::max_element(seen.begin(), seen.end()), 1.0);

    std::vector<double> rows;
    Progress hp([&](double f) {
        std::lock_guard lock(m);
        rows.push_back(f);
    });
    HeatMapOptions ho;
    ho.progress = &hp;
    const HeatMap hw = diffHeatMap(a, b, img.view(), ho);
    const HeatMap hwo = diffHeatMap(a, b, img.view());
    EXPECT_EQ(hw.image.pixels(), hwo.image.pixels());
    EXPECT_EQ(rows.size(), 200u); // one report per row
    EXPECT_DOUBLE_EQ(*std::max_element(rows.begin(), rows.end()), 1.0);
}

TEST(DiffProgress, ACancelStopsTheDiffAndTheHeatMapBeforeTheEnd) {
    const Lut3D a = lutFrom(17, smoothGrade), b = randomLut(9);
    const Image img = gradientImage(1000, 1000);
    for (int which = 0; which < 2; ++which) {
        // Cancelled at the first report from a thread of its own (the window's thread, in the
        // editor), joined before the report returns: the work stops at its next check.
        std::atomic<double> reached{0.0};
        std::atomic<int> reports{0};
        Progress* self = nullptr;
        Progress p([&](double f) {
            double r = reached.load();
            while (f > r && !reached.compare_exchange_weak(r, f)) {
            }
            if (reports++ == 0)
                std::thread([self] { self->cancel(); }).join();
        });
        self = &p;
        bool stopped = false;
        try {
            if (which == 0) {
                DiffOptions o;
                o.progress = &p;
                diffLutsOnImage(a, b, img.view(), o);
            } else {
                HeatMapOptions o;
                o.progress = &p;
                diffHeatMap(a, b, img.view(), o);
            }
        } catch (const CancelledError& e) {
            stopped = true;
            EXPECT_STREQ(e.what(), which == 0 ? "diff: cancelled" : "heat map: cancelled");
        }
        EXPECT_TRUE(stopped) << which;
        // Each thread finishes the block or row it is in: far from the end.
        EXPECT_LT(reached.load(), 0.1) << which;
    }
}
