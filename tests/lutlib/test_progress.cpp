// SPDX-License-Identifier: Apache-2.0
// lut/Progress.h: what a long call reports and how it stops when cancelled (the editor runs
// reads, writes and comparisons on workers and cancels them from the window's thread).
#include "lut/Progress.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>
#include <vector>

using namespace lut;

TEST(Progress, ReportsClampedFractionsAndIgnoresNaN) {
    std::vector<double> seen;
    Progress p([&](double f) { seen.push_back(f); });
    p.report(0.25);
    p.report(-1.0);
    p.report(2.0);
    p.report(NAN);
    EXPECT_EQ(seen, (std::vector<double>{0.25, 0.0, 1.0}));
}

TEST(Progress, APartMapsOntoItsRangeOfTheParent) {
    std::vector<double> seen;
    Progress whole([&](double f) { seen.push_back(f); });
    const Progress first(whole, 0.0, 0.6), second(whole, 0.6, 1.0);
    first.report(0.5);
    first.report(1.0);
    second.report(0.5);
    second.report(1.0);
    ASSERT_EQ(seen.size(), 4u);
    EXPECT_DOUBLE_EQ(seen[0], 0.3);
    EXPECT_DOUBLE_EQ(seen[1], 0.6);
    EXPECT_DOUBLE_EQ(seen[2], 0.8);
    EXPECT_DOUBLE_EQ(seen[3], 1.0);
}

TEST(Progress, CheckThrowsOnceCancelledAndAPartFollowsItsParent) {
    Progress whole;
    const Progress part(whole, 0.2, 0.4);
    EXPECT_NO_THROW(part.check("x.png"));
    EXPECT_FALSE(part.cancelled());
    std::thread canceller([&] { whole.cancel(); }); // from another thread, as the window does
    canceller.join();
    EXPECT_TRUE(whole.cancelled());
    EXPECT_TRUE(part.cancelled());
    try {
        part.check("x.png");
        FAIL() << "no CancelledError";
    } catch (const CancelledError& e) {
        EXPECT_STREQ(e.what(), "x.png: cancelled");
    }
    // A null Progress is none: nothing reported, nothing cancelled.
    EXPECT_NO_THROW(checkCancelled(nullptr, "x"));
    reportProgress(nullptr, 0.5);
}
