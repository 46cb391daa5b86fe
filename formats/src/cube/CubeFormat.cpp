// .cube: Adobe Cube LUT Specification 1.0 and the DaVinci Resolve dialect.
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
//    "departure"), at most 3 per kind plus a count of the rest.
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
//    is refused at row N^3 + 1.
//  - Speed: whole file memory-mapped, no per-line allocation, floats by an exact Clinger fast path
//    (falls back to std::from_chars), and plain big files parsed on all cores (parallelRows);
//    anything unusual is re-read by the one sequential parser, which owns every message.
//
// Writing: comments first (as "# text"), TITLE when set, the size line(s), DOMAIN_MIN/MAX (Adobe)
// or LUT_*_INPUT_RANGE (Resolve) only when the domain is not the default 0..1 (the default is
// implied by the spec, and some readers mishandle DOMAIN lines), then the rows, LF line ends.
// Floats are written as the shortest text that reads back as the same float (std::to_chars), so
// write -> read is bit-exact. A shaper + cube file is written in the Resolve dialect when every
// domain is equal on all channels; otherwise the shaper is baked into the cube (Warning).
// Non-finite entries are written as 0 (NaN) or +-FLT_MAX (Inf) with a Warning.
#include "lut/formats/Cube.h"

#include "Formats.h"
#include "cube/TextLineReader.h"

#include "lut/Limits.h"
#include "lut/Parallel.h"
#include "lut/io/AtomicFile.h"
#include "lut/ops/Resample.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>

