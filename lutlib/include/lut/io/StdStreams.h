// SPDX-License-Identifier: Apache-2.0
#pragma once
// "-" on lutkit's command lines: standard input, read whole and bounded. Writes to standard
// output go through lut/io/OutputFile.h (a LUT file's: lut/io/LutWriter.h).
#include "lut/Error.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace lut {

// Whether an input path names standard input: "-", or the names the system gives it
// (/dev/stdin, /dev/fd/0, /proc/self/fd/0), which are read as "-" is (`lutkit info /dev/stdin`
// said "no format reads '' files").
inline bool isStdinName(const std::string& path) {
    return path == "-" || path == "/dev/stdin" || path == "/dev/fd/0" || path == "/proc/self/fd/0";
}

// All of standard input. Throws lut::LimitError past maxBytes ("-: standard input is over the
// limit of N bytes") and lut::Error when it cannot be read.
std::string readStandardInput(std::size_t maxBytes);

// What a stream may be, judged from its first bytes: at most `bytes` in all (0 = maxBytes), with
// `what` saying why in the error past it ("its PNG header declares 64x64 pixels").
struct StreamBound {
    std::uint64_t bytes = 0;
    std::string what;
};
// The same, bounded by its content: once the first kStreamHeadBytes (1 MiB) have arrived (or
// all of it, when it is shorter), bound(head) says how long the whole may be, or throws to
// refuse it at once (standard input that is no format the caller reads: `lutkit info - <
// /dev/zero` stops after 1 MiB instead of taking 2 GB). Past the bound: lut::LimitError "-:
// standard input is over the N bytes WHAT".
constexpr std::size_t kStreamHeadBytes = std::size_t(1) << 20;
std::string readStandardInput(std::size_t maxBytes,
                              const std::function<StreamBound(const std::string& head)>& bound);

} // namespace lut
