// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib's match: printf into a string, for the report's and the warnings' text. The
// format attribute has the compiler match every call's arguments to its format.
#include <cstdarg>
#include <cstdio>
#include <string>

namespace lut::detail {

[[gnu::format(printf, 1, 2)]] inline std::string fmt(const char* f, ...) {
    char buf[768];
    va_list args;
    va_start(args, f);
    std::vsnprintf(buf, sizeof buf, f, args);
    va_end(args);
    return buf;
}

} // namespace lut::detail
