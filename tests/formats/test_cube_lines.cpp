// SPDX-License-Identifier: Apache-2.0
// The shared physical-line reader (formats/src/cube/TextLineReader.h): line numbers and columns as
// an editor shows them across LF, CR LF, lone CR, BOM, blank lines; bounded look at long lines.
#include "cube/TextLineReader.h"

#include <gtest/gtest.h>

#include <vector>

using namespace lut;
using namespace lut::formats;

namespace {

std::vector<std::pair<int, std::string>> lines(std::string_view data, std::size_t max = 1 << 16) {
    TextLineReader r(data, "t.txt", max);
    std::vector<std::pair<int, std::string>> out;
    TextLine l;
    while (r.next(l))
        out.emplace_back(l.number, std::string(l.text));
    return out;
}

using Lines = std::vector<std::pair<int, std::string>>;

} // namespace

TEST(CubeTextLines, LineEndsOfEveryKind) {
    EXPECT_EQ(lines("a\nb\n\nc"), (Lines{{1, "a"}, {2, "b"}, {3, ""}, {4, "c"}}));
    EXPECT_EQ(lines("a\r\n\r\nb\r\n"), (Lines{{1, "a"}, {2, ""}, {3, "b"}}));
    EXPECT_EQ(lines("a\r\rb\r"), (Lines{{1, "a"}, {2, ""}, {3, "b"}}));
    EXPECT_EQ(lines(""), Lines{});
    EXPECT_EQ(lines("\n"), (Lines{{1, ""}}));
    // A file ending in a lone CR after LF lines: the CR is a line end, not text.
    EXPECT_EQ(lines("a\nb\r"), (Lines{{1, "a"}, {2, "b"}}));
}

TEST(CubeTextLines, BomIsNotTextAndNotAColumn) {
    TextLineReader r("\xEF\xBB\xBFLUT\n", "b.txt");
    TextLine l;
    ASSERT_TRUE(r.next(l));
    EXPECT_TRUE(r.hasBom());
    EXPECT_EQ(l.text, "LUT");
    EXPECT_EQ(columnOf(l, l.text.data()), 1);
}

TEST(CubeTextLines, EndPosition) {
    {
        TextLineReader r("a\nbc", "e.txt");
        TextLine l;
        while (r.next(l)) {
        }
        EXPECT_EQ(r.endPosition(), std::make_pair(2, 3)); // after "bc" on line 2
    }
    {
        TextLineReader r("a\nbc\n", "e.txt");
        TextLine l;
        while (r.next(l)) {
        }
        EXPECT_EQ(r.endPosition(), std::make_pair(3, 1)); // the empty line after the last LF
    }
    TextLineReader empty("", "e.txt");
    EXPECT_EQ(empty.endPosition(), std::make_pair(1, 1));
}

TEST(CubeTextLines, LongLineRefusedWithLineAndLimit) {
    const std::string data = "ok\n" + std::string(100, 'x') + "\nnext\n";
    TextLineReader r(data, "long.txt", 64);
    TextLine l;
    ASSERT_TRUE(r.next(l));
    try {
        r.next(l);
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 2);
        EXPECT_EQ(e.column(), 65);
        EXPECT_EQ(e.message(),
                  "line is longer than the limit of 64 bytes (lut::limits::kMaxTextLineBytes)");
    }
    // Exactly at the limit, with CR LF, is fine.
    EXPECT_EQ(lines(std::string(64, 'y') + "\r\nz", 64).size(), 2u);
}
