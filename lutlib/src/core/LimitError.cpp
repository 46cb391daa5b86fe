// SPDX-License-Identifier: Apache-2.0
#include "lut/LimitError.h"

#include <cstring>

namespace lut {

const char* limitName(LimitId id) {
    switch (id) {
    case LimitId::Max3DSize:
        return "lut::limits::kMax3DSize";
    case LimitId::Max1DSize:
        return "lut::limits::kMax1DSize";
    case LimitId::MaxTextLineBytes:
        return "lut::limits::kMaxTextLineBytes";
    case LimitId::MaxLutFileBytes:
        return "lut::limits::kMaxLutFileBytes";
    }
    return "";
}

LimitExceeded::~LimitExceeded() = default;

std::string LimitExceeded::whatWith(std::string_view words) const {
    return m_before + std::string(words) + m_after;
}

namespace {

// ParseError's what() is "PATH:LINE:COL: " + message + " (found '...')": the parts around the
// limit's name are the same error's what() with the message cut there.
std::string parseWhat(const std::string& path, int line, int column, const std::string& message,
                      const std::string& offending) {
    return ParseError(path, line, column, message, offending).what();
}

} // namespace

LineLimitError::LineLimitError(const std::string& path, int line, int column, LimitId limit,
                               const std::string& before, const std::string& after,
                               std::string offending)
    : ParseError(path, line, column, before + limitName(limit) + after, offending),
      LimitExceeded(limit, parseWhat(path, line, column, before, {}),
                    // what() past the name: the message's end and the offending text
                    std::string(what() + parseWhat(path, line, column, before, {}).size() +
                                std::strlen(limitName(limit)))) {}

} // namespace lut
