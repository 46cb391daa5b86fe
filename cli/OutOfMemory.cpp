// SPDX-License-Identifier: Apache-2.0
#include "OutOfMemory.h"

#include <cstdio>

namespace lut::cli {

namespace {
thread_local std::size_t t_failed = 0;
}

void noteFailedAllocation(std::size_t bytes) noexcept {
    t_failed = bytes;
}

std::size_t lastFailedAllocation() noexcept {
    return t_failed;
}

std::string outOfMemoryText() {
    const std::size_t n = lastFailedAllocation();
    if (n == 0)
        return "out of memory";
    char mib[32];
    std::snprintf(mib, sizeof mib, "%.1f", static_cast<double>(n) / (1024.0 * 1024.0));
    return "out of memory: an allocation of " + std::to_string(n) + " bytes (" + mib +
           " MiB) failed";
}

} // namespace lut::cli
