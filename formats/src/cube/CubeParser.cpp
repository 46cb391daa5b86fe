// The .cube parser: lines, comments, data rows and the result (CubeParser.h says what is
// accepted and refused; the header's keywords are in CubeHeader.cpp).
#include "cube/CubeParser.h"

#include "cube/ParallelRows.h"

#include <algorithm>
#include <climits>

namespace lut::formats::cube {

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
    m_comments.emplace_back(c, static_cast<std::size_t>(trimRight(c, e) - c));
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
    if (m_size1D)
        file.shaper.emplace(m_size1D);
    if (m_size3D)
        file.cube.emplace(m_size3D);
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
}

LutFile CubeParser::parse() {
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

    // The tables, allocated now that every size is known to be within limits.
    const std::string_view rest = m_reader.rest();
    LutFile file;
    file.format = "cube";
    allocateTables(file);
    const RowTarget target =
        file.shaper ? RowTarget{&file.shaper->entries()[0].x, static_cast<std::size_t>(m_size1D),
                                file.cube ? file.cube->data() : nullptr}
                    : RowTarget{file.cube->data(), total, nullptr};

    // Big plain files: all cores. Strict mode reports per-line departures, so it stays sequential.
    constexpr std::size_t kParallelMinRows = 32768;
    bool done = false;
    if (!m_strict && total >= kParallelMinRows && !m_reader.crOnly())
        done = parallelRows(line.text.data(), rest.data() + rest.size(), total, target);

    std::size_t rows = 0;
    while (!done) {
        // `line` is a data line starting at s.
        float* out = target.row(rows);
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
