// SPDX-License-Identifier: Apache-2.0
// Sony Pictures Imageworks .spi3d: OCIO 2.1 reads it but its Baker cannot write it, so we
// write it ourselves ("SPILUT 1.0", "3 3", "N N N", then one "r g b  R G B" line per lattice
// point with its indices; no domain, no shaper), and read it ourselves too, in every edition (the
// browser and Windows ones have no OpenColorIO): the same layout, each lattice point exactly once
// (OpenColorIO fills a missing one with 0), values as OpenColorIO reads them. tests/formats
// compares the reading with OpenColorIO's.
#include "Formats.h"
#include "LutPrep.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/NumberText.h"
#include "lut/io/Format.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <vector>

namespace lut::formats {

namespace {

// The file's text, line by line, with the position of every token for messages.
class Reader {
public:
    Reader(std::string_view text, std::string path) : m_text(text), m_path(std::move(path)) {}
    [[noreturn]] void fail(const std::string& what) const {
        throw ParseError(m_path, m_line, static_cast<int>(m_pos - m_lineStart) + 1, what);
    }
    bool more() {
        skipBlankLines();
        return m_pos < m_text.size();
    }
    void skipLine() {
        while (m_pos < m_text.size() && m_text[m_pos] != '\n' && m_text[m_pos] != '\r')
            ++m_pos;
        skipBlankLines();
    }
    void nextLine() {
        skipSpaces();
        if (m_pos < m_text.size() && m_text[m_pos] != '\n' && m_text[m_pos] != '\r')
            fail("unexpected text at the end of the line");
        skipBlankLines();
    }
    void expectWord(const char* word, const char* what) {
        skipBlankLines();
        const std::string_view w = token();
        if (w != word)
            fail(what);
    }
    long integer(const char* what) {
        const std::size_t at = m_pos;
        const std::string_view t = token();
        long v = 0;
        const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
        if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size()) {
            m_pos = at;
            skipSpaces();
            fail(std::string("expected the ") + what + " (an integer)");
        }
        return v;
    }
    float value() {
        const std::size_t at = m_pos;
        const std::string_view t = token();
        float v = 0.0f;
        const auto r = lut::fromChars(t.data(), t.data() + t.size(), v);
        if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v)) {
            m_pos = at;
            skipSpaces();
            fail("expected a finite number for a colour value");
        }
        return v;
    }

private:
    void skipSpaces() {
        while (m_pos < m_text.size() && (m_text[m_pos] == ' ' || m_text[m_pos] == '\t'))
            ++m_pos;
    }
    void skipBlankLines() {
        for (;;) {
            skipSpaces();
            if (m_pos >= m_text.size() || (m_text[m_pos] != '\n' && m_text[m_pos] != '\r'))
                return;
            if (m_text[m_pos] == '\r' && m_pos + 1 < m_text.size() && m_text[m_pos + 1] == '\n')
                ++m_pos;
            ++m_pos;
            ++m_line;
            m_lineStart = m_pos;
        }
    }
    std::string_view token() {
        skipSpaces();
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && !std::isspace(static_cast<unsigned char>(m_text[m_pos])))
            ++m_pos;
        return m_text.substr(start, m_pos - start);
    }

    std::string_view m_text;
    std::string m_path;
    std::size_t m_pos = 0, m_lineStart = 0;
    int m_line = 1;
};

class Spi3dFormat final : public Format {
public:
    std::string name() const override { return "spi3d"; }
    std::string description() const override { return "Sony Imageworks .spi3d"; }
    std::vector<std::string> extensions() const override { return {".spi3d"}; }
    LutFile readMemory(std::string_view bytes, const std::string& path,
                       const FormatOptions&) const override {
        Reader in(bytes, path);
        in.expectWord("SPILUT", "a .spi3d starts with SPILUT 1.0");
        in.skipLine(); // the version, as OpenColorIO takes any

        if (in.integer("input dimensions") != 3 || in.integer("output dimensions") != 3)
            in.fail("a 3D .spi3d has 3 input and 3 output dimensions (\"3 3\")");
        in.nextLine();
        const long n = in.integer("lattice size");
        if (in.integer("lattice size") != n || in.integer("lattice size") != n)
            in.fail("the lattice must have the same size on all three axes");
        if (n < 2 || n > limits::kMax3DSize)
            in.fail("lattice size " + std::to_string(n) + " is outside 2.." +
                    std::to_string(limits::kMax3DSize));
        in.nextLine();
        const int size = static_cast<int>(n);
        LutFile f;
        f.cube = Lut3D(size);
        f.format = name();
        std::vector<unsigned char> seen(f.cube->entryCount(), 0);
        std::size_t count = 0;
        while (in.more()) {
            int idx[3];
            for (int& i : idx) {
                const long v = in.integer("lattice index");
                if (v < 0 || v >= n)
                    in.fail("lattice index " + std::to_string(v) + " outside 0.." +
                            std::to_string(n - 1));
                i = static_cast<int>(v);
            }
            glm::vec3 c;
            for (int k = 0; k < 3; ++k)
                c[k] = in.value();
            const std::size_t at = f.cube->index(idx[0], idx[1], idx[2]);
            if (seen[at])
                in.fail("lattice point " + std::to_string(idx[0]) + " " + std::to_string(idx[1]) +
                        " " + std::to_string(idx[2]) + " given twice");
            seen[at] = 1;
            f.cube->at(idx[0], idx[1], idx[2]) = c;
            ++count;
            in.nextLine();
        }
        if (count != f.cube->entryCount())
            in.fail(std::to_string(count) + " of the " + std::to_string(f.cube->entryCount()) +
                    " lattice points given");
        return f;
    }
    std::string writeMemory(const LutFile& file, const std::string& path,
                            const FormatOptions& options, Diagnostics* diagnostics) const override {
        Diagnostics diags;
        const Lut3D lut = prepareUnitLut(file, options.size, path, diags);
        const int n = lut.size();
        std::string text = "SPILUT 1.0\n3 3\n" + std::to_string(n) + " " + std::to_string(n) + " " +
                           std::to_string(n) + "\n";
        text.reserve(text.size() + static_cast<std::size_t>(n) * n * n * 48);
        char buf[160];
        for (int r = 0; r < n; ++r)
            for (int g = 0; g < n; ++g)
                for (int b = 0; b < n; ++b) {
                    const glm::vec3 v = lut.at(r, g, b);
                    // %.9g: every float reads back as itself.
                    std::snprintf(buf, sizeof buf, "%d %d %d %.9g %.9g %.9g\n", r, g, b,
                                  double(v.x), double(v.y), double(v.z));
                    text += buf;
                }
        if (diagnostics)
            *diagnostics = std::move(diags);
        return text;
    }
};

} // namespace

std::unique_ptr<Format> makeSpi3dFormat() {
    return std::make_unique<Spi3dFormat>();
}

} // namespace lut::formats
