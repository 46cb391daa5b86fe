#pragma once
#include <functional>

namespace lut {

// Number of worker threads for nthreads (0 = all hardware threads).
int resolveThreads(int nthreads);

// Runs fn(begin, end) over [0, count) split into contiguous chunks on up to nthreads threads
// (0 = all cores). Blocks until done; rethrows the first exception a chunk threw.
void parallelFor(int count, int nthreads, const std::function<void(int begin, int end)>& fn);

} // namespace lut
