// SPDX-License-Identifier: Apache-2.0
// Resource limits: files that claim or contain far too much are refused early, with a message
// that names the limit. Large files are made sparse (ftruncate) so the tests cost nothing: a
// reader that tried to read them whole would need gigabytes, so passing shows it did not.
#include "RobustSupport.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/formats/Registry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

using namespace lut::robust;
using ::testing::HasSubstr;

namespace {

// Writes head, then extends the file with zero bytes (a hole) to `total` bytes.
void writeSparse(const std::string& path, const std::string& head, std::uint64_t total) {
    writeBytes(path, head);
    const int fd = ::open(path.c_str(), O_WRONLY);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::ftruncate(fd, static_cast<off_t>(total)), 0);
    ::close(fd);
}

std::string readError(const std::string& path, const lut::FormatOptions& options = {}) {
    try {
        (void)lut::formats::readLut(path, options);
    } catch (const lut::Error& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(Limits, CubeSize100000IsRefusedAtItsLineNamingTheLimit) {
    const std::string dir = lut::test::tempDir();
    // The size line comes first; 8 rows follow. A reader that allocated 100000^3 entries before
    // checking would die here (12 PB).
    writeBytes(dir + "/huge.cube", "LUT_3D_SIZE 100000\n0 0 0\n");
    EXPECT_EQ(stripDir(readError(dir + "/huge.cube"), dir),
              "huge.cube:1:13: LUT_3D_SIZE 100000 is over the limit of 256 "
              "(lut::limits::kMax3DSize) (found "
              "'100000')");
    writeBytes(dir + "/huge1d.cube", "LUT_1D_SIZE 4294967296\n");
    EXPECT_THAT(readError(dir + "/huge1d.cube"), HasSubstr("65536"));
}

TEST(Limits, NutexbWidth2Pow31IsRefusedNamingTheLimit) {
    const std::string dir = lut::test::tempDir();
    NutexbFields f;
    f.width = f.height = f.depth = 1u << 31;
    writeBytes(dir + "/wide.nutexb", nutexbFile(f, 1024));
    EXPECT_EQ(stripDir(readError(dir + "/wide.nutexb"), dir),
              "wide.nutexb: nutexb width: found 2147483648, expected a LUT size 2..256");
    // Only the width is huge: refused naming the width (the field that disagrees with the two
    // others), still before allocating.
    NutexbFields g;
    g.width = 1u << 31;
    writeBytes(dir + "/wide2.nutexb", nutexbFile(g, 1024));
    EXPECT_EQ(stripDir(readError(dir + "/wide2.nutexb"), dir),
              "wide2.nutexb: nutexb width: found 2147483648, expected 2 (equal to height and "
              "depth for a LUT)");
}

TEST(Limits, NutexbFileLargerThanAny256CubeIsRefusedBeforeReading) {
    const std::string dir = lut::test::tempDir();
    // 256^3 tiled RGBA8 is 64 MiB; a 1 GiB file cannot be a LUT.
    writeSparse(dir + "/big.nutexb", "", 1ull << 30);
    const std::string msg = stripDir(readError(dir + "/big.nutexb"), dir);
    EXPECT_THAT(msg, HasSubstr("big.nutexb: file is 1073741824 bytes, over the limit of "));
}

TEST(Limits, CubeWithFiftyMegabytesOfExtraRowsStopsAtTheFirstExtraRow) {
    const std::string dir = lut::test::tempDir();
    std::string text = neutralCube(2);
    const std::string row = "0.5 0.5 0.5\n";
    std::string extra;
    extra.reserve(50u << 20);
    while (extra.size() < (50u << 20))
        extra += row;
    writeBytes(dir + "/rows.cube", text + extra);
    // Line 1 is the size, lines 2..9 the 8 rows, line 10 the first row too many.
    EXPECT_EQ(
        stripDir(readError(dir + "/rows.cube"), dir),
        "rows.cube:10:1: too many data rows: expected 8 data rows for LUT_3D_SIZE 2, this is row 9 "
        "(found '0.5 0.5 0.5')");
    std::filesystem::remove_all(dir); // 50 MB
}

TEST(Limits, CubeLineOfAGigabyteIsRefusedAfterTheLineLimit) {
    const std::string dir = lut::test::tempDir();
    // A comment line that goes on for 1 GiB (zero bytes in a hole: nothing on disk).
    writeSparse(dir + "/longline.cube", "LUT_3D_SIZE 2\n# ", (1ull << 30) + 2);
    const std::string msg = stripDir(readError(dir + "/longline.cube"), dir);
    EXPECT_THAT(msg,
                HasSubstr("longline.cube:2:65537: line is longer than the limit of 65536 bytes "
                          "(lut::limits::kMaxTextLineBytes)"));
    // A data line of 100 MB of digits, really written.
    writeBytes(dir + "/longrow.cube", "LUT_3D_SIZE 2\n" + std::string(100u << 20, '1') + " 0 0\n");
    EXPECT_THAT(stripDir(readError(dir + "/longrow.cube"), dir),
                HasSubstr("longrow.cube:2:65537: line is longer than the limit of 65536 bytes "
                          "(lut::limits::kMaxTextLineBytes)"));
    std::filesystem::remove_all(dir); // 100 MB
}

TEST(Limits, CubeFileOverTheFileSizeLimitIsRefusedBeforeReading) {
    const std::string dir = lut::test::tempDir();
    writeSparse(dir + "/giant.cube", "LUT_3D_SIZE 2\n", lut::limits::kMaxLutFileBytes + 1);
    EXPECT_EQ(stripDir(readError(dir + "/giant.cube"), dir),
              "giant.cube: file is 2147483649 bytes, over the limit of 2147483648 bytes "
              "(lut::limits::kMaxLutFileBytes)");
}

TEST(Limits, ImageHeaderClaimingFourGigapixelsIsALimitError) {
    const std::string dir = lut::test::tempDir();
    // Same crafted header as in the malformed table; here the error type is checked too.
    writeBytes(dir + "/huge.png", craftedPng(65536, 65536, 2, "\x78\x01"));
    try {
        (void)lut::formats::readLut(dir + "/huge.png");
        FAIL() << "accepted";
    } catch (const lut::LimitError& e) {
        EXPECT_EQ(stripDir(e.what(), dir),
                  "huge.png: image is 65536x65536 with 3 channels, over the limit of "
                  "268435456 pixels and 64 channels");
    }
}

// Found by fuzz_image_apply: a 330-byte OpenEXR file whose "Software" attribute claims 1.7 GB made
// OpenEXR (inside OpenImageIO's open, before any size check of ours) take 1.8 GB of memory and
// 3 s. The header's declared sizes are now checked against the file first. The file is built here
// field by field from the OpenEXR layout: magic, version 2, attributes "name\0type\0" + size.
TEST(Limits, OpenExrAttributeClaimingMoreThanTheFileIsRefusedBeforeOpening) {
    const std::string dir = lut::test::tempDir();
    auto le = [](std::uint32_t v) {
        return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)};
    };
    const std::string exr =
        std::string("\x76\x2f\x31\x01", 4) + le(2) + std::string("comments\0string\0", 16) + le(4) +
        "abcd" + std::string("Software\0string\0", 16) + le(1735289202) + std::string(100, 'x');
    writeBytes(dir + "/claims.exr", exr);
    const auto r =
        lut::test::runCli("apply --lut '" + lut::test::dataPath("cube/adobe_3d_domain.cube") +
                          "' '" + dir + "/claims.exr' -o '" + dir + "/out.exr'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(stripDir(r.err, dir),
              "lutkit: error: claims.exr: OpenEXR header attribute 'Software' declares 1735289202 "
              "bytes, but only 100 bytes follow in the file (truncated or corrupt)\n");
}

} // namespace
