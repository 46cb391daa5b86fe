// SPDX-License-Identifier: Apache-2.0
#pragma once
// A tiny JSON writer for the --json output of lutkit info and convert: strings are escaped
// (quotes, backslashes, control characters; bytes >= 0x80 pass through as UTF-8) and non-finite
// numbers become null, so the output is always valid JSON.
#include "lut/Error.h"
#include "lut/ErrorStats.h"

#include <cmath>
#include <glm/vec3.hpp>

#include <cstdio>
#include <string>
#include <string_view>

namespace lut::cli::json {

inline std::string quote(std::string_view s) {
    std::string out = "\"";
    for (const char ch : s) {
        const auto c = static_cast<unsigned char>(ch);
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        case '\b':
            out += "\\b";
            break;
        case '\f':
            out += "\\f";
            break;
        default:
            if (c < 0x20 || c == 0x7f) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", c);
                out += buf;
            } else {
                out += ch;
            }
        }
    }
    return out + "\"";
}

inline std::string number(double v) {
    if (!std::isfinite(v))
        return "null";
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

// [r, g, b]
inline std::string vec3(const glm::dvec3& v) {
    return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]";
}

inline std::string stats(const ErrorStats& s) {
    // max_is_bound: max bounds the difference over every input (max_seen: the largest at the
    // held_out_points between the lattice points; 0 points: max is exact)
    std::string bound;
    if (s.bounded)
        bound = ", \"max_is_bound\": true, \"max_seen\": " + number(s.sampledMax) +
                ", \"held_out_points\": " + std::to_string(s.heldOutPoints);
    return "{\"max\": " + number(s.maxAbs) + ", \"mean\": " + number(s.meanAbs) +
           ", \"max_8bit_steps\": " + number(s.maxSteps8()) +
           ", \"mean_8bit_steps\": " + number(s.meanSteps8()) + bound +
           ", \"seconds\": " + number(s.seconds) + "}";
}

inline const char* severity(Diagnostic::Severity s) {
    switch (s) {
    case Diagnostic::Severity::Info:
        return "info";
    case Diagnostic::Severity::Warning:
        return "warning";
    case Diagnostic::Severity::Error:
        return "error";
    }
    return "warning";
}

inline std::string diagnostics(const Diagnostics& diags) {
    std::string out = "[";
    for (std::size_t i = 0; i < diags.size(); ++i) {
        const auto& d = diags[i];
        out += (i ? ", " : "") + std::string("{\"severity\": ") + quote(severity(d.severity)) +
               ", \"path\": " + quote(d.path) + ", \"line\": " + std::to_string(d.line) +
               ", \"column\": " + std::to_string(d.column) + ", \"message\": " + quote(d.message) +
               "}";
    }
    return out + "]";
}

} // namespace lut::cli::json
