// SPDX-License-Identifier: Apache-2.0
// The process's memory limit: see lut/io/MemoryLimit.h.
#include "lut/io/MemoryLimit.h"

#include "lut/Error.h"
#include "lut/os/Memory.h"

#include <atomic>

namespace lut {

namespace {

std::atomic<std::uint64_t> g_limit{0};

std::string mib(std::uint64_t bytes) {
    return std::to_string((bytes + (std::uint64_t(1) << 20) - 1) >> 20) + " MiB";
}

} // namespace

void setMemoryLimit(std::uint64_t bytes) {
    g_limit.store(bytes);
}

std::uint64_t defaultMemoryLimit() {
    const std::uint64_t physical = os::physicalMemoryBytes();
    return physical > 0 ? physical / 2 : std::uint64_t(4) << 30;
}

std::uint64_t memoryLimit() {
    const std::uint64_t set = g_limit.load();
    return set > 0 ? set : defaultMemoryLimit();
}

void checkMemoryLimit(const std::string& path, const std::string& what, std::uint64_t bytes) {
    const std::uint64_t limit = memoryLimit();
    if (bytes > limit)
        throw LimitError(path + ": " + what + " needs " + mib(bytes) +
                         ", over the memory limit of " + mib(limit) + " (--max-memory)");
}

} // namespace lut
