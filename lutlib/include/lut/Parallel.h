// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <functional>

namespace lut {

// Whether this build can start threads: false in the browser edition (WebAssembly threads need
// the cross-origin isolation headers most static hosts do not send, docs/portable.md), where
// everything runs on the calling thread, in the same order of results.
bool threadsAvailable();

// Number of worker threads for nthreads (0 = all hardware threads); 1 without threads.
int resolveThreads(int nthreads);

// Runs fn(begin, end) over [0, count) split into contiguous chunks on up to nthreads threads
// (0 = all cores). Blocks until done; rethrows the first exception a chunk threw.
void parallelFor(int count, int nthreads, const std::function<void(int begin, int end)>& fn);

// The same with dynamic scheduling: each thread takes the next `grain` items until none are left,
// so uneven rows (or a core the OS takes away for a while) do not leave the other cores idle.
// fn is called any number of times, in any order; use it where the work of each item is
// independent of the others (results must not depend on how the range was cut).
void parallelForDynamic(int count, int nthreads, int grain,
                        const std::function<void(int begin, int end)>& fn);

} // namespace lut
