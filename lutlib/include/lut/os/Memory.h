// SPDX-License-Identifier: Apache-2.0
#pragma once
// Memory from the system beyond operator new: over-aligned blocks (lutkit's operator new,
// cli/main.cpp), fresh pages for whole files (lut::readFileBytes) with the huge-page advice that
// makes first touches cheap on Linux, and how much memory the machine has.
#include <cstddef>
#include <cstdint>

namespace lut::os {

// A block of bytes aligned to alignment (a power of two, at least sizeof(void*)), or nullptr;
// freed by freeAligned only (Windows' aligned blocks are not std::free's).
void* allocateAligned(std::size_t bytes, std::size_t alignment) noexcept;
void freeAligned(void* block) noexcept;

// Fresh zeroed pages for a large buffer (an anonymous mapping), with huge pages asked for where
// the system has them; nullptr on failure. freePages takes the same size.
void* allocatePages(std::size_t bytes) noexcept;
void freePages(void* pages, std::size_t bytes) noexcept;
// Asks for huge pages under the 2 MiB-aligned inside of a large buffer not yet touched (Linux's
// transparent huge pages in "madvise" mode; elsewhere nothing). Only advice: contents are the same.
void adviseHugePages(void* data, std::size_t bytes) noexcept;

// The machine's physical memory in bytes, 0 when it cannot be told.
std::uint64_t physicalMemoryBytes() noexcept;
// The process's id (seeds temporary names).
unsigned long processId() noexcept;

} // namespace lut::os
