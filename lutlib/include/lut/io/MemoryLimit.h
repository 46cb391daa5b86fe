// SPDX-License-Identifier: Apache-2.0
#pragma once
// The memory one command may take for what it reads and holds at once (lutkit's --max-memory,
// which every command takes): a float frame, a picture's subsample, standard input read whole.
// One limit for the process, half the machine's physical memory unless set (4 GiB when the
// machine does not say). What streams (a picture read a chunk of rows at a time: match, check
// --image, atlas, apply) stays far below it whatever the file.
#include <cstdint>
#include <string>

namespace lut {

// 0 = the default.
void setMemoryLimit(std::uint64_t bytes);
std::uint64_t memoryLimit();
// Half the physical memory (the default).
std::uint64_t defaultMemoryLimit();
// Throws lut::LimitError "PATH: WHAT needs N MiB, over the memory limit of M MiB" when bytes
// pass the limit.
void checkMemoryLimit(const std::string& path, const std::string& what, std::uint64_t bytes);

} // namespace lut
