// SPDX-License-Identifier: Apache-2.0
#pragma once
// The .cube lexer: whitespace and tokens of one line, and numbers. The hot path (fastRow, a plain
// data line of three numbers, with an exact Clinger fast path for the floats) is inline here so
// the parser and the parallel row reader share it; anything it does not take goes to the careful
// path (parseFloat, splitTokens), which tells exactly what is wrong.
#include "cube/TextLineReader.h"
#include "lut/NumberText.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace lut::formats::cube {

inline bool isSpace(char c) {
    return c == ' ' || c == '\t';
}
inline const char* skipSpace(const char* p, const char* e) {
    while (p < e && isSpace(*p))
        ++p;
    return p;
}
inline const char* tokenEnd(const char* p, const char* e) {
    while (p < e && !isSpace(*p))
        ++p;
    return p;
}
inline const char* trimRight(const char* b, const char* e) {
    while (e > b && isSpace(e[-1]))
        --e;
    return e;
}
inline bool isAlpha(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
// [b, e) without trailing whitespace, as a string (offending text in messages).
inline std::string content(const char* b, const char* e) {
    return std::string(b, static_cast<std::size_t>(trimRight(b, e) - b));
}

// The shortest text that reads back as v.
std::string floatText(float v);

enum class NumStatus { Ok, NotNumber, NonFinite, TooLarge };

// Parses the whole token as a float. Locale independent; accepts a leading '+'. Numbers too
// small for a float become 0 (or a denormal); too large ones are TooLarge, "nan"/"inf" NonFinite.
NumStatus parseFloat(std::string_view tok, float& out);

inline constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                    1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                    1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// Decimal text to float with the same result as std::from_chars, for the common case (at most
// 19 digits, exponent within +-22): m and 10^k are exact doubles, so m * 10^k or m / 10^k is
// rounded once to double; rounding that double to float gives the correctly rounded float unless
// the double lies exactly halfway between two floats, which goes to the general algorithm.
// Returns the end of the number, or nullptr when the general algorithm must decide.
inline const char* fastFloat(const char* p, const char* e, float& out) {
    bool negative = false;
    if (p < e && *p == '-') {
        negative = true;
        ++p;
    }
    std::uint64_t m = 0;
    const char* q = p;
    while (q < e && static_cast<unsigned>(*q - '0') < 10)
        m = m * 10 + static_cast<unsigned>(*q++ - '0');
    std::ptrdiff_t digits = q - p;
    int exp10 = 0;
    if (q < e && *q == '.') {
        const char* f = ++q;
        while (q < e && static_cast<unsigned>(*q - '0') < 10)
            m = m * 10 + static_cast<unsigned>(*q++ - '0');
        exp10 = -static_cast<int>(q - f);
        digits += q - f;
    }
    if (digits == 0 || digits > 19)
        return nullptr;
    if (q < e && (*q == 'e' || *q == 'E')) {
        const char* x = q + 1;
        bool expNegative = false;
        if (x < e && (*x == '-' || *x == '+'))
            expNegative = *x++ == '-';
        if (x == e || static_cast<unsigned>(*x - '0') >= 10)
            return nullptr;
        int v = 0;
        while (x < e && static_cast<unsigned>(*x - '0') < 10 && v < 1000)
            v = v * 10 + (*x++ - '0');
        if (x < e && static_cast<unsigned>(*x - '0') < 10)
            return nullptr;
        exp10 += expNegative ? -v : v;
        q = x;
    }
    if (m == 0) {
        out = negative ? -0.0f : 0.0f;
        return q;
    }
    if (m > (std::uint64_t(1) << 53) || exp10 < -22 || exp10 > 22)
        return nullptr;
    double d = static_cast<double>(m);
    d = exp10 < 0 ? d / kPow10[-exp10] : d * kPow10[exp10];
    std::uint64_t bits;
    std::memcpy(&bits, &d, sizeof bits);
    if ((bits & 0x1FFFFFFFu) == 0x10000000u)
        return nullptr; // exactly halfway between floats
    const float f = static_cast<float>(d);
    out = negative ? -f : f;
    return q;
}

// The hot path: a plain data line of three numbers (no comment, no '+', nothing odd). Anything
// else returns false and goes through the careful path, which reports or accepts it.
inline bool fastRow(const char* p, const char* e, float* out) {
    for (int i = 0; i < 3; ++i) {
        p = skipSpace(p, e);
        const char* q = fastFloat(p, e, out[i]);
        if (!q) {
            const auto r = lut::fromChars(p, e, out[i]);
            if (r.ec != std::errc{} || r.ptr == p)
                return false;
            if (!std::isfinite(out[i]))
                return false;
            q = r.ptr;
        }
        p = q;
        if (p < e && !isSpace(*p))
            return false;
    }
    return skipSpace(p, e) == e;
}

struct Token {
    std::string_view text;
    int column = 0;
};

// Up to 4 whitespace-separated tokens of [p, e), stopping at a token that starts with '#'.
struct Tokens {
    std::array<Token, 4> tok;
    int count = 0;          // tokens before any comment (may exceed 4; only 4 are kept)
    const char* contentEnd; // end of the last token before the comment
    const char* comment = nullptr;
};

Tokens splitTokens(const TextLine& line, const char* p, const char* e);

} // namespace lut::formats::cube
