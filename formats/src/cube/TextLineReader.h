// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one physical-line reader of the text formats. It exists so that every text reader counts
// lines the same way an editor does (OpenColorIO's readers drift after blank lines and comments):
// a line ends at LF, CR LF or (in a file whose first line end is a lone CR) CR; blank lines and
// comments are lines like any other; a UTF-8 byte order mark before line 1 is skipped and does
// not count as a column. Columns are 1-based byte offsets inside the line.
//
// Limits: a line longer than maxLineBytes is refused after looking at maxLineBytes + 2 bytes, so
// a "line of a gigabyte" costs no more than a normal one. The reader works on bytes in memory
// (files are read whole by lut::readFile, never mapped).
#include "lut/Error.h"
#include "lut/Limits.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

namespace lut::formats {

enum class LineEnd : std::uint8_t { None, LF, CRLF, CR };

struct TextLine {
    std::string_view text; // without its line end; on line 1 without the byte order mark
    int number = 0;        // 1-based physical line number
    LineEnd end = LineEnd::None;
};

class TextLineReader {
public:
    TextLineReader(std::string_view data, std::string path,
                   std::size_t maxLineBytes = limits::kMaxTextLineBytes);

    // The next physical line; false at the end of the data. Throws lut::ParseError naming the
    // line and the limit if the line is longer than maxLineBytes.
    bool next(TextLine& line);

    const std::string& path() const { return m_path; }
    // The bytes not yet returned by next().
    std::string_view rest() const { return m_data.substr(m_pos); }
    bool hasBom() const { return m_bom; }
    // True when the file's line ends are a lone CR (classic Mac OS).
    bool crOnly() const { return m_terminator == '\r'; }
    // Line and column just past the last byte: where "the file ends" messages point.
    std::pair<int, int> endPosition() const;

    [[noreturn]] void fail(int line, int column, std::string message,
                           std::string offending = {}) const;

private:
    std::string_view m_data;
    std::size_t m_pos = 0;
    std::string m_path;
    std::size_t m_maxLineBytes;
    int m_line = 0; // number of the last line returned
    char m_terminator = '\n';
    bool m_bom = false;
    // Length of the last line returned and whether it had a line end (for endPosition()).
    std::size_t m_lastLength = 0;
    bool m_lastTerminated = true;
};

// 1-based column of p inside line.text.
inline int columnOf(const TextLine& line, const char* p) {
    return static_cast<int>(p - line.text.data()) + 1;
}

} // namespace lut::formats