namespace lut::formats {

namespace {

constexpr std::size_t kAdobeMaxLineBytes = 250;

inline bool isSpace(char c) {
    return c == ' ' || c == '\t';
}
inline const char* skipSpace(const char* p, const char* e) {
    while (p < e && isSpace(*p))
        ++p;
    return p;
}
inline const char* tokenEnd(const char* p, const char* e) {
    while (p < e && !isSpace(*p))
        ++p;
    return p;
}
inline const char* trimRight(const char* b, const char* e) {
    while (e > b && isSpace(e[-1]))
        --e;
    return e;
}
inline bool isAlpha(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

std::string floatText(float v) {
    char buf[32];
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

enum class NumStatus { Ok, NotNumber, NonFinite, TooLarge };

// Parses the whole token as a float. Locale independent; accepts a leading '+'.
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
    const auto r = std::from_chars(p, e, v);
    if (r.ptr != e || r.ec == std::errc::invalid_argument)
        return NumStatus::NotNumber;
    if (r.ec == std::errc::result_out_of_range) {
        // Too large or too small for a float: tell which from the double value (or exponent).
        double d = 0.0;
        const auto r2 = std::from_chars(p, e, d);
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

constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// Decimal text to float with the same result as std::from_chars, for the common case (at most
// 19 digits, exponent within +-22): m and 10^k are exact doubles, so m * 10^k or m / 10^k is
// rounded once to double; rounding that double to float gives the correctly rounded float unless
// the double lies exactly halfway between two floats, which goes to the general algorithm.
// Returns the end of the number, or nullptr when the general algorithm must decide.
inline const char* fastFloat(const char* p, const char* e, float& out) {
    bool negative = false;
    if (p < e && *p == '-') {
        negative = true;
        ++p;
    }
    std::uint64_t m = 0;
    const char* q = p;
    while (q < e && static_cast<unsigned>(*q - '0') < 10)
        m = m * 10 + static_cast<unsigned>(*q++ - '0');
    std::ptrdiff_t digits = q - p;
    int exp10 = 0;
    if (q < e && *q == '.') {
        const char* f = ++q;
        while (q < e && static_cast<unsigned>(*q - '0') < 10)
            m = m * 10 + static_cast<unsigned>(*q++ - '0');
        exp10 = -static_cast<int>(q - f);
        digits += q - f;
    }
    if (digits == 0 || digits > 19)
        return nullptr;
    if (q < e && (*q == 'e' || *q == 'E')) {
        const char* x = q + 1;
        bool expNegative = false;
        if (x < e && (*x == '-' || *x == '+'))
            expNegative = *x++ == '-';
        if (x == e || static_cast<unsigned>(*x - '0') >= 10)
            return nullptr;
        int v = 0;
        while (x < e && static_cast<unsigned>(*x - '0') < 10 && v < 1000)
            v = v * 10 + (*x++ - '0');
        if (x < e && static_cast<unsigned>(*x - '0') < 10)
            return nullptr;
        exp10 += expNegative ? -v : v;
        q = x;
    }
    if (m == 0) {
        out = negative ? -0.0f : 0.0f;
        return q;
    }
    if (m > (std::uint64_t(1) << 53) || exp10 < -22 || exp10 > 22)
        return nullptr;
    double d = static_cast<double>(m);
    d = exp10 < 0 ? d / kPow10[-exp10] : d * kPow10[exp10];
    std::uint64_t bits;
    std::memcpy(&bits, &d, sizeof bits);
    if ((bits & 0x1FFFFFFFu) == 0x10000000u)
        return nullptr; // exactly halfway between floats
    const float f = static_cast<float>(d);
    out = negative ? -f : f;
    return q;
}

// The hot path: a plain data line of three numbers (no comment, no '+', nothing odd). Anything
// else returns false and goes through the careful path, which reports or accepts it.
inline bool fastRow(const char* p, const char* e, float* out) {
    for (int i = 0; i < 3; ++i) {
        p = skipSpace(p, e);
        const char* q = fastFloat(p, e, out[i]);
        if (!q) {
            const auto r = std::from_chars(p, e, out[i]);
            if (r.ec != std::errc{} || r.ptr == p)
                return false;
            if (!std::isfinite(out[i]))
                return false;
            q = r.ptr;
        }
        p = q;
        if (p < e && !isSpace(*p))
            return false;
    }
    return skipSpace(p, e) == e;
}

// Where data row i goes: the shaper's rows first, then the cube's.
struct RowTarget {
    float* first;
    std::size_t firstRows;
    float* second;
    float* row(std::size_t i) const {
        return i < firstRows ? first + 3 * i : second + 3 * (i - firstRows);
    }
};

// The data rows of a plain file (nothing but data rows and blank lines from the first data line
// to the end, exactly `rows` of them, every one fastRow-clean) parsed on all cores: one pass
// counts rows per chunk, a second parses each chunk into its place. Anything else (comments,
// keywords, wrong row count, odd numbers, long lines) returns false, and the sequential parser,
// which owns every message and line number, reads the file from the first data line again.
bool parallelRows(const char* begin, const char* end, std::size_t rows, const RowTarget& target) {
    const int chunks = resolveThreads(0);
    if (chunks < 2)
        return false;
    std::vector<const char*> cut(static_cast<std::size_t>(chunks) + 1);
    cut[0] = begin;
    cut[static_cast<std::size_t>(chunks)] = end;
    for (int i = 1; i < chunks; ++i) {
        const char* p = begin + (end - begin) * i / chunks;
        if (p < cut[static_cast<std::size_t>(i) - 1])
            p = cut[static_cast<std::size_t>(i) - 1];
        const auto* nl =
            static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
        cut[static_cast<std::size_t>(i)] = nl ? nl + 1 : end;
    }
    // Calls fn(start, lineEnd) for each non-blank line of chunk c (CR of CR LF removed); stops
    // and returns false when fn does or the line is not a plain data line.
    auto eachRow = [&](int c, auto&& fn) {
        const char* p = cut[static_cast<std::size_t>(c)];
        const char* e = cut[static_cast<std::size_t>(c) + 1];
        while (p < e) {
            const auto* nl =
                static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(e - p)));
            const char* le = nl ? nl : e;
            const char* next = nl ? nl + 1 : e;
            if (static_cast<std::size_t>(le - p) > limits::kMaxTextLineBytes)
                return false;
            if (le > p && le[-1] == '\r')
                --le;
            const char* s = skipSpace(p, le);
            if (s != le) {
                if (*s == '#' || isAlpha(*s))
                    return false;
                if (!fn(s, le))
                    return false;
            }
            p = next;
        }
        return true;
    };
    std::vector<std::size_t> count(static_cast<std::size_t>(chunks), 0);
    std::vector<char> ok(static_cast<std::size_t>(chunks), 1);
    parallelFor(chunks, chunks, [&](int c0, int c1) {
        for (int c = c0; c < c1; ++c) {
            std::size_t n = 0;
            // A chunk with more rows than the whole table stops at once (a file with a billion
            // rows is not scanned to its end).
            ok[static_cast<std::size_t>(c)] =
                eachRow(c, [&](const char*, const char*) { return ++n <= rows; });
            count[static_cast<std::size_t>(c)] = n;
        }
    });
    std::vector<std::size_t> first(static_cast<std::size_t>(chunks), 0);
    std::size_t total = 0;
    for (int c = 0; c < chunks; ++c) {
        if (!ok[static_cast<std::size_t>(c)])
            return false;
        first[static_cast<std::size_t>(c)] = total;
        total += count[static_cast<std::size_t>(c)];
    }
    if (total != rows)
        return false;
    parallelFor(chunks, chunks, [&](int c0, int c1) {
        for (int c = c0; c < c1; ++c) {
            std::size_t r = first[static_cast<std::size_t>(c)];
            ok[static_cast<std::size_t>(c)] = eachRow(
                c, [&](const char* s, const char* le) { return fastRow(s, le, target.row(r++)); });
        }
    });
    for (char c : ok)
        if (!c)
            return false;
    return true;
}

enum class Key { Title, DomainMin, DomainMax, Size1D, Size3D, Range1D, Range3D, InVideo, OutVideo };
constexpr int kKeyCount = 9;
constexpr const char* kKeyNames[kKeyCount] = {"TITLE",
                                              "DOMAIN_MIN",
                                              "DOMAIN_MAX",
                                              "LUT_1D_SIZE",
                                              "LUT_3D_SIZE",
                                              "LUT_1D_INPUT_RANGE",
                                              "LUT_3D_INPUT_RANGE",
                                              "LUT_IN_VIDEO_RANGE",
                                              "LUT_OUT_VIDEO_RANGE"};

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        char x = a[i];
        if (x >= 'a' && x <= 'z')
            x = static_cast<char>(x - 'a' + 'A');
        if (x != b[i])
            return false;
    }
    return true;
}

int lookupKey(std::string_view tok) {
    for (int k = 0; k < kKeyCount; ++k)
        if (equalsIgnoreCase(tok, kKeyNames[k]))
            return k;
    return -1;
}

enum class Departure {
    Bom,
    CrLf,
    CrOnly,
    LongLine,
    KeywordCase,
    KeywordRepeated,
    CommentIndent,
    TrailingComment,
    ResolveKeyword,
    ShaperAndCube,
    UnquotedTitle,
    UnknownKeyword,
    IgnoredKeyword,
    Count
};

struct DepartureInfo {
    int cap;          // reports of this kind before only counting
    const char* rest; // "and N more: <rest>"
};
constexpr DepartureInfo kDepartureInfo[] = {
    {1, "byte order marks"},
    {1, "lines end with CR LF"},
    {1, "lines end with CR"},
    {3, "lines are longer than 250 bytes"},
    {3, "keywords are not upper case"},
    {3, "keywords are repeated"},
    {3, "comments do not start at column 1"},
    {3, "lines end with a comment"},
    {3, "Resolve keywords"},
    {1, "shaper and cube"},
    {3, "unquoted titles"},
    {3, "unknown keywords"},
    {3, "ignored keywords"},
};
static_assert(std::size(kDepartureInfo) == static_cast<std::size_t>(Departure::Count));

struct Token {
    std::string_view text;
    int column = 0;
};

// Up to 4 whitespace-separated tokens of [p, e), stopping at a token that starts with '#'.
struct Tokens {
    std::array<Token, 4> tok;
    int count = 0;          // tokens before any comment (may exceed 4; only 4 are kept)
    const char* contentEnd; // end of the last token before the comment
    const char* comment = nullptr;
};

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

struct KeySeen {
    int line = 0;
    int column = 0;
    std::string args;               // argument text, for "repeated with another value"
    std::array<int, 3> argColumn{}; // columns of the numbers
};

class CubeParser {
public:
    CubeParser(std::string_view text, const std::string& path, const CubeReadOptions& options,
               Diagnostics& diagnostics)
        : m_reader(text, path), m_strict(options.strict), m_diags(diagnostics) {}

