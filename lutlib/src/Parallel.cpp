#include "lut/Parallel.h"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace lut {

int resolveThreads(int nthreads) {
    if (nthreads > 0) return nthreads;
    const unsigned hw = std::thread::hardware_concurrency();
    return hw == 0 ? 1 : static_cast<int>(hw);
}

void parallelFor(int count, int nthreads, const std::function<void(int, int)>& fn) {
    if (count <= 0) return;
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
    for (int i = 1; i < n; ++i) threads.emplace_back(chunk, i);
    chunk(0);
    for (auto& t : threads) t.join();
    for (auto& e : errors)
        if (e) std::rethrow_exception(e);
}

} // namespace lut
