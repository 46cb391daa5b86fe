// SPDX-License-Identifier: Apache-2.0
// parallelFor: every index exactly once, any thread count, exceptions come back to the caller.
#include "lut/Parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace lut;

TEST(Parallel, CoversEveryIndexOnce) {
    for (int count : {0, 1, 2, 5, 17, 1000}) {
        for (int threads : {0, 1, 2, 3, 16, 2000}) {
            std::vector<std::atomic<int>> hits(static_cast<std::size_t>(count));
            std::atomic<int> calls{0};
            parallelFor(count, threads, [&](int b, int e) {
                ASSERT_LE(0, b);
                ASSERT_LT(b, e); // no empty chunks
                ASSERT_LE(e, count);
                ++calls;
                for (int i = b; i < e; ++i)
                    ++hits[static_cast<std::size_t>(i)];
            });
            for (auto& h : hits)
                ASSERT_EQ(h.load(), 1) << count << " " << threads;
            EXPECT_LE(calls.load(), std::max(1, resolveThreads(threads)));
            if (count == 0) {
                EXPECT_EQ(calls.load(), 0);
            }
        }
    }
}

TEST(Parallel, ResolveThreads) {
    EXPECT_EQ(resolveThreads(3), 3);
    EXPECT_GE(resolveThreads(0), 1);
    EXPECT_EQ(resolveThreads(0),
              std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
    EXPECT_GE(resolveThreads(-1), 1);
}

TEST(Parallel, RethrowsAChunksException) {
    EXPECT_THROW(parallelFor(100, 4,
                             [](int b, int) {
                                 if (b > 0)
                                     throw std::runtime_error("chunk failed");
                             }),
                 std::runtime_error);
    EXPECT_THROW(parallelFor(10, 1, [](int, int) { throw std::logic_error("x"); }),
                 std::logic_error);
}
