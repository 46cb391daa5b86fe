// SPDX-License-Identifier: Apache-2.0
#pragma once
// The .cube reader: Adobe Cube LUT Specification 1.0 and the DaVinci Resolve dialect.
//
// The spec in short (docs/specs/cube-format.md): text, one item per line (keyword, '#' comment or
// data), lines at most 250 bytes, LF ends. Keywords before the data, each once, upper case:
// TITLE "text", DOMAIN_MIN r g b / DOMAIN_MAX r g b (default 0 0 0 / 1 1 1, min < max), and one of
// LUT_1D_SIZE N (2..65536) or LUT_3D_SIZE N (2..256). Data: 3 floats per line, N rows (1D) or N^3
// rows (3D) with red fastest. Resolve adds LUT_1D_INPUT_RANGE / LUT_3D_INPUT_RANGE min max (one
// pair for all channels), a 1D shaper followed by a 3D table in one file (both size lines; the
// shaper rows come first), and the flags LUT_IN_VIDEO_RANGE / LUT_OUT_VIDEO_RANGE.
//
// Reading (what we accept beyond the spec, and what we refuse):
//  - CR LF, CR-only line ends, a UTF-8 BOM, blank lines, comments anywhere (also after the data
//    and at the end of a line), tabs, keywords in any case, an unquoted TITLE, '+' signs: all
//    accepted. With CubeReadOptions::strict each is reported as a Warning diagnostic (a
//    "departure", CubeKeywords.h), at most 3 per kind plus a count of the rest.
//  - A UTF-16 or UTF-32 file (a byte order mark, or a NUL in every other byte) is refused as such.
//  - Lines and columns are physical and 1-based (TextLineReader): a BOM is not a column.
//  - A keyword given twice with the same value is a departure; with a different value an error.
//  - Unknown keywords before the data are ignored with a Warning in every mode (files in the wild
//    carry vendor keywords); after the first data line any non-number is an error.
//  - DOMAIN_* applies to the only table, or to the shaper when the file has both (the whole
//    file's input domain); LUT_3D_INPUT_RANGE / LUT_1D_INPUT_RANGE set the cube / shaper domain.
//    Giving both for the same table is an error; an INPUT_RANGE for a table the file lacks is
//    ignored with a Warning.
//  - LUT_IN_VIDEO_RANGE / LUT_OUT_VIDEO_RANGE are recognised but not applied: the table is kept
//    as stored and an Info diagnostic says so (LutFile has no field for them).
//  - NaN / Inf policy: "nan", "inf", "infinity" in the data or keywords are refused in every mode
//    with an error naming line and column. A non-finite entry would spread into every pixel that
//    touches it and no conforming writer produces one. Numbers beyond the float range (1e39) are
//    refused too; numbers too small for a float (1e-50) become 0 (or a denormal).
//  - Values outside 0..1 are kept as read (the spec does not limit the table values).
//  - Limits: the file size (lut::limits::kMaxLutFileBytes) before reading, each size keyword
//    the moment it is read (before any data), each line's length (kMaxTextLineBytes) after at
//    most that many bytes, and the row count at the first extra row: a file with a billion rows
//    is refused at row N^3 + 1. Memory follows what the file holds, not what it claims: the
//    tables are allocated only when the bytes after the header can hold the declared rows (each
//    row takes at least 6 bytes, "0 0 0" and a line end); otherwise the rows are parsed without
//    being stored, which ends in the same error (a bad row or "found N before the end") as ever.
//  - Files are read into memory (lut::readFile), never mapped: a file that shrinks or changes
//    while it is read is reported as such, never a SIGBUS.
//  - Speed: no per-line allocation, floats by an exact Clinger fast path (CubeLexer.h; falls back
//    to std::from_chars), and plain big files parsed on all cores (ParallelRows.h); anything
//    unusual is re-read by the one sequential parser, which owns every message.
#include "cube/CubeKeywords.h"
#include "cube/CubeLexer.h"
#include "cube/TextLineReader.h"

#include "lut/Error.h"
#include "lut/LimitError.h"
#include "lut/LutFile.h"
#include "lut/formats/Cube.h"
#include "lut/io/InputFile.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lut::formats::cube {

// The bytes of a .cube file, read whole into memory through lut::readFileBytes (regular files
// only, at most lut::limits::kMaxLutFileBytes, refused if the file changes while it is read).
FileBytes readCubeFile(const std::string& path);

// The header of a regular file larger than its first kHeaderPrefixBytes, checked from those
// bytes alone (CubeParser::checkHeader): a declaration over the limits (LUT_3D_SIZE 257) is
// refused at its line before the rest of a file of any size is read. Other files: nothing.
constexpr std::size_t kHeaderPrefixBytes = 1 << 16;
void checkCubeFileHeader(const std::string& path, const CubeReadOptions& options);

