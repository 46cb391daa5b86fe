// SPDX-License-Identifier: Apache-2.0
// .cube resource limits: huge declared sizes refused before any data is read, huge lines refused
// after a bounded look, endless rows refused at the first extra row, oversized files refused.
#include "TestSupport.h"

#include "lut/Limits.h"
#include "lut/formats/Cube.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

#include <string>

using namespace lut;
using namespace lut::formats;

namespace {

// A sparse file of `size` bytes starting with `head` (the rest reads as NUL bytes and takes no
// disk space).
std::string sparseFile(const std::string& name, const std::string& head, off_t size) {
    const std::string path = lut::test::tempDir() + "/" + name;
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    EXPECT_GE(fd, 0);
    EXPECT_EQ(::write(fd, head.data(), head.size()), static_cast<ssize_t>(head.size()));
    EXPECT_EQ(::ftruncate(fd, size), 0);
    ::close(fd);
    return path;
}

} // namespace

TEST(CubeLimits, HugeSizeRefusedBeforeAnyData) {
    // Only the header exists: a reader that allocated or read rows first would fail otherwise.
    for (const char* text : {"LUT_3D_SIZE 100000\n", "LUT_3D_SIZE 257\n",
                             "LUT_3D_SIZE 99999999999999999999999\n", "LUT_1D_SIZE 65537\n"}) {
        try {
            parseCube(text, "h.cube");
            FAIL() << text;
        } catch (const ParseError& e) {
            EXPECT_EQ(e.line(), 1);
            EXPECT_EQ(e.column(), 13);
            EXPECT_NE(e.message().find("is over the limit of"), std::string::npos);
            EXPECT_NE(e.message().find("lut::limits::kMax"), std::string::npos);
        }
    }
}

TEST(CubeLimits, LargestSizesAccepted) {
    // 256 is allowed: the error must be about missing rows, not the size.
    try {
        parseCube("LUT_3D_SIZE 256\n0 0 0\n", "max.cube");
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(
            e.message(),
            "expected 16777216 data rows for LUT_3D_SIZE 256, found 1 before the end of the file");
    }
    std::string text = "LUT_1D_SIZE 65536\n";
    for (int i = 0; i < 65536; ++i)
        text += "0.5 0.25 1\n";
    EXPECT_EQ(parseCube(text, "big1d.cube").shaper->size(), 65536);
}

TEST(CubeLimits, LineOfAGigabyteRefusedAtTheLimit) {
    // 1 GiB, all on line 2 (sparse: NUL bytes after the header).
    const std::string path = sparseFile("gigaline.cube", "LUT_3D_SIZE 2\n0 0 ", off_t(1) << 30);
    try {
        readCube(path);
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 2);
        EXPECT_EQ(e.column(), static_cast<int>(limits::kMaxTextLineBytes) + 1);
        EXPECT_EQ(e.message(), "line is longer than the limit of " +
                                   std::to_string(limits::kMaxTextLineBytes) +
                                   " bytes (lut::limits::kMaxTextLineBytes)");
    }
}

TEST(CubeLimits, LongLineAtTheLimitIsFine) {
    // A comment of exactly kMaxTextLineBytes bytes is accepted (CR LF not counted), one more
    // byte is not.
    const std::string okComment = "#" + std::string(limits::kMaxTextLineBytes - 1, 'x');
    const std::string body = "LUT_1D_SIZE 2\n0 0 0\n1 1 1\n";
    EXPECT_NO_THROW(parseCube(okComment + "\r\n" + body, "ok.cube"));
    try {
        parseCube(okComment + "x\n" + body, "long.cube");
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 1);
        EXPECT_EQ(e.column(), static_cast<int>(limits::kMaxTextLineBytes) + 1);
    }
}

TEST(CubeLimits, EndlessRowsStopAtTheFirstExtraRow) {
    // Ten million rows after a 2^3 cube: refused at row 9 (line 10) without reading the rest.
    std::string text = "LUT_3D_SIZE 2\n";
    text.reserve(14 + 10'000'000 * 6);
    for (int i = 0; i < 10'000'000; ++i)
        text += "0 0 0\n";
    try {
        parseCube(text, "endless.cube");
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 10);
        EXPECT_EQ(e.column(), 1);
        EXPECT_EQ(e.message(),
                  "too many data rows: expected 8 data rows for LUT_3D_SIZE 2, this is row 9");
    }
}

TEST(CubeLimits, FileLargerThanTheCapRefusedBeforeReading) {
    const std::string path = sparseFile("huge.cube", "LUT_3D_SIZE 2\n",
                                        static_cast<off_t>(limits::kMaxLutFileBytes) + 1);
    try {
        readCube(path);
        FAIL();
    } catch (const LimitError& e) {
        EXPECT_NE(std::string(e.what()).find("over the limit of " +
                                             std::to_string(limits::kMaxLutFileBytes)),
                  std::string::npos)
            << e.what();
    }
}

TEST(CubeLimits, MissingFileAndDirectory) {
    EXPECT_THROW(readCube("/nonexistent/x.cube"), Error);
    EXPECT_THROW(readCube(lut::test::tempDir()), Error);
}

TEST(CubeLimits, BinaryGarbageIsAnErrorNotACrash) {
    std::string junk;
    for (int i = 0; i < 4096; ++i)
        junk += static_cast<char>((i * 7919) & 0xff);
    EXPECT_THROW(parseCube(junk, "junk.cube"), ParseError);
    EXPECT_THROW(parseCube(std::string("LUT_3D_SIZE 2\n\0\0\0", 17), "nul.cube"), ParseError);
}
