// SPDX-License-Identifier: Apache-2.0
#include "lut/Parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace lut {

bool threadsAvailable() {
#ifdef LUTKIT_NO_THREADS
    return false;
#else
    return true;
#endif
}

int resolveThreads(int nthreads) {
    if (!threadsAvailable())
        return 1;
    if (nthreads > 0)
        return nthreads;
    const unsigned hw = std::thread::hardware_concurrency();
    return hw == 0 ? 1 : static_cast<int>(hw);
}

void parallelFor(int count, int nthreads, const std::function<void(int, int)>& fn) {
    if (count <= 0)
        return;
    const int n = std::min(resolveThreads(nthreads), count);
    if (n <= 1) {
        fn(0, count);
        return;
    }
    std::vector<std::thread> threads;
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(n));
    threads.reserve(static_cast<std::size_t>(n - 1));
    auto chunk = [&](int i) {
        const int begin = static_cast<int>(static_cast<long long>(count) * i / n);
        const int end = static_cast<int>(static_cast<long long>(count) * (i + 1) / n);
        try {
            fn(begin, end);
        } catch (...) {
            errors[static_cast<std::size_t>(i)] = std::current_exception();
        }
    };
    for (int i = 1; i < n; ++i)
        threads.emplace_back(chunk, i);
    chunk(0);
    for (auto& t : threads)
        t.join();
    for (auto& e : errors)
        if (e)
            std::rethrow_exception(e);
}

void parallelForDynamic(int count, int nthreads, int grain,
                        const std::function<void(int, int)>& fn) {
    if (count <= 0)
        return;
    grain = std::max(1, grain);
    const int chunks = (count + grain - 1) / grain;
    const int n = std::min(resolveThreads(nthreads), chunks);
    if (n <= 1) {
        fn(0, count);
        return;
    }
    std::atomic<int> next{0};
    std::atomic<bool> failed{false};
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(n));
    auto worker = [&](int i) {
        try {
            for (;;) {
                if (failed.load(std::memory_order_relaxed))
                    return;
                const int c = next.fetch_add(1, std::memory_order_relaxed);
                if (c >= chunks)
                    return;
                const int begin = c * grain;
                fn(begin, std::min(count, begin + grain));
            }
        } catch (...) {
            errors[static_cast<std::size_t>(i)] = std::current_exception();
            failed = true;
        }
    };
    std::vector<std::thread> threads;
    threads.reserve(static_cast<std::size_t>(n - 1));
    for (int i = 1; i < n; ++i)
        threads.emplace_back(worker, i);
    worker(0);
    for (auto& t : threads)
        t.join();
    for (auto& e : errors)
        if (e)
            std::rethrow_exception(e);
}

} // namespace lut
