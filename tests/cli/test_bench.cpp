// SPDX-License-Identifier: Apache-2.0
// lutkit bench --json: the figures of the table as one JSON document (issue 27), each with the
// yardstick it is measured against in the same run. Times are not asserted (speed goes in
// benchmarks, never in a test); what must hold whatever the machine's load is.
#include "TestSupport.h"
#include "test_convert_json.h"

#include <gtest/gtest.h>

#include <cmath>

using lut::test::runCli;

TEST(BenchJson, EveryRowWithItsYardstickAndError) {
    const auto r = runCli("bench --width 32 --height 8 --sizes 2,17 --interp tetrahedral,trilinear "
                          "--reps 1 --no-ocio --scalar --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto js = lut::test::json::parse(r.out);
    const double copyNs = js["memcpy"]["ns_per_pixel"].number;
    EXPECT_GT(copyNs, 0.0);
    EXPECT_EQ(js["frame"]["width"].number, 32);
    EXPECT_GE(js["machine"]["cores"].number, 1);
    const std::string isa = js["kernels"].string;
    EXPECT_TRUE(isa == "avx512" || isa == "avx2" || isa == "scalar") << isa;
    const auto& rows = js["rows"].array;
    ASSERT_EQ(rows.size(), 8u); // 2 methods x 2 sizes, each with its scalar row
    for (const auto& row : rows) {
        const double ns = row["ns_per_pixel"].number;
        EXPECT_GT(ns, 0.0);
        // The ratio is the row's time over the copy's, both printed: it must say so.
        EXPECT_NEAR(row["memcpy_ratio"].number, ns / copyNs, 1e-6 * (ns / copyNs));
        EXPECT_TRUE(row["ocio_ns_per_pixel"].isNull()); // --no-ocio
        if (row["path"].string == "scalar")
            continue;
        EXPECT_EQ(row["path"].string, isa);
        EXPECT_GE(row["max_err"].number, row["mean_err"].number);
        EXPECT_GT(row["mean_err"].number, 0.0);
    }
    // The error is measured against the analytic grade: a 17^3 LUT follows it far more closely
    // than a 2^3 one (a printed error that did not move with the size would be no measure).
    EXPECT_LT(rows[2]["max_err"].number * 10, rows[0]["max_err"].number);
    const auto& other = js["other"].array;
    ASSERT_EQ(other.size(), 1u);
    EXPECT_EQ(other[0]["label"].string, "smash chain 1920x1080");
    EXPECT_LE(other[0]["best_ms"].number, other[0]["median_ms"].number);
    EXPECT_LE(other[0]["median_ms"].number, other[0]["worst_ms"].number);
    EXPECT_GT(other[0]["copy_ms"].number, 0.0);
    EXPECT_EQ(other[0]["target_ms"].number, 10);
}
