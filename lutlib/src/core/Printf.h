// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: printf into a std::string, for report, warning and finding text (match,
// roundtrip's fit and extract, check). The one such helper: the format attribute has the compiler
// match every call's arguments to its format (a %g given an int, or one argument too few, is a
// build error under -Werror; aeea765 fixed a warning that printed whatever the stack held). The
// text is never cut: a message longer than the first buffer is formatted again at its length.
#include <cstdarg>
#include <cstdio>
#include <string>

namespace lut::detail {

[[gnu::format(printf, 1, 2)]] inline std::string fmt(const char* f, ...) {
    char buf[512];
    va_list args;
    va_start(args, f);
    va_list again;
    va_copy(again, args);
    const int n = std::vsnprintf(buf, sizeof buf, f, args);
    va_end(args);
    std::string out;
    if (n >= static_cast<int>(sizeof buf)) {
        out.resize(static_cast<std::size_t>(n));
        std::vsnprintf(out.data(), out.size() + 1, f, again);
    } else if (n > 0) {
        out.assign(buf, static_cast<std::size_t>(n));
    }
    va_end(again);
    return out;
}

} // namespace lut::detail
