// SPDX-License-Identifier: Apache-2.0
// lut/os/Memory.h on Windows.
#include "lut/os/Memory.h"

#include "Wide.h"

#include <malloc.h>

namespace lut::os {

void* allocateAligned(std::size_t bytes, std::size_t alignment) noexcept {
    return ::_aligned_malloc(bytes, alignment);
}

void freeAligned(void* block) noexcept {
    ::_aligned_free(block);
}

void* allocatePages(std::size_t bytes) noexcept {
    return ::VirtualAlloc(nullptr, bytes, MEM_RESERVE | MEM_COMMIT, PAGE_READWRITE);
}

void freePages(void* pages, std::size_t) noexcept {
    if (pages)
        ::VirtualFree(pages, 0, MEM_RELEASE);
}

void adviseHugePages(void*, std::size_t) noexcept {}

std::uint64_t physicalMemoryBytes() noexcept {
    MEMORYSTATUSEX status{};
    status.dwLength = sizeof status;
    return ::GlobalMemoryStatusEx(&status) ? status.ullTotalPhys : 0;
}

unsigned long processId() noexcept {
    return ::GetCurrentProcessId();
}

} // namespace lut::os
