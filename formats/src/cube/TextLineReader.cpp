// SPDX-License-Identifier: Apache-2.0
#include "cube/TextLineReader.h"

#include "lut/LimitError.h"

#include <algorithm>
#include <climits>
#include <cstring>

namespace lut::formats {

TextLineReader::TextLineReader(std::string_view data, std::string path, std::size_t maxLineBytes)
    : m_data(data), m_path(std::move(path)), m_maxLineBytes(maxLineBytes) {
    if (m_data.size() >= 3 && static_cast<unsigned char>(m_data[0]) == 0xEF &&
        static_cast<unsigned char>(m_data[1]) == 0xBB &&
        static_cast<unsigned char>(m_data[2]) == 0xBF) {
        m_bom = true;
        m_pos = 3;
    }
    // The first line end decides whether a lone CR ends lines (classic Mac OS files). Look no
    // further than one maximal line: the first next() refuses a longer line anyway.
    const std::size_t window = std::min(m_data.size() - m_pos, m_maxLineBytes + 2);
    const char* begin = m_data.data() + m_pos;
    for (std::size_t i = 0; i < window; ++i) {
        if (begin[i] == '\n')
            break;
        if (begin[i] == '\r') {
            if (i + 1 >= m_data.size() - m_pos || begin[i + 1] != '\n')
                m_terminator = '\r';
            break;
        }
    }
}

bool TextLineReader::next(TextLine& line) {
    if (m_pos >= m_data.size())
        return false;
    if (m_line < INT_MAX)
        ++m_line;
    const char* begin = m_data.data() + m_pos;
    const std::size_t remaining = m_data.size() - m_pos;
    const std::size_t window = std::min(remaining, m_maxLineBytes + 2);
    const char* end = static_cast<const char*>(std::memchr(begin, m_terminator, window));
    std::size_t length;
    std::size_t consumed;
    LineEnd kind;
    if (end) {
        length = static_cast<std::size_t>(end - begin);
        consumed = length + 1;
        kind = m_terminator == '\r' ? LineEnd::CR : LineEnd::LF;
        if (kind == LineEnd::LF && length > 0 && begin[length - 1] == '\r') {
            --length;
            kind = LineEnd::CRLF;
        }
    } else {
        if (remaining > m_maxLineBytes + 1)
            length = m_maxLineBytes + 1; // too long; do not look further
        else
            length = remaining;
        consumed = length;
        kind = LineEnd::None;
        // A file in LF mode that ends in a lone CR: the CR is the line end.
        if (length == remaining && length > 0 && begin[length - 1] == '\r') {
            --length;
            kind = LineEnd::CR;
        }
    }
    if (length > m_maxLineBytes) {
        std::string after = ")";
        if (m_terminator == '\n' && std::memchr(begin, '\r', window))
            after += "; its line ends may be a lone CR (classic Mac OS)";
        throw LineLimitError(
            m_path, m_line, static_cast<int>(m_maxLineBytes) + 1, LimitId::MaxTextLineBytes,
            "line is longer than the limit of " + std::to_string(m_maxLineBytes) + " bytes (",
            after, std::string(begin, std::min<std::size_t>(length, 61)));
    }
    line.text = std::string_view(begin, length);
    line.number = m_line;
    line.end = kind;
    m_pos += consumed;
    m_lastLength = length;
    m_lastTerminated = kind != LineEnd::None;
    return true;
}

std::pair<int, int> TextLineReader::endPosition() const {
    if (m_line == 0)
        return {1, 1};
    if (m_lastTerminated)
        return {m_line < INT_MAX ? m_line + 1 : m_line, 1};
    return {m_line, static_cast<int>(m_lastLength) + 1};
}

void TextLineReader::fail(int line, int column, std::string message, std::string offending) const {
    throw ParseError(m_path, line, column, std::move(message), std::move(offending));
}

} // namespace lut::formats
