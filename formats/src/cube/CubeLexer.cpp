// SPDX-License-Identifier: Apache-2.0
#include "cube/CubeLexer.h"
#include "lut/NumberText.h"

namespace lut::formats::cube {

std::string floatText(float v) {
    char buf[32];
    auto r = lut::toChars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

NumStatus parseFloat(std::string_view tok, float& out) {
    const char* p = tok.data();
    const char* e = p + tok.size();
    if (p < e && *p == '+') {
        ++p;
        if (p < e && (*p == '+' || *p == '-'))
            return NumStatus::NotNumber;
    }
    if (p == e)
        return NumStatus::NotNumber;
    float v = 0.0f;
    const auto r = lut::fromChars(p, e, v);
    if (r.ptr != e || r.ec == std::errc::invalid_argument)
        return NumStatus::NotNumber;
    if (r.ec == std::errc::result_out_of_range) {
        // Too large or too small for a float: tell which from the double value (or exponent).
        double d = 0.0;
        const auto r2 = lut::fromChars(p, e, d);
        const bool negative = *p == '-';
        if (r2.ec == std::errc{} && std::isfinite(d)) {
            if (std::fabs(d) >= 1.0)
                return NumStatus::TooLarge;
            out = static_cast<float>(d);
            return NumStatus::Ok;
        }
        const std::string_view t(p, static_cast<std::size_t>(e - p));
        if (t.find("e-") != std::string_view::npos || t.find("E-") != std::string_view::npos) {
            out = negative ? -0.0f : 0.0f;
            return NumStatus::Ok;
        }
        return NumStatus::TooLarge;
    }
    if (!std::isfinite(v))
        return NumStatus::NonFinite;
    out = v;
    return NumStatus::Ok;
}

Tokens splitTokens(const TextLine& line, const char* p, const char* e) {
    Tokens t;
    t.contentEnd = p;
    for (;;) {
        p = skipSpace(p, e);
        if (p == e)
            break;
        if (*p == '#') {
            t.comment = p;
            break;
        }
        const char* q = tokenEnd(p, e);
        if (t.count < 4)
            t.tok[static_cast<std::size_t>(t.count)] = {
                std::string_view(p, static_cast<std::size_t>(q - p)), columnOf(line, p)};
        ++t.count;
        t.contentEnd = q;
        p = q;
    }
    return t;
}

} // namespace lut::formats::cube
