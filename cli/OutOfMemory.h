// SPDX-License-Identifier: Apache-2.0
#pragma once
// std::bad_alloc as one clear line with the size asked for: lutkit's operator new (main.cpp)
// notes the size of an allocation that fails before it throws, and the error handlers (the
// command line, the batch runner) say it.
#include <cstddef>
#include <string>

namespace lut::cli {

void noteFailedAllocation(std::size_t bytes) noexcept; // this thread's last failure
std::size_t lastFailedAllocation() noexcept;           // 0 = not known

// "out of memory: an allocation of N bytes (X MiB) failed", or "out of memory" when the size is
// not known (an allocator other than lutkit's own failed).
std::string outOfMemoryText();

} // namespace lut::cli