    LutFile parse();
    int departures() const {
        int n = 0;
        for (int d : m_departures)
            n += d;
        return n;
    }

private:
    TextLineReader m_reader;
    bool m_strict;
    Diagnostics& m_diags;
    std::array<int, static_cast<int>(Departure::Count)> m_departures{};

    // Header state.
    std::array<KeySeen, kKeyCount> m_seen{};
    std::string m_title;
    glm::vec3 m_domainMin{0.0f}, m_domainMax{1.0f};
    int m_size1D = 0, m_size3D = 0;
    float m_range1D[2] = {0.0f, 1.0f}, m_range3D[2] = {0.0f, 1.0f};
    std::vector<std::string> m_comments;
    int m_firstDataLine = 0;

    const std::string& path() const { return m_reader.path(); }
    [[noreturn]] void fail(const TextLine& line, int column, std::string message,
                           std::string offending = {}) const {
        m_reader.fail(line.number, column, std::move(message), std::move(offending));
    }
    static std::string content(const char* b, const char* e) {
        return std::string(b, static_cast<std::size_t>(trimRight(b, e) - b));
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
    void finishDepartures() {
        // Report in file order; the "and N more" summaries (line 0) go last.
        std::stable_sort(
            m_diags.begin(), m_diags.end(), [](const Diagnostic& a, const Diagnostic& b) {
                return (a.line == 0 ? INT_MAX : a.line) < (b.line == 0 ? INT_MAX : b.line);
            });
        for (int d = 0; d < static_cast<int>(Departure::Count); ++d) {
            const int extra = m_departures[static_cast<std::size_t>(d)] - kDepartureInfo[d].cap;
            if (extra > 0)
                diag(Diagnostic::Severity::Warning, 0, 0,
                     "and " + std::to_string(extra) + " more: " + kDepartureInfo[d].rest);
        }
    }

    void checkLine(const TextLine& line) {
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

    void comment(const TextLine& line, const char* hash, const char* e) {
        if (hash != line.text.data())
            depart(Departure::CommentIndent, line.number, columnOf(line, hash),
                   "comment does not start at column 1; the Adobe spec wants '#' first");
        const char* c = hash + 1;
        if (c < e && *c == ' ')
            ++c;
        m_comments.emplace_back(c, static_cast<std::size_t>(trimRight(c, e) - c));
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

    void keyword(const TextLine& line, const char* s, const char* e);
    void readNumbers(const TextLine& line, const Tokens& t, const char* keyword, int count,
                     float* out, const char* lineEnd);
    int readSize(const TextLine& line, const Tokens& t, const char* keyword, int min, int max,
                 const char* maxName, const char* lineEnd);
    void beginData(const TextLine& line, const char* s);
    void finishHeader(const TextLine* firstData, const char* s);
    void slowRow(const TextLine& line, const char* s, float* out);
    std::string rowsExpected() const;
    std::size_t expectedRows() const {
        return static_cast<std::size_t>(m_size1D) + static_cast<std::size_t>(m_size3D) *
                                                        static_cast<std::size_t>(m_size3D) *
                                                        static_cast<std::size_t>(m_size3D);
    }
};

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
                         int max, const char* maxName, const char* lineEnd) {
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
        fail(line, tok.column,
             std::string(keyword) + " " + std::string(tok.text) + " is over the limit of " +
                 std::to_string(max) + " (lut::limits::" + maxName + ")",
             std::string(tok.text));
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
    case Key::Title: {
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
                    fail(line, columnOf(line, after),
                         "unexpected text after the TITLE's closing quote",
                         std::string(after, static_cast<std::size_t>(end - after)));
                trailingComment(line, after);
            }
            m_title.assign(a + 1, static_cast<std::size_t>(close - a - 1));
        } else {
            depart(Departure::UnquotedTitle, line.number, columnOf(line, a),
                   "TITLE text is not in double quotes");
            m_title.assign(a, static_cast<std::size_t>(end - a));
        }
        break;
    }
    case Key::DomainMin:
    case Key::DomainMax: {
        float v[3];
        readNumbers(line, t, name, 3, v, lineEnd);
        (key == Key::DomainMin ? m_domainMin : m_domainMax) = glm::vec3(v[0], v[1], v[2]);
        break;
    }
    case Key::Size1D:
        m_size1D =
            readSize(line, t, name, limits::kMin1DSize, limits::kMax1DSize, "kMax1DSize", lineEnd);
        break;
    case Key::Size3D:
        m_size3D =
            readSize(line, t, name, limits::kMin3DSize, limits::kMax3DSize, "kMax3DSize", lineEnd);
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
    if (hasDomain) {
        static const char* const channel[] = {"red", "green", "blue"};
        for (int c = 0; c < 3; ++c) {
            if (m_domainMin[c] < m_domainMax[c])
                continue;
            // Point at the value on whichever of the two lines came last.
            const auto& d = dmax.line >= dmin.line ? dmax : dmin;
            const bool isMax = &d == &dmax;
            m_reader.fail(d.line, d.argColumn[static_cast<std::size_t>(c)],
                          "DOMAIN_MIN must be below DOMAIN_MAX for every channel: " +
                              std::string(channel[c]) + " has min " + floatText(m_domainMin[c]) +
                              " and max " + floatText(m_domainMax[c]),
                          floatText(isMax ? m_domainMax[c] : m_domainMin[c]));
        }
    }
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
    LutFile file;
    file.format = "cube";
    if (m_size1D) {
        file.shaper.emplace(m_size1D);
        file.shaper->setTitle(m_title);
    }
    if (m_size3D) {
        file.cube.emplace(m_size3D);
        file.cube->setTitle(m_title);
    }
    struct Segment {
        float* begin;
        float* end;
    };
    Segment segments[2];
    int segmentCount = 0;
    if (file.shaper)
        segments[segmentCount++] = {&file.shaper->entries()[0].x,
                                    &file.shaper->entries()[0].x + 3 * std::size_t(m_size1D)};
    if (file.cube)
        segments[segmentCount++] = {file.cube->data(),
                                    file.cube->data() + 3 * file.cube->entryCount()};