// Where and how a keyword was first given.
struct KeySeen {
    int line = 0;
    int column = 0;
    std::string args;               // argument text, for "repeated with another value"
    std::array<int, 3> argColumn{}; // columns of the numbers
};

// One parse of one text. Header methods are in CubeHeader.cpp, the rest in CubeParser.cpp.
class CubeParser {
public:
    CubeParser(std::string_view text, const std::string& path, const CubeReadOptions& options,
               Diagnostics& diagnostics)
        : m_reader(text, path), m_strict(options.strict), m_diags(diagnostics) {}

    // Throws lut::ParseError (file:line:col) on any error; diagnostics go to the constructor's
    // list as they are found and are copied into the result.
    LutFile parse();
    // Only the header: every keyword line up to the first data line, with the checks parse()
    // makes there (sizes over the limits, bad keywords, the header as a whole), for the first
    // bytes of a big file read before the rest. Returns without a word when the text ends before
    // the first data line (parse() of the whole file then decides).
    void checkHeader();
    // Departures found (strict mode), including those only counted in an "and N more" line.
    int departures() const;

private:
    TextLineReader m_reader;
    bool m_strict;
    Diagnostics& m_diags;
    std::array<int, static_cast<int>(Departure::Count)> m_departures{};

    // Header state.
    std::array<KeySeen, kKeyCount> m_seen{};
    std::string m_title;
    bool m_titleComment = false; // the title came from a '# TITLE "..."' comment
    glm::vec3 m_domainMin{0.0f}, m_domainMax{1.0f};
    int m_size1D = 0, m_size3D = 0;
    float m_range1D[2] = {0.0f, 1.0f}, m_range3D[2] = {0.0f, 1.0f};
    std::vector<std::string> m_comments;
    std::optional<LutPurpose> m_purpose; // the LUTKIT_PURPOSE comment
    int m_firstDataLine = 0;

    const std::string& path() const { return m_reader.path(); }
    [[noreturn]] void fail(const TextLine& line, int column, std::string message,
                           std::string offending = {}) const {
        m_reader.fail(line.number, column, std::move(message), std::move(offending));
    }
    void diag(Diagnostic::Severity s, int line, int column, std::string message) {
        m_diags.push_back({s, path(), line, column, std::move(message)});
    }
    void depart(Departure d, int line, int column, std::string message, bool always = false) {
        if (!m_strict && !always)
            return;
        const int n = m_departures[static_cast<int>(d)]++;
        if (n < kDepartureInfo[static_cast<int>(d)].cap)
            diag(Diagnostic::Severity::Warning, line, column, std::move(message));
    }
    void trailingComment(const TextLine& line, const char* hash) {
        depart(Departure::TrailingComment, line.number, columnOf(line, hash),
               "comment at the end of a line; the Adobe spec allows comments only on lines of "
               "their own");
    }
    bool isKeywordLine(const char* s, const char* e) const {
        if (!isAlpha(*s))
            return false;
        float ignored;
        // "nan" and "inf" start with a letter but are (refused) numbers, not keywords.
        return parseFloat(std::string_view(s, static_cast<std::size_t>(tokenEnd(s, e) - s)),
                          ignored) == NumStatus::NotNumber;
    }
    std::size_t expectedRows() const {
        return static_cast<std::size_t>(m_size1D) + static_cast<std::size_t>(m_size3D) *
                                                        static_cast<std::size_t>(m_size3D) *
                                                        static_cast<std::size_t>(m_size3D);
    }

    // CubeParser.cpp: lines, comments, rows, the result.
    void finishDepartures();
    void checkLine(const TextLine& line);
    void comment(const TextLine& line, const char* hash, const char* e);
    void slowRow(const TextLine& line, const char* s, float* out);
    // Reads the next line that is neither blank nor a comment into line/s/e; false at the end.
    bool nextContentLine(TextLine& line, const char*& s, const char*& e);
    void allocateTables(LutFile& file);
    void setDomains(LutFile& file);

    // CubeHeader.cpp: keywords and the header as a whole.
    void keyword(const TextLine& line, const char* s, const char* e);
    void title(const TextLine& line, const char* kEnd, const char* argsBegin, const char* e);
    void readNumbers(const TextLine& line, const Tokens& t, const char* keyword, int count,
                     float* out, const char* lineEnd);
    int readSize(const TextLine& line, const Tokens& t, const char* keyword, int min, int max,
                 LimitId maxId, const char* lineEnd);
    void finishHeader(const TextLine* firstData, const char* s);
    void checkDomains();
    std::string rowsExpected() const;
    std::string tablesName() const;
};

} // namespace lut::formats::cube
