// SPDX-License-Identifier: Apache-2.0
#include "lut/Error.h"

namespace lut {

static std::string formatParseError(const std::string& path, int line, int column,
                                    const std::string& message, const std::string& offending) {
    std::string s = path;
    if (line > 0) {
        s += ":" + std::to_string(line);
        if (column > 0)
            s += ":" + std::to_string(column);
    }
    s += ": " + message;
    if (!offending.empty()) {
        // Keep the message one line and short: long or binary text is cut and escaped.
        std::string shown;
        for (char c : offending.substr(0, 60)) {
            unsigned char u = static_cast<unsigned char>(c);
            if (u < 0x20 || u >= 0x7f) {
                static const char* hex = "0123456789abcdef";
                shown += "\\x";
                shown += hex[u >> 4];
                shown += hex[u & 15];
            } else {
                shown += c;
            }
        }
        if (offending.size() > 60)
            shown += "...";
        s += " (found '" + shown + "')";
    }
    return s;
}

ParseError::ParseError(std::string path, int line, int column, std::string message,
                       std::string offending)
    : Error(formatParseError(path, line, column, message, offending)), m_path(std::move(path)),
      m_line(line), m_column(column), m_message(std::move(message)),
      m_offending(std::move(offending)) {}

std::string Diagnostic::str() const {
    std::string s = path;
    if (line > 0) {
        s += ":" + std::to_string(line);
        if (column > 0)
            s += ":" + std::to_string(column);
    }
    if (!s.empty())
        s += ": ";
    switch (severity) {
    case Severity::Info:
        s += "note: ";
        break;
    case Severity::Warning:
        s += "warning: ";
        break;
    case Severity::Error:
        s += "error: ";
        break;
    }
    return s + message;
}

} // namespace lut
