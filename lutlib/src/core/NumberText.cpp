// SPDX-License-Identifier: Apache-2.0
#include "lut/NumberText.h"

#include <fast_float/fast_float.h>
#define FMT_HEADER_ONLY
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

// GCC's standard library has floating-point from_chars and to_chars (the Linux and Windows
// builds); Emscripten's libc++ (the browser edition) has neither.
#if defined(__cpp_lib_to_chars)
#define LUTKIT_STD_CHARS 1
#else
#define LUTKIT_STD_CHARS 0
#endif

namespace lut {

namespace {

// Whether the number's text (a decimal in general format, as parsed) names infinity, and whether
// its significand has a digit other than zero: a finite text read as infinity overflowed, one
// with a non-zero digit read as zero underflowed.
bool namesInfinity(const char* p, const char* end) {
    if (p < end && *p == '-')
        ++p;
    return p < end && (*p == 'i' || *p == 'I');
}

bool hasNonZeroDigit(const char* p, const char* end) {
    for (; p < end; ++p) {
        if (*p == 'e' || *p == 'E')
            return false;
        if (*p >= '1' && *p <= '9')
            return true;
    }
    return false;
}

template <class T> std::from_chars_result parse(const char* first, const char* last, T& value) {
    T v{};
    const auto r = fast_float::from_chars(first, last, v);
    std::from_chars_result out{r.ptr, r.ec};
    if (r.ec != std::errc())
        return out;
    if ((std::isinf(v) && !namesInfinity(first, r.ptr)) ||
        (v == T(0) && hasNonZeroDigit(first, r.ptr))) {
        out.ec = std::errc::result_out_of_range;
        return out;
    }
    value = v;
    return out;
}

std::to_chars_result put(char* first, char* last, const char* text, std::size_t n) {
    if (static_cast<std::size_t>(last - first) < n)
        return {last, std::errc::value_too_large};
    std::memcpy(first, text, n);
    return {first + n, std::errc()};
}

// The shortest digits that read back as `value` (Dragonbox), in printf's %f or %e style,
// whichever is shorter (%f on a tie), as the standard asks of std::to_chars(first, last, value).
template <class T> std::to_chars_result shortest(char* first, char* last, T value) {
    char buf[400];
    std::size_t n = 0;
    if (std::signbit(value))
        buf[n++] = '-';
    if (std::isnan(value)) {
        std::memcpy(buf + n, "nan", 3);
        return put(first, last, buf, n + 3);
    }
    if (std::isinf(value)) {
        std::memcpy(buf + n, "inf", 3);
        return put(first, last, buf, n + 3);
    }
    if (value == T(0)) {
        buf[n++] = '0';
        return put(first, last, buf, n);
    }
    const auto dec = fmt::detail::dragonbox::to_decimal(std::fabs(value));
    char digits[24];
    const int nd = std::snprintf(digits, sizeof digits, "%llu",
                                 static_cast<unsigned long long>(dec.significand));
    const int e = dec.exponent; // value = digits * 10^e
    const int sciExp = e + nd - 1;
    const int absExp = sciExp < 0 ? -sciExp : sciExp;
    const int sciLen = nd + (nd > 1 ? 1 : 0) + 2 + (absExp >= 100 ? 3 : 2);
    const int fixedLen = e >= 0 ? nd + e : nd + e > 0 ? nd + 1 : 2 - (nd + e) + nd;
    if (fixedLen <= sciLen) {
        if (e >= 0) {
            std::memcpy(buf + n, digits, static_cast<std::size_t>(nd));
            n += static_cast<std::size_t>(nd);
            for (int i = 0; i < e; ++i)
                buf[n++] = '0';
        } else if (nd + e > 0) {
            const int whole = nd + e;
            std::memcpy(buf + n, digits, static_cast<std::size_t>(whole));
            n += static_cast<std::size_t>(whole);
            buf[n++] = '.';
            std::memcpy(buf + n, digits + whole, static_cast<std::size_t>(nd - whole));
            n += static_cast<std::size_t>(nd - whole);
        } else {
            buf[n++] = '0';
            buf[n++] = '.';
            for (int i = 0; i < -(nd + e); ++i)
                buf[n++] = '0';
            std::memcpy(buf + n, digits, static_cast<std::size_t>(nd));
            n += static_cast<std::size_t>(nd);
        }
        return put(first, last, buf, n);
    }
    buf[n++] = digits[0];
    if (nd > 1) {
        buf[n++] = '.';
        std::memcpy(buf + n, digits + 1, static_cast<std::size_t>(nd - 1));
        n += static_cast<std::size_t>(nd - 1);
    }
    n += static_cast<std::size_t>(
        std::snprintf(buf + n, sizeof buf - n, "e%c%02d", sciExp < 0 ? '-' : '+', absExp));
    return put(first, last, buf, n);
}

} // namespace

namespace detail {

std::from_chars_result fromCharsPortable(const char* first, const char* last, float& value) {
    return parse(first, last, value);
}

std::from_chars_result fromCharsPortable(const char* first, const char* last, double& value) {
    return parse(first, last, value);
}

std::to_chars_result toCharsPortable(char* first, char* last, float value) {
    return shortest(first, last, value);
}

std::to_chars_result toCharsPortable(char* first, char* last, double value) {
    return shortest(first, last, value);
}

std::to_chars_result toCharsFixedPortable(char* first, char* last, double value, int precision) {
    // printf's %.Nf is correctly rounded in glibc, musl and MinGW-w64's own printf, as
    // std::to_chars with a precision is.
    const int n = std::snprintf(nullptr, 0, "%.*f", precision, value);
    if (n < 1 || last - first < n) // n >= 1 said for GCC's -Wformat-truncation
        return {last, std::errc::value_too_large};
    std::string text(static_cast<std::size_t>(n) + 1, '\0');
    std::snprintf(text.data(), text.size(), "%.*f", precision, value);
    return put(first, last, text.data(), static_cast<std::size_t>(n));
}

} // namespace detail

std::from_chars_result fromChars(const char* first, const char* last, float& value) {
#if LUTKIT_STD_CHARS
    return std::from_chars(first, last, value);
#else
    return detail::fromCharsPortable(first, last, value);
#endif
}

std::from_chars_result fromChars(const char* first, const char* last, double& value) {
#if LUTKIT_STD_CHARS
    return std::from_chars(first, last, value);
#else
    return detail::fromCharsPortable(first, last, value);
#endif
}

std::to_chars_result toChars(char* first, char* last, float value) {
#if LUTKIT_STD_CHARS
    return std::to_chars(first, last, value);
#else
    return detail::toCharsPortable(first, last, value);
#endif
}

std::to_chars_result toChars(char* first, char* last, double value) {
#if LUTKIT_STD_CHARS
    return std::to_chars(first, last, value);
#else
    return detail::toCharsPortable(first, last, value);
#endif
}

std::to_chars_result toCharsFixed(char* first, char* last, double value, int precision) {
#if LUTKIT_STD_CHARS
    return std::to_chars(first, last, value, std::chars_format::fixed, precision);
#else
    return detail::toCharsFixedPortable(first, last, value, precision);
#endif
}

} // namespace lut
