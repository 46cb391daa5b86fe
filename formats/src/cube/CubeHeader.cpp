// SPDX-License-Identifier: Apache-2.0
// The .cube header: keywords, their arguments and the header as a whole (CubeParser.h says what
// is accepted and refused).
#include "cube/CubeParser.h"

#include "lut/Limits.h"

#include <algorithm>

namespace lut::formats::cube {

void CubeParser::readNumbers(const TextLine& line, const Tokens& t, const char* keyword, int count,
                             float* out, const char* lineEnd) {
    const std::string what = "expected " + std::to_string(count) + " numbers after " + keyword;
    for (int i = 0; i < std::min(t.count, count); ++i) {
        const Token& tok = t.tok[static_cast<std::size_t>(i)];
        switch (parseFloat(tok.text, out[i])) {
        case NumStatus::Ok:
            break;
        case NumStatus::NotNumber:
            fail(line, tok.column, what, std::string(tok.text));
        case NumStatus::NonFinite:
            fail(line, tok.column,
                 std::string(keyword) + " values must be finite numbers (NaN and infinity are "
                                        "not allowed)",
                 std::string(tok.text));
        case NumStatus::TooLarge:
            fail(line, tok.column, "number is out of the 32-bit float range",
                 std::string(tok.text));
        }
    }
    if (t.count < count)
        fail(line, columnOf(line, t.contentEnd) + 1, what + ", found " + std::to_string(t.count),
             content(line.text.data(), lineEnd));
    if (t.count > count)
        fail(line, t.tok[static_cast<std::size_t>(count)].column,
             what + ", found " + std::to_string(t.count), content(line.text.data(), lineEnd));
}

int CubeParser::readSize(const TextLine& line, const Tokens& t, const char* keyword, int min,
                         int max, LimitId maxId, const char* lineEnd) {
    if (t.count == 0)
        fail(line, columnOf(line, t.contentEnd) + 1,
             std::string("expected a size after ") + keyword, content(line.text.data(), lineEnd));
    if (t.count > 1)
        fail(line, t.tok[1].column,
             std::string("unexpected text after ") + keyword + " " + std::string(t.tok[0].text),
             std::string(t.tok[1].text));
    const Token& tok = t.tok[0];
    const char* p = tok.text.data();
    const char* e = p + tok.text.size();
    if (p < e && *p == '+')
        ++p;
    long long v = 0;
    const auto r = std::from_chars(p, e, v);
    const bool digitsOnly = r.ptr == e && p < e && *p != '-';
    if (!digitsOnly || (r.ec != std::errc{} && r.ec != std::errc::result_out_of_range)) {
        if (r.ptr == e && p < e && *p == '-')
            fail(line, tok.column,
                 std::string(keyword) + " " + std::string(tok.text) + " is below the minimum of " +
                     std::to_string(min),
                 std::string(tok.text));
        fail(line, tok.column, std::string("expected an integer size after ") + keyword,
             std::string(tok.text));
    }
    if (r.ec == std::errc::result_out_of_range || v > max)
        throw LineLimitError(path(), line.number, tok.column, maxId,
                             std::string(keyword) + " " + std::string(tok.text) +
                                 " is over the limit of " + std::to_string(max) + " (",
                             ")", std::string(tok.text));
    if (v < min)
        fail(line, tok.column,
             std::string(keyword) + " " + std::string(tok.text) + " is below the minimum of " +
                 std::to_string(min),
             std::string(tok.text));
    return static_cast<int>(v);
}

void CubeParser::keyword(const TextLine& line, const char* s, const char* e) {
    const char* kEnd = tokenEnd(s, e);
    const std::string_view tok(s, static_cast<std::size_t>(kEnd - s));
    const int col = columnOf(line, s);
    const int k = lookupKey(tok);
    if (k < 0) {
        depart(Departure::UnknownKeyword, line.number, col,
               "unknown keyword '" + std::string(tok) + "' ignored", true);
        return;
    }
    const Key key = static_cast<Key>(k);
    const char* name = kKeyNames[k];
    if (m_firstDataLine != 0)
        fail(line, col,
             std::string(name) + " must come before the first data line (line " +
                 std::to_string(m_firstDataLine) + ")",
             std::string(tok));
    if (tok != name)
        depart(Departure::KeywordCase, line.number, col,
               "keyword '" + std::string(tok) + "' is not upper case; the Adobe spec spells it " +
                   name);
    if (key == Key::Range1D || key == Key::Range3D || key == Key::InVideo || key == Key::OutVideo)
        depart(
            Departure::ResolveKeyword, line.number, col,
            std::string(name) + " is a Resolve keyword, not in the Adobe spec" +
                (key == Key::Range1D || key == Key::Range3D ? " (use DOMAIN_MIN/DOMAIN_MAX)" : ""));

    // The argument text (without a trailing comment) decides "repeated" vs "conflicting".
    Tokens t = splitTokens(line, kEnd, e);
    std::string args;
    const char* argsBegin = skipSpace(kEnd, e);
    if (key == Key::Title) {
        // The title may contain '#' and spaces: the closing quote is the last one on the line.
        args = content(argsBegin, e);
    } else {
        args = content(argsBegin, t.comment ? t.comment : e);
        if (t.comment)
            trailingComment(line, t.comment);
    }
    KeySeen& seen = m_seen[static_cast<std::size_t>(k)];
    if (seen.line != 0) {
        if (args != seen.args)
            fail(line, col,
                 std::string(name) + " given twice with different values (first on line " +
                     std::to_string(seen.line) + ")",
                 content(s, e));
        depart(Departure::KeywordRepeated, line.number, col,
               std::string(name) + " repeated (first on line " + std::to_string(seen.line) + ")");
        return;
    }
    seen.line = line.number;
    seen.column = col;
    seen.args = args;
    for (int i = 0; i < std::min(t.count, 3); ++i)
        seen.argColumn[static_cast<std::size_t>(i)] = t.tok[static_cast<std::size_t>(i)].column;

    const char* lineEnd = t.comment ? t.comment : e;
    switch (key) {
    case Key::Title:
        title(line, kEnd, argsBegin, e);
        break;
    case Key::DomainMin:
    case Key::DomainMax: {
        float v[3];
        readNumbers(line, t, name, 3, v, lineEnd);
        (key == Key::DomainMin ? m_domainMin : m_domainMax) = glm::vec3(v[0], v[1], v[2]);
        break;
    }
    case Key::Size1D:
        m_size1D = readSize(line, t, name, limits::kMin1DSize, limits::kMax1DSize,
                            LimitId::Max1DSize, lineEnd);
        break;
    case Key::Size3D:
        m_size3D = readSize(line, t, name, limits::kMin3DSize, limits::kMax3DSize,
                            LimitId::Max3DSize, lineEnd);
        break;
    case Key::Range1D:
    case Key::Range3D: {
        float* r = key == Key::Range1D ? m_range1D : m_range3D;
        readNumbers(line, t, name, 2, r, lineEnd);
        if (!(r[0] < r[1]))
            fail(line, t.tok[1].column, std::string(name) + " min must be below max",
                 content(argsBegin, lineEnd));
        break;
    }
    case Key::InVideo:
    case Key::OutVideo:
        if (t.count > 0)
            fail(line, t.tok[0].column, std::string("unexpected text after ") + name,
                 std::string(t.tok[0].text));
        diag(Diagnostic::Severity::Info, line.number, col,
             std::string(name) + " is not applied: the table is kept as stored, and the flag is "
                                 "not written back");
        break;
    }
}

void CubeParser::title(const TextLine& line, const char* kEnd, const char* argsBegin,
                       const char* e) {
    const char* a = argsBegin;
    const char* end = trimRight(a, e);
    if (a == end)
        fail(line, columnOf(line, kEnd) + 1, "expected a quoted title after TITLE");
    if (*a == '"') {
        const char* close = end - 1;
        while (close > a && *close != '"')
            --close;
        if (close == a) {
            fail(line, columnOf(line, end), "TITLE has no closing quote",
                 std::string(a, static_cast<std::size_t>(end - a)));
        }
        // Anything after the closing quote must be a comment or nothing.
        const char* after = skipSpace(close + 1, end);
        if (after != end) {
            if (*after != '#')
                fail(line, columnOf(line, after), "unexpected text after the TITLE's closing quote",
                     std::string(after, static_cast<std::size_t>(end - after)));
            trailingComment(line, after);
        }
        m_title.assign(a + 1, static_cast<std::size_t>(close - a - 1));
    } else {
        depart(Departure::UnquotedTitle, line.number, columnOf(line, a),
               "TITLE text is not in double quotes");
        m_title.assign(a, static_cast<std::size_t>(end - a));
    }
}

std::string CubeParser::rowsExpected() const {
    const std::size_t n3 = static_cast<std::size_t>(m_size3D) * m_size3D * m_size3D;
    if (m_size1D && m_size3D)
        return std::to_string(m_size1D) + " + " + std::to_string(n3) + " = " +
               std::to_string(expectedRows()) + " data rows for LUT_1D_SIZE " +
               std::to_string(m_size1D) + " and LUT_3D_SIZE " + std::to_string(m_size3D);
    if (m_size3D)
        return std::to_string(n3) + " data rows for LUT_3D_SIZE " + std::to_string(m_size3D);
    return std::to_string(m_size1D) + " data rows for LUT_1D_SIZE " + std::to_string(m_size1D);
}

// "the LUT_3D_SIZE 33 table" (or both tables), for out-of-memory messages.
std::string CubeParser::tablesName() const {
    if (m_size1D && m_size3D)
        return "the LUT_1D_SIZE " + std::to_string(m_size1D) + " and LUT_3D_SIZE " +
               std::to_string(m_size3D) + " tables";
    if (m_size3D)
        return "the LUT_3D_SIZE " + std::to_string(m_size3D) + " table";
    return "the LUT_1D_SIZE " + std::to_string(m_size1D) + " table";
}

// Checks the header as a whole; firstData is the first data line (nullptr at the end of file).
void CubeParser::finishHeader(const TextLine* firstData, const char* s) {
    if (m_size1D == 0 && m_size3D == 0) {
        if (firstData)
            fail(*firstData, columnOf(*firstData, s),
                 "expected LUT_3D_SIZE or LUT_1D_SIZE before the first data line",
                 content(s, firstData->text.data() + firstData->text.size()));
        const auto [l, c] = m_reader.endPosition();
        m_reader.fail(l, c,
                      l == 1 && c == 1 && !m_reader.hasBom()
                          ? "the file is empty: expected a .cube header with LUT_3D_SIZE or "
                            "LUT_1D_SIZE"
                          : "expected LUT_3D_SIZE or LUT_1D_SIZE, found the end of the file");
    }
    const auto& size1 = m_seen[static_cast<int>(Key::Size1D)];
    const auto& size3 = m_seen[static_cast<int>(Key::Size3D)];
    if (m_size1D && m_size3D) {
        const auto& later = size1.line > size3.line ? size1 : size3;
        depart(Departure::ShaperAndCube, later.line, later.column,
               "both LUT_1D_SIZE and LUT_3D_SIZE: a shaper followed by a cube is a Resolve "
               "extension");
    }
    // Which table DOMAIN_* belongs to, and whether an INPUT_RANGE competes with it.
    const auto& dmin = m_seen[static_cast<int>(Key::DomainMin)];
    const auto& dmax = m_seen[static_cast<int>(Key::DomainMax)];
    const bool hasDomain = dmin.line || dmax.line;
    const bool domainIs1D = m_size1D != 0;
    for (Key rk : {Key::Range1D, Key::Range3D}) {
        const auto& r = m_seen[static_cast<int>(rk)];
        if (!r.line)
            continue;
        const bool is1D = rk == Key::Range1D;
        if ((is1D && !m_size1D) || (!is1D && !m_size3D)) {
            depart(Departure::IgnoredKeyword, r.line, r.column,
                   std::string(kKeyNames[static_cast<int>(rk)]) + " ignored: the file has no " +
                       (is1D ? "LUT_1D_SIZE" : "LUT_3D_SIZE"),
                   true);
            continue;
        }
        if (hasDomain && is1D == domainIs1D) {
            const auto& d = dmin.line > dmax.line ? dmin : dmax;
            const auto& later = d.line > r.line ? d : r;
            m_reader.fail(
                later.line, later.column,
                std::string("DOMAIN_MIN/DOMAIN_MAX and ") + kKeyNames[static_cast<int>(rk)] +
                    " both set the input domain of the " + (is1D ? "1D" : "3D") + " table");
        }
    }
    if (hasDomain)
        checkDomains();
}

// DOMAIN_MIN below DOMAIN_MAX on every channel (pointing at the value on the later line).
void CubeParser::checkDomains() {
    const auto& dmin = m_seen[static_cast<int>(Key::DomainMin)];
    const auto& dmax = m_seen[static_cast<int>(Key::DomainMax)];
    static const char* const channel[] = {"red", "green", "blue"};
    for (int c = 0; c < 3; ++c) {
        if (m_domainMin[c] < m_domainMax[c])
            continue;
        // Point at the value on whichever of the two lines came last.
        const auto& d = dmax.line >= dmin.line ? dmax : dmin;
        const bool isMax = &d == &dmax;
        m_reader.fail(
            d.line, d.argColumn[static_cast<std::size_t>(c)],
            "DOMAIN_MIN must be below DOMAIN_MAX for every channel: " + std::string(channel[c]) +
                " has min " + floatText(m_domainMin[c]) + " and max " + floatText(m_domainMax[c]),
            floatText(isMax ? m_domainMax[c] : m_domainMin[c]));
    }
}

} // namespace lut::formats::cube
