// SPDX-License-Identifier: Apache-2.0
// The .cube parser: lines, comments, data rows and the result (CubeParser.h says what is
// accepted and refused; the header's keywords are in CubeHeader.cpp).
#include "cube/CubeParser.h"

#include "cube/ParallelRows.h"

#include "lut/io/InputFile.h"

#include <algorithm>
#include <climits>
#include <cstdint>

namespace lut::formats::cube {

namespace {

// A .cube saved as UTF-16 or UTF-32 (Windows Notepad's "Unicode") would be refused for a NUL
// byte or a strange keyword; say what it is instead. A byte order mark decides; without one,
// ASCII text in UTF-16 has a NUL in every other byte of its first line.
void checkEncoding(std::string_view text, const std::string& path) {
    auto u = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const char* what = nullptr;
    if (text.size() >= 4 && ((u(0) == 0xFF && u(1) == 0xFE && u(2) == 0 && u(3) == 0) ||
                             (u(0) == 0 && u(1) == 0 && u(2) == 0xFE && u(3) == 0xFF)))
        what = "UTF-32";
    else if (text.size() >= 2 && ((u(0) == 0xFF && u(1) == 0xFE) || (u(0) == 0xFE && u(1) == 0xFF)))
        what = "UTF-16";
    else if (text.size() >= 4) {
        const std::size_t window = std::min<std::size_t>(text.size(), 64) & ~std::size_t(1);
        std::size_t nulEven = 0, nulOdd = 0;
        for (std::size_t i = 0; i < window; ++i)
            (i % 2 ? nulOdd : nulEven) += u(i) == 0;
        if ((nulOdd == window / 2 && nulEven == 0) || (nulEven == window / 2 && nulOdd == 0))
            what = "UTF-16";
    }
    if (what)
        throw ParseError(path, 0, 0,
                         std::string("the file is ") + what + " text; save it as UTF-8 or ASCII");
}

// Each data row takes at least 6 bytes: three one-character numbers, two separators and a line
// end (5 for the last row, which may have none).
constexpr std::size_t kMinRowBytes = 6;

} // namespace

int CubeParser::departures() const {
    int n = 0;
    for (int d : m_departures)
        n += d;
    return n;
}

void CubeParser::finishDepartures() {
    // Report in file order; the "and N more" summaries (line 0) go last.
    std::stable_sort(m_diags.begin(), m_diags.end(), [](const Diagnostic& a, const Diagnostic& b) {
        return (a.line == 0 ? INT_MAX : a.line) < (b.line == 0 ? INT_MAX : b.line);
    });
    for (int d = 0; d < static_cast<int>(Departure::Count); ++d) {
        const int extra = m_departures[static_cast<std::size_t>(d)] - kDepartureInfo[d].cap;
        if (extra > 0)
            diag(Diagnostic::Severity::Warning, 0, 0,
                 "and " + std::to_string(extra) + " more: " + kDepartureInfo[d].rest);
    }
}

void CubeParser::checkLine(const TextLine& line) {
    if (line.end == LineEnd::CRLF)
        depart(Departure::CrLf, line.number, static_cast<int>(line.text.size()) + 1,
               "line ends with CR LF; the Adobe spec uses LF");
    else if (line.end == LineEnd::CR)
        depart(Departure::CrOnly, line.number, static_cast<int>(line.text.size()) + 1,
               "line ends with a lone CR; the Adobe spec uses LF");
    if (line.text.size() > kAdobeMaxLineBytes)
        depart(Departure::LongLine, line.number, static_cast<int>(kAdobeMaxLineBytes) + 1,
               "line is " + std::to_string(line.text.size()) +
                   " bytes long; the Adobe spec allows at most 250");
}

void CubeParser::comment(const TextLine& line, const char* hash, const char* e) {
    if (hash != line.text.data())
        depart(Departure::CommentIndent, line.number, columnOf(line, hash),
               "comment does not start at column 1; the Adobe spec wants '#' first");
    const char* c = hash + 1;
    if (c < e && *c == ' ')
        ++c;
    const std::string_view text(c, static_cast<std::size_t>(trimRight(c, e) - c));
    // "# LUTKIT_PURPOSE smash": what the LUT is for (lut/LutPurpose.h), not kept as a comment.
    std::optional<LutPurpose> purpose;
    try {
        purpose = purposeInText(text);
    } catch (const Error& err) {
        fail(line, columnOf(line, c), err.what(), std::string(text));
    }
    if (!purpose) {
        // '# TITLE "text"': the title as the Resolve dialect (which has no TITLE keyword) holds
        // it, written so by lutkit (CubeWriter.cpp); read back as the title.
        constexpr std::string_view kTitle = "TITLE \"";
        if (m_title.empty() && !m_titleComment && text.size() > kTitle.size() &&
            text.substr(0, kTitle.size()) == kTitle && text.back() == '"') {
            m_title.assign(text.substr(kTitle.size(), text.size() - kTitle.size() - 1));
            m_titleComment = true;
            return;
        }
        m_comments.emplace_back(text);
        return;
    }
    if (m_purpose && *m_purpose != *purpose)
        fail(line, columnOf(line, c),
             std::string("a second LUTKIT_PURPOSE says ") + toString(*purpose) + ", the first " +
                 toString(*m_purpose),
             std::string(text));
    m_purpose = purpose;
}

bool CubeParser::nextContentLine(TextLine& line, const char*& s, const char*& e) {
    while (m_reader.next(line)) {
        if (m_strict)
            checkLine(line);
        e = line.text.data() + line.text.size();
        s = skipSpace(line.text.data(), e);
        if (s == e)
            continue;
        if (*s == '#') {
            comment(line, s, e);
            continue;
        }
        return true;
    }
    return false;
}

void CubeParser::slowRow(const TextLine& line, const char* s, float* out) {
    const char* e = line.text.data() + line.text.size();
    const Tokens t = splitTokens(line, s, e);
    const char* lineEnd = t.comment ? t.comment : e;
    for (int i = 0; i < std::min(t.count, 3); ++i) {
        const Token& tok = t.tok[static_cast<std::size_t>(i)];
        switch (parseFloat(tok.text, out[i])) {
        case NumStatus::Ok:
            break;
        case NumStatus::NotNumber:
            if (i == 0 && isAlpha(tok.text[0]) && lookupKey(tok.text) >= 0)
                fail(line, tok.column,
                     std::string(kKeyNames[lookupKey(tok.text)]) +
                         " must come before the first data line (line " +
                         std::to_string(m_firstDataLine) + ")",
                     std::string(tok.text));
            fail(line, tok.column, "expected a number", std::string(tok.text));
        case NumStatus::NonFinite:
            fail(line, tok.column,
                 "NaN and infinity are not allowed in .cube data; expected a finite number",
                 std::string(tok.text));
        case NumStatus::TooLarge:
            fail(line, tok.column, "number is out of the 32-bit float range",
                 std::string(tok.text));
        }
    }
    if (t.count < 3)
        fail(line, columnOf(line, t.contentEnd) + 1,
             "expected 3 numbers on a data line, found " + std::to_string(t.count),
             content(s, lineEnd));
    if (t.count > 3)
        fail(line, t.tok[3].column,
             "expected 3 numbers on a data line, found " + std::to_string(t.count),
             content(s, lineEnd));
    if (t.comment)
        trailingComment(line, t.comment);
}

void CubeParser::allocateTables(LutFile& file) {
    const std::uint64_t bytes = static_cast<std::uint64_t>(expectedRows()) * sizeof(glm::vec3);
    allocating(path(), tablesName(), bytes, [&] {
        if (m_size1D)
            file.shaper.emplace(m_size1D);
        if (m_size3D)
            file.cube.emplace(m_size3D);
    });
    if (file.shaper)
        file.shaper->setTitle(m_title);
    if (file.cube)
        file.cube->setTitle(m_title);
}

// Domains (checked in finishHeader), comments and the dialect.
void CubeParser::setDomains(LutFile& file) {
    const auto& dmin = m_seen[static_cast<int>(Key::DomainMin)];
    const auto& dmax = m_seen[static_cast<int>(Key::DomainMax)];
    const bool hasDomain = dmin.line || dmax.line;
    if (file.shaper) {
        if (m_seen[static_cast<int>(Key::Range1D)].line)
            file.shaper->setDomain(glm::vec3(m_range1D[0]), glm::vec3(m_range1D[1]));
        else if (hasDomain)
            file.shaper->setDomain(m_domainMin, m_domainMax);
    }
    if (file.cube) {
        if (m_seen[static_cast<int>(Key::Range3D)].line)
            file.cube->setDomain(glm::vec3(m_range3D[0]), glm::vec3(m_range3D[1]));
        else if (hasDomain && !file.shaper)
            file.cube->setDomain(m_domainMin, m_domainMax);
        file.cube->comments() = std::move(m_comments);
    } else if (!m_comments.empty()) {
        diag(Diagnostic::Severity::Info, 0, 0,
             std::to_string(m_comments.size()) +
                 " comment line(s) not kept: a 1D-only LUT has no place for comments");
    }
    bool resolve = m_size1D && m_size3D;
    for (Key k : {Key::Range1D, Key::Range3D, Key::InVideo, Key::OutVideo})
        if (m_seen[static_cast<int>(k)].line)
            resolve = true;
    file.dialect = resolve ? "resolve" : "adobe";
    file.purpose = m_purpose;
}

void CubeParser::checkHeader() {
    checkEncoding(m_reader.rest(), path());
    TextLine line;
    while (m_reader.next(line)) {
        const char* e = line.text.data() + line.text.size();
        const char* s = skipSpace(line.text.data(), e);
        if (s == e || *s == '#')
            continue;
        if (!isKeywordLine(s, e)) {
            finishHeader(&line, s);
            return;
        }
        keyword(line, s, e);
    }
}

LutFile CubeParser::parse() {
    checkEncoding(m_reader.rest(), path());
    if (m_reader.hasBom())
        depart(Departure::Bom, 1, 1, "file starts with a UTF-8 byte order mark");
    TextLine line;
    const char* s = nullptr;
    const char* e = nullptr;
    bool haveData = false;
    while (m_reader.next(line)) {
        if (m_strict)
            checkLine(line);
        e = line.text.data() + line.text.size();
        s = skipSpace(line.text.data(), e);
        if (s == e)
            continue;
        if (*s == '#') {
            comment(line, s, e);
            continue;
        }
        if (isKeywordLine(s, e)) {
            keyword(line, s, e);
            continue;
        }
        haveData = true;
        break;
    }
    finishHeader(haveData ? &line : nullptr, s);
    const std::size_t total = expectedRows();
    if (!haveData) {
        const auto [l, c] = m_reader.endPosition();
        m_reader.fail(l, c, "expected " + rowsExpected() + ", found 0 before the end of the file");
    }
    m_firstDataLine = line.number;

    // The tables are allocated only when the rest of the file can hold their rows. When it
    // cannot, the rows are parsed into a scratch row instead: that ends, as it must, in the error
    // the file deserves (a bad row, or too few rows), without allocating what the header claims.
    const std::string_view rest = m_reader.rest();
    const auto available = static_cast<std::size_t>(rest.data() + rest.size() - line.text.data());
    const bool store = available + 1 >= kMinRowBytes * total;
    LutFile file;
    file.format = "cube";
    float scratch[3];
    RowTarget target{scratch, 0, scratch};
    if (store) {
        allocateTables(file);
        if (file.shaper)
            target = {&file.shaper->entries()[0].x, static_cast<std::size_t>(m_size1D),
                      file.cube ? file.cube->data() : nullptr};
        else
            target = {file.cube->data(), total, nullptr};
    }

    // Big plain files: all cores. Strict mode reports per-line departures, so it stays sequential.
    constexpr std::size_t kParallelMinRows = 32768;
    bool done = false;
    if (store && !m_strict && total >= kParallelMinRows && !m_reader.crOnly())
        done = parallelRows(line.text.data(), rest.data() + rest.size(), total, target);

    std::size_t rows = 0;
    while (!done) {
        // `line` is a data line starting at s.
        float* out = store ? target.row(rows) : scratch;
        if (!fastRow(s, e, out))
            slowRow(line, s, out);
        if (++rows == total)
            break;
        if (!nextContentLine(line, s, e)) {
            const auto [l, c] = m_reader.endPosition();
            m_reader.fail(l, c,
                          "expected " + rowsExpected() + ", found " + std::to_string(rows) +
                              " before the end of the file");
        }
    }
    if (!store) // cannot happen: the rows did not fit in the bytes
        throw Error(path() + ": internal error: more rows than the file can hold");
    const int lastRowLine = line.number;
    // After the last row: only blank lines and comments. Stop at the first extra row, so a file
    // with a billion rows is refused without reading them.
    while (!done && nextContentLine(line, s, e)) {
        const char* tEnd = tokenEnd(s, e);
        const int k = isAlpha(*s) ? lookupKey(std::string_view(s, std::size_t(tEnd - s))) : -1;
        if (k >= 0)
            fail(line, columnOf(line, s),
                 std::string(kKeyNames[k]) + " must come before the first data line (line " +
                     std::to_string(m_firstDataLine) + ")",
                 std::string(s, tEnd));
        if (isKeywordLine(s, e))
            fail(line, columnOf(line, s),
                 "expected only blank lines and comments after the last data row (line " +
                     std::to_string(lastRowLine) + ")",
                 content(s, e));
        fail(line, columnOf(line, s),
             "too many data rows: expected " + rowsExpected() + ", this is row " +
                 std::to_string(total + 1),
             content(s, e));
    }

    setDomains(file);
    finishDepartures();
    file.diagnostics = m_diags;
    return file;
}

} // namespace lut::formats::cube