    // Big plain files: all cores. Strict mode reports per-line departures, so it stays sequential.
    constexpr std::size_t kParallelMinRows = 32768;
    bool done = false;
    if (!m_strict && total >= kParallelMinRows && !m_reader.crOnly()) {
        const std::string_view rest = m_reader.rest();
        RowTarget target{segments[0].begin,
                         static_cast<std::size_t>(segments[0].end - segments[0].begin) / 3,
                         segmentCount > 1 ? segments[1].begin : nullptr};
        done = parallelRows(line.text.data(), rest.data() + rest.size(), total, target);
    }

    int segment = 0;
    float* out = segments[0].begin;
    float* outEnd = segments[0].end;
    std::size_t rows = 0;
    for (; !done;) {
        // `line` is a data line starting at s.
        if (!fastRow(s, e, out))
            slowRow(line, s, out);
        ++rows;
        out += 3;
        if (out == outEnd) {
            if (++segment == segmentCount)
                break;
            out = segments[segment].begin;
            outEnd = segments[segment].end;
        }
        for (;;) {
            if (!m_reader.next(line)) {
                const auto [l, c] = m_reader.endPosition();
                m_reader.fail(l, c,
                              "expected " + rowsExpected() + ", found " + std::to_string(rows) +
                                  " before the end of the file");
            }
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
            break;
        }
    }
    const int lastRowLine = line.number;
    // After the last row: only blank lines and comments. Stop at the first extra row, so a file
    // with a billion rows is refused without reading them.
    while (!done && m_reader.next(line)) {
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

    // Domains (checked in finishHeader).
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
    finishDepartures();
    file.diagnostics = m_diags;
    return file;
}

// Appends the shortest round-trip text of v (or fixed decimals).
inline char* putFloat(char* p, float v, int decimals) {
    if (decimals < 0)
        return std::to_chars(p, p + 48, v).ptr;
    return std::to_chars(p, p + 80, v, std::chars_format::fixed, decimals).ptr;
}

// Formats rows [0, count) of v (3 floats each) into dst; returns the number of non-finite values
// replaced. Plain loop, one bounds check per row.
// Shortest texts of recently written floats. LUTs repeat values a lot (a neutral N^3 table has N
// distinct values, one from 8-bit data at most 256), and a lookup costs a fraction of to_chars.
class FloatTextCache {
public:
    FloatTextCache() {
        for (auto& s : m_slots)
            s.bits = 0xFFFFFFFFu; // a NaN pattern: never looked up
    }
    char* put(char* p, float v) {
        std::uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        Slot& s = m_slots[(bits * 0x9E3779B1u) >> (32 - kBits)];
        if (s.bits != bits) {
            s.bits = bits;
            s.length = static_cast<std::uint8_t>(
                std::to_chars(s.text, s.text + sizeof s.text, v).ptr - s.text);
        }
        std::memcpy(p, s.text, sizeof s.text);
        return p + s.length;
    }

private:
    static constexpr int kBits = 10;
    struct Slot {
        std::uint32_t bits;
        std::uint8_t length;
        char text[19]; // the longest shortest float text is 15 bytes ("-1.17549435e-38")
    };
    std::array<Slot, 1u << kBits> m_slots;
};

std::size_t formatRows(std::string& dst, const float* v, std::size_t count, int decimals) {
    // Room for the longest row; the cache copies whole 19-byte slots, hence the margin.
    const std::size_t rowMax =
        decimals < 0 ? 3 * 20 + 19 : 3 * (static_cast<std::size_t>(decimals) + 42);
    auto cache = std::make_unique<FloatTextCache>();
    std::size_t nonFinite = 0;
    std::size_t used = dst.size();
    dst.resize(used + count * 3 * 12 + rowMax);
    for (std::size_t r = 0; r < count; ++r) {
        if (dst.size() - used < rowMax)
            dst.resize(dst.size() + (count - r) * 3 * 12 + rowMax);
        char* p = dst.data() + used;
        for (int c = 0; c < 3; ++c) {
            float x = v[r * 3 + static_cast<std::size_t>(c)];
            if (!std::isfinite(x)) {
                ++nonFinite;
                x = std::isnan(x) ? 0.0f : (x > 0 ? FLT_MAX : -FLT_MAX);
            }
            p = decimals < 0 ? cache->put(p, x) : putFloat(p, x, decimals);
            *p++ = c == 2 ? '\n' : ' ';
        }
        used = static_cast<std::size_t>(p - dst.data());
    }
    dst.resize(used);
    return nonFinite;
}

// Appends the rows to out, formatted on all cores in rounds of bounded size (so a 256^3 table
// does not need a second full-size copy of its text).
std::size_t putRows(std::string& out, const float* v, std::size_t count, int decimals) {
    constexpr std::size_t kParallelMin = 16384;
    constexpr std::size_t kRoundRows = std::size_t(1) << 20;
    const int threads = count < kParallelMin ? 1 : resolveThreads(0);
    if (threads <= 1)
        return formatRows(out, v, count, decimals);
    std::vector<std::string> parts(static_cast<std::size_t>(threads));
    std::vector<std::size_t> bad(static_cast<std::size_t>(threads));
    std::size_t nonFinite = 0;
    for (std::size_t begin = 0; begin < count; begin += kRoundRows) {
        const std::size_t n = std::min(kRoundRows, count - begin);
        parallelFor(threads, threads, [&](int t0, int t1) {
            for (int t = t0; t < t1; ++t) {
                const std::size_t a = begin + n * static_cast<std::size_t>(t) / threads;
                const std::size_t b = begin + n * static_cast<std::size_t>(t + 1) / threads;
                auto& part = parts[static_cast<std::size_t>(t)];
                part.clear();
                bad[static_cast<std::size_t>(t)] = formatRows(part, v + 3 * a, b - a, decimals);
            }
        });
        for (int t = 0; t < threads; ++t) {
            out += parts[static_cast<std::size_t>(t)];
            nonFinite += bad[static_cast<std::size_t>(t)];
        }
    }
    return nonFinite;
}

bool uniform(glm::vec3 v) {
    return v.x == v.y && v.y == v.z;
}

std::string oneLine(std::string s, const char* what, Diagnostics& d, bool isTitle) {
    bool changed = false;
    for (char& c : s)
        if (c == '\n' || c == '\r' || (isTitle && c == '"')) {
            c = c == '"' ? '\'' : ' ';
            changed = true;
        }
    // Leave room for the keyword and quotes so the line stays readable by our own limit.
    const std::size_t cap = limits::kMaxTextLineBytes - 16;
    if (s.size() > cap) {
        s.resize(cap);
        changed = true;
    }
    if (changed)
        d.push_back({Diagnostic::Severity::Warning,
                     {},
                     0,
                     0,
                     std::string(what) + " changed to fit one .cube line (quotes, line breaks or "
                                         "length)"});
    return s;
}

} // namespace

LutFile parseCube(std::string_view text, const std::string& path, const CubeReadOptions& options) {
    Diagnostics diags;
    CubeParser parser(text, path, options, diags);
    return parser.parse();
}

LutFile readCube(const std::string& path, const CubeReadOptions& options) {
    const FileView file(path);
    return parseCube(file.bytes(), path, options);
}

std::string writeCubeString(const LutFile& lut, Diagnostics* diagnostics,
                            const CubeWriteOptions& options) {
    if (!lut.cube && !lut.shaper)
        throw Error("cannot write a .cube: the LUT holds no table");
    Diagnostics local;
    Diagnostics& diags = diagnostics ? *diagnostics : local;
    const Lut1D* shaper = lut.shaper ? &*lut.shaper : nullptr;
    const Lut3D* cube = lut.cube ? &*lut.cube : nullptr;
    std::optional<Lut3D> baked;
    using Dialect = CubeWriteOptions::Dialect;
    bool resolve = false;
    if (shaper && cube) {
        const bool canResolve = uniform(shaper->domainMin()) && uniform(shaper->domainMax()) &&
                                uniform(cube->domainMin()) && uniform(cube->domainMax());
        if (options.dialect == Dialect::Adobe || !canResolve) {
            baked = lut.toLut3D(cube->size());
            cube = &*baked;
            shaper = nullptr;
            diags.push_back({Diagnostic::Severity::Warning,
                             {},
                             0,
                             0,
                             options.dialect == Dialect::Adobe
                                 ? "1D shaper baked into the 3D table: the Adobe dialect has no "
                                   "shaper"
                                 : "1D shaper baked into the 3D table: its domain differs per "
                                   "channel, and the Resolve dialect has one input range for all "
                                   "channels"});
        } else {
            resolve = true;
        }
    } else if (options.dialect == Dialect::Resolve ||
               (options.dialect == Dialect::Auto && lut.dialect == "resolve")) {
        const glm::vec3 mn = cube ? cube->domainMin() : shaper->domainMin();
        const glm::vec3 mx = cube ? cube->domainMax() : shaper->domainMax();
        resolve = uniform(mn) && uniform(mx);
        if (!resolve && options.dialect == Dialect::Resolve)
            diags.push_back({Diagnostic::Severity::Warning,
                             {},
                             0,
                             0,
                             "written in the Adobe dialect: the domain differs per channel, and "
                             "the Resolve dialect has one input range for all channels"});
    }

    const std::size_t rows =
        (shaper ? static_cast<std::size_t>(shaper->size()) : 0) + (cube ? cube->entryCount() : 0);
    std::string out;
    out.reserve(rows * (options.decimals < 0 ? 30 : 3 * (options.decimals + 4)) + 4096);

    static const std::vector<std::string> kNoComments;
    const std::vector<std::string>& comments = cube ? cube->comments() : kNoComments;
    for (const std::string& c : comments) {
        // A comment with line breaks becomes several comment lines.
        std::size_t start = 0;
        for (;;) {
            const std::size_t nl = c.find('\n', start);
            std::string part =
                c.substr(start, nl == std::string::npos ? std::string::npos : nl - start);
            if (!part.empty() && part.back() == '\r')
                part.pop_back();
            part = oneLine(std::move(part), "a comment", diags, false);
            out += part.empty() ? "#\n" : "# " + part + "\n";
            if (nl == std::string::npos)
                break;
            start = nl + 1;
        }
    }
    const std::string& title = cube ? cube->title() : shaper->title();
    if (!title.empty())
        out += "TITLE \"" + oneLine(title, "the title", diags, true) + "\"\n";

    char buf[256];
    auto putTriple = [&](const char* keyword, glm::vec3 v) {
        char* p = buf;
        for (int c = 0; c < 3; ++c) {
            *p++ = ' ';
            p = putFloat(p, v[c], -1);
        }
        out += keyword;
        out.append(buf, static_cast<std::size_t>(p - buf));
        out += '\n';
    };
    auto putRange = [&](const char* keyword, float a, float b) {
        char* p = buf;
        *p++ = ' ';
        p = putFloat(p, a, -1);
        *p++ = ' ';
        p = putFloat(p, b, -1);
        out += keyword;
        out.append(buf, static_cast<std::size_t>(p - buf));
        out += '\n';
    };
    auto isDefault = [](glm::vec3 mn, glm::vec3 mx) {
        return mn == glm::vec3(0.0f) && mx == glm::vec3(1.0f);
    };
    if (shaper) {
        out += "LUT_1D_SIZE " + std::to_string(shaper->size()) + "\n";
        if (resolve) {
            if (cube || !isDefault(shaper->domainMin(), shaper->domainMax()))
                putRange("LUT_1D_INPUT_RANGE", shaper->domainMin().x, shaper->domainMax().x);
        } else if (!isDefault(shaper->domainMin(), shaper->domainMax())) {
            putTriple("DOMAIN_MIN", shaper->domainMin());
            putTriple("DOMAIN_MAX", shaper->domainMax());
        }
    }
    if (cube) {
        out += "LUT_3D_SIZE " + std::to_string(cube->size()) + "\n";
        if (resolve) {
            if (shaper || !isDefault(cube->domainMin(), cube->domainMax()))
                putRange("LUT_3D_INPUT_RANGE", cube->domainMin().x, cube->domainMax().x);
        } else if (!isDefault(cube->domainMin(), cube->domainMax())) {
            putTriple("DOMAIN_MIN", cube->domainMin());
            putTriple("DOMAIN_MAX", cube->domainMax());
        }
    }

    const int decimals = std::min(options.decimals, 40);
    const std::size_t nonFinite =
        (shaper ? putRows(out, &shaper->entries()[0].x, static_cast<std::size_t>(shaper->size()),
                          decimals)
                : 0) +
        (cube ? putRows(out, cube->data(), cube->entryCount(), decimals) : 0);
    if (nonFinite)
        diags.push_back({Diagnostic::Severity::Warning,
                         {},
                         0,
                         0,
                         std::to_string(nonFinite) +
                             " non-finite value(s) written as 0 (NaN) or +-3.40282347e+38 "
                             "(infinity): .cube readers refuse NaN and Inf"});
    return out;
}

Diagnostics writeCube(const std::string& path, const LutFile& lut,
                      const CubeWriteOptions& options) {
    Diagnostics diags;
    const std::string text = writeCubeString(lut, &diags, options);
    writeFileAtomically(path, text);
    for (auto& d : diags)
        if (d.path.empty())
            d.path = path;
    return diags;
}

std::string describeCube(const LutFile& lut) {
    std::string s = lut.dialect.empty() ? "cube" : lut.dialect;
    if (lut.shaper && lut.cube)
        return s + " 1D " + std::to_string(lut.shaper->size()) + " + 3D, " +
               std::to_string(lut.cube->size()) + "^3";
    if (lut.cube)
        return s + " 3D, " + std::to_string(lut.cube->size()) + "^3";
    if (lut.shaper)
        return s + " 1D, " + std::to_string(lut.shaper->size());
    return s;
}

std::string CubeValidation::summary() const {
    return lut ? describeCube(*lut) : std::string();
}

CubeValidation validateCube(const std::string& path, bool strict) {
    CubeValidation v;
    Diagnostics diags;
    try {
        const FileView file(path);
        CubeReadOptions options;
        options.strict = strict;
        CubeParser parser(file.bytes(), path, options, diags);
        v.lut = parser.parse();
        v.diagnostics = v.lut->diagnostics;
        v.departures = parser.departures();
    } catch (const ParseError& e) {
        v.diagnostics = std::move(diags);
        // what() is "path:line:col: message (found '...')"; keep the part after the place.
        std::string prefix = e.path();
        if (e.line() > 0) {
            prefix += ":" + std::to_string(e.line());
            if (e.column() > 0)
                prefix += ":" + std::to_string(e.column());
        }
        prefix += ": ";
        std::string what = e.what();
        if (what.compare(0, prefix.size(), prefix) == 0)
            what.erase(0, prefix.size());
        v.diagnostics.push_back(
            {Diagnostic::Severity::Error, e.path(), e.line(), e.column(), what});
    } catch (const Error& e) {
        v.diagnostics = std::move(diags);
        v.diagnostics.push_back({Diagnostic::Severity::Error, {}, 0, 0, e.what()});
    }
    v.ok = v.lut.has_value();
    if (strict)
        for (const auto& d : v.diagnostics)
            if (d.severity != Diagnostic::Severity::Info)
                v.ok = false;
    return v;
}

namespace {

class CubeFormat final : public Format {
public:
    std::string name() const override { return "cube"; }
    std::string description() const override {
        return ".cube 1D/3D LUT, Adobe 1.0 and Resolve dialects (text)";
    }
    std::vector<std::string> extensions() const override { return {".cube"}; }
    LutFile read(const std::string& path, const FormatOptions& options) const override {
        CubeReadOptions o;
        o.strict = options.strict;
        return readCube(path, o);
    }
    LutFile readMemory(std::string_view bytes, const std::string& name,
                       const FormatOptions& options) const override {
        if (bytes.size() > limits::kMaxLutFileBytes)
            throw LimitError(name + ": " + std::to_string(bytes.size()) +
                             " bytes, over the limit of " +
                             std::to_string(limits::kMaxLutFileBytes) + " for a LUT file");
        CubeReadOptions o;
        o.strict = options.strict;
        return parseCube(bytes, name, o);
    }
    Diagnostics write(const std::string& path, const LutFile& lut,
                      const FormatOptions& options) const override {
        if (options.size != 0 && lut.cube && options.size != lut.cube->size()) {
            LutFile resized = lut;
            resized.cube = resample(*lut.cube, options.size, Interpolation::Tetrahedral);
            Diagnostics d = writeCube(path, resized);
            d.insert(d.begin(), {Diagnostic::Severity::Info, path, 0, 0,
                                 "3D table resampled from " + std::to_string(lut.cube->size()) +
                                     "^3 to " + std::to_string(options.size) + "^3 (tetrahedral)"});
            return d;
        }
        return writeCube(path, lut);
    }
};

} // namespace

std::unique_ptr<Format> makeCubeFormat() {
    return std::make_unique<CubeFormat>();
}

} // namespace lut::formats
