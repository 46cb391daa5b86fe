// SPDX-License-Identifier: Apache-2.0
// Memory bounded in every command (issue 41): a picture a command needs only in part or in one
// pass is streamed or subsampled, never held as a float frame. Each reproducer of the issue, its
// peak resident memory measured by /usr/bin/time (memory is asserted, never time): before,
// `match` on one 16384^2 PNG took 4.3 GB, `check --image` 4.1 GB, `atlas info` on 8192 rows about
// 8 GB, standard input that starts with a PNG signature and goes on with zeros 4.1 GB.
#include "HostileSupport.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <zlib.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

using namespace lut::robust;
using ::testing::HasSubstr;

namespace {

constexpr double kBoundMiB = 512.0;

std::string be32s(std::uint32_t v) {
    return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

void chunk(std::FILE* f, const char* type, const std::string& data) {
    const std::string head = be32s(static_cast<std::uint32_t>(data.size())) + type;
    uLong crc = crc32(0, reinterpret_cast<const Bytef*>(type), 4);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(data.data()), static_cast<uInt>(data.size()));
    std::fwrite(head.data(), 1, head.size(), f);
    std::fwrite(data.data(), 1, data.size(), f);
    const std::string tail = be32s(static_cast<std::uint32_t>(crc));
    std::fwrite(tail.data(), 1, 4, f);
}

// An 8-bit PNG of width x height with `channels` (3 or 4) written a row at a time (each row
// filtered "Up", so repeated rows cost nothing): row(y, bytes) fills a row's samples. A
// picture of gigabytes of pixels in a file of a few MB, never held in memory here either.
void writeLargePng(const std::string& path, int width, int height, int channels,
                   const std::function<void(int y, std::vector<std::uint8_t>& row)>& row) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fwrite("\x89PNG\r\n\x1a\n", 1, 8, f);
    std::string ihdr =
        be32s(static_cast<std::uint32_t>(width)) + be32s(static_cast<std::uint32_t>(height));
    ihdr += char(8);
    ihdr += char(channels == 4 ? 6 : 2);
    ihdr += std::string(3, '\0');
    chunk(f, "IHDR", ihdr);
    z_stream z{};
    ASSERT_EQ(deflateInit(&z, 1), Z_OK);
    const std::size_t rb = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
    std::vector<std::uint8_t> prev(rb, 0), cur(rb), line(rb + 1);
    std::vector<unsigned char> out(1 << 20);
    auto pump = [&](int flush) {
        do {
            z.next_out = out.data();
            z.avail_out = static_cast<uInt>(out.size());
            deflate(&z, flush);
            const std::size_t got = out.size() - z.avail_out;
            if (got > 0)
                chunk(f, "IDAT", std::string(reinterpret_cast<const char*>(out.data()), got));
        } while (z.avail_out == 0);
    };
    for (int y = 0; y < height; ++y) {
        row(y, cur);
        line[0] = 2; // Up
        for (std::size_t i = 0; i < rb; ++i)
            line[i + 1] = static_cast<std::uint8_t>(cur[i] - prev[i]);
        prev.swap(cur);
        z.next_in = line.data();
        z.avail_in = static_cast<uInt>(line.size());
        pump(Z_NO_FLUSH);
    }
    pump(Z_FINISH);
    deflateEnd(&z);
    chunk(f, "IEND", "");
    std::fclose(f);
}

// 16384^2 RGB: 64x64 blocks of colours, so matching has something to match.
void writeLargePicture(const std::string& path, int side = 16384) {
    writeLargePng(path, side, side, 3, [](int y, std::vector<std::uint8_t>& row) {
        for (std::size_t x = 0; x < row.size() / 3; ++x) {
            row[3 * x] = static_cast<std::uint8_t>((x >> 6) * 5);
            row[3 * x + 1] = static_cast<std::uint8_t>((y >> 6) * 3);
            row[3 * x + 2] = static_cast<std::uint8_t>(((x >> 6) ^ (y >> 6)) * 7);
        }
    });
}

// A ReShade atlas of `rows` neutral 32^3 rows (1024 x 32 * rows, RGBA): x = b * 32 + r, y = g.
void writeNeutralAtlas(const std::string& path, int rows) {
    writeLargePng(path, 1024, 32 * rows, 4, [](int y, std::vector<std::uint8_t>& row) {
        const auto code = [](int v) { return static_cast<std::uint8_t>((v * 255 + 15) / 31); };
        for (int x = 0; x < 1024; ++x) {
            std::uint8_t* p = &row[4 * static_cast<std::size_t>(x)];
            p[0] = code(x % 32);
            p[1] = code(y % 32);
            p[2] = code(x / 32);
            p[3] = 255;
        }
    });
}

// `lutkit ARGS` with standard input from a shell command's output: the result and the peak.
Measured runPiped(const std::string& producer, const std::string& args, const std::string& dir) {
    Measured m;
    const std::string timeFile = dir + "/time.txt", out = dir + "/run.out", err = dir + "/run.err";
    const std::string cmd = producer + " | /usr/bin/time -f 'peak %M' -o " + shellQuoted(timeFile) +
                            " " + shellQuoted(LUTKIT_CLI) + " " + args + " >" + shellQuoted(out) +
                            " 2>" + shellQuoted(err);
    writeBytes(dir + "/run.sh", cmd + "\n"); // the producer's own quotes kept as written
    const int status = std::system(("bash " + shellQuoted(dir + "/run.sh")).c_str());
    m.run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    m.run.out = fileBytes(out);
    m.run.err = fileBytes(err);
    const std::string t = fileBytes(timeFile);
    const auto at = t.rfind("peak ");
    m.peakMiB = at == std::string::npos ? -1.0 : std::atof(t.c_str() + at + 5) / 1024.0;
    return m;
}

class MemoryBounds : public ::testing::Test {
protected:
    void SetUp() override {
        if (kMemorySanitized)
            GTEST_SKIP() << "peak memory means nothing under a sanitizer";
        dir = lut::test::tempDir();
    }
    // The 16384^2 picture, written once per test that needs it (~1 MB).
    std::string large() {
        const std::string path = dir + "/large.png";
        if (!std::filesystem::exists(path))
            writeLargePicture(path);
        return path;
    }
    std::string dir;
};

// The fit samples at most 4 megapixels of a picture: only that grid is read (a 2048^2 frame).
TEST_F(MemoryBounds, MatchReadsOnlyTheGridItSamplesOfA16384SquarePicture) {
    writeLargePng(dir + "/ref.png", 256, 256, 3, [](int y, std::vector<std::uint8_t>& row) {
        for (std::size_t x = 0; x < row.size() / 3; ++x) {
            row[3 * x] = static_cast<std::uint8_t>(x);
            row[3 * x + 1] = static_cast<std::uint8_t>(255 - y);
            row[3 * x + 2] = 90;
        }
    });
    const Measured m =
        runMeasured("match " + shellQuoted(large()) + " " + shellQuoted(dir + "/ref.png") + " " +
                        shellQuoted(dir + "/look.cube") + " -y",
                    dir);
    ASSERT_EQ(m.run.exitCode, 0) << m.run.err;
    // The report counts the whole picture's pixels, of which it sampled a 2048^2 grid.
    EXPECT_THAT(m.run.out, HasSubstr("of 268435456"));
    EXPECT_LT(m.peakMiB, kBoundMiB) << m.run.out;
}

// A mask of a large picture is read on the same grid; one of another size is still refused
// with both whole sizes.
TEST_F(MemoryBounds, MatchReadsALargeMaskOnItsPicturesGridAndNamesWholeSizes) {
    writeLargePng(dir + "/mask-small.png", 100, 100, 3, [](int, std::vector<std::uint8_t>& row) {
        std::fill(row.begin(), row.end(), 255);
    });
    const Measured m = runMeasured("match " + shellQuoted(large()) + " " + shellQuoted(large()) +
                                       " " + shellQuoted(dir + "/self.cube") +
                                       " -y --mask-source " + shellQuoted(dir + "/mask-small.png"),
                                   dir);
    EXPECT_EQ(m.run.exitCode, 1);
    EXPECT_THAT(m.run.err, HasSubstr("the mask is 100x100, the picture 16384x16384"));
    EXPECT_LT(m.peakMiB, kBoundMiB);
}

// check --image weighs the picture's colours as it reads them.
TEST_F(MemoryBounds, CheckImageWeighsA16384SquarePictureAsItIsRead) {
    writeBytes(dir + "/n.cube", neutralCube(17));
    const Measured m = runMeasured(
        "check " + shellQuoted(dir + "/n.cube") + " --image " + shellQuoted(large()), dir);
    ASSERT_EQ(m.run.exitCode, 0) << m.run.err;
    EXPECT_THAT(m.run.out, HasSubstr("picture"));
    EXPECT_LT(m.peakMiB, kBoundMiB) << m.run.out;
}

// atlas info and split read one row of the atlas at a time (before: every row kept, with the
// picture as a float frame: about 8 GB for 8192 rows of 32^3).
TEST_F(MemoryBounds, AtlasInfoOf8192RowsHoldsOneRowAtATime) {
    writeNeutralAtlas(dir + "/atlas.png", 8192);
    // The layout named: one pass over the 268 megapixels (detection is a second, the same way).
    const Measured m =
        runMeasured("atlas info " + shellQuoted(dir + "/atlas.png") + " --in-layout reshade", dir);
    ASSERT_EQ(m.run.exitCode, 0) << m.run.err;
    EXPECT_THAT(m.run.out, HasSubstr("rows     8192 (32^3 each)"));
    // Every row is the neutral LUT; each repeat is paired with the first row that held it.
    EXPECT_THAT(m.run.out, HasSubstr("row 8191 = row 0\n"));
    EXPECT_THAT(m.run.out, ::testing::Not(HasSubstr("row 2 = row 1")));
    EXPECT_LT(m.peakMiB, kBoundMiB);
    std::filesystem::remove_all(dir);
}

// split writes each row as it is read (1024 rows: each file is synced and read back, 8192 of
// them take minutes; the memory does not depend on the count: before, 1 GB here).
TEST_F(MemoryBounds, AtlasSplitOf1024RowsHoldsOneRowAtATime) {
    writeNeutralAtlas(dir + "/atlas.png", 1024);
    std::filesystem::create_directories(dir + "/rows");
    const Measured m = runMeasured("atlas split " + shellQuoted(dir + "/atlas.png") + " -o " +
                                       shellQuoted(dir + "/rows/") + " -q",
                                   dir);
    ASSERT_EQ(m.run.exitCode, 0) << m.run.err;
    EXPECT_EQ(listDir(dir + "/rows").size(), 1024u);
    EXPECT_LT(m.peakMiB, kBoundMiB);
    std::filesystem::remove_all(dir);
}

// Standard input whose header says it is not what its signature claims is refused once its
// head has arrived, not buffered to the 2 GiB limit.
TEST_F(MemoryBounds, StandardInputWithAPngSignatureThenZerosIsRefusedAtItsHeader) {
    writeBytes(dir + "/n.cube", neutralCube(5));
    const Measured m = runPiped("{ printf '\\211PNG\\r\\n\\032\\n'; cat /dev/zero; }",
                                "apply --lut " + shellQuoted(dir + "/n.cube") + " - -o " +
                                    shellQuoted(dir + "/z.png") + " -y",
                                dir);
    EXPECT_EQ(m.run.exitCode, 1) << m.run.err;
    EXPECT_THAT(m.run.err, HasSubstr("-: "));
    EXPECT_LT(m.peakMiB, 64.0) << m.run.err;
}

TEST_F(MemoryBounds, StandardInputNamedPngWithoutItsSignatureIsRefusedAtOnce) {
    writeBytes(dir + "/n.cube", neutralCube(5));
    const Measured m =
        runMeasured("apply --lut " + shellQuoted(dir + "/n.cube") + " - --in-format png -o " +
                        shellQuoted(dir + "/z.png") + " -y",
                    dir, "/dev/zero");
    EXPECT_EQ(m.run.exitCode, 1) << m.run.err;
    EXPECT_THAT(m.run.err, HasSubstr("does not start as a png file does"));
    EXPECT_LT(m.peakMiB, 64.0) << m.run.err;
}

TEST_F(MemoryBounds, StandardInputOfCommentLinesAloneIsNoLutFile) {
    const Measured m = runPiped("yes '# c'", "info -", dir);
    EXPECT_EQ(m.run.exitCode, 1) << m.run.err;
    EXPECT_THAT(m.run.err, HasSubstr("comment and blank lines only"));
    EXPECT_LT(m.peakMiB, 64.0) << m.run.err;
}

// Every command takes --max-memory, with the same grammar; a frame over it is refused naming it.
TEST_F(MemoryBounds, EveryCommandTakesMaxMemory) {
    writeBytes(dir + "/n.cube", neutralCube(5));
    for (const std::string command :
         {"neutral", "convert", "info",  "validate", "apply", "preview", "embed",  "extract",
          "fit",     "match",   "bench", "bake",     "diff",  "compose", "invert", "resize",
          "smooth",  "mix",     "plot",  "adjust",   "check", "chart",   "atlas"}) {
        const lut::test::RunResult r = lut::test::runCli(command + " --help");
        EXPECT_THAT(r.out, HasSubstr("--max-memory")) << command;
    }
    lut::test::RunResult r =
        lut::test::runCli("info " + shellQuoted(dir + "/n.cube") + " --max-memory 64M");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    r = lut::test::runCli("info " + shellQuoted(dir + "/n.cube") + " --max-memory 1e3");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    // A frame over the limit: refused before it is allocated, the limit named.
    writeLargePicture(dir + "/5000.png", 5000);
    r = lut::test::runCli("extract " + shellQuoted(dir + "/5000.png") + " " +
                          shellQuoted(dir + "/x.cube") + " --max-memory 256M");
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_THAT(r.err, HasSubstr("over the memory limit of 256 MiB (--max-memory)"));
}

// extract searches the whole picture for a patch: a picture larger than an 8K screenshot is
// refused before it is read (it took 4.1 GB), with advice.
TEST_F(MemoryBounds, ExtractRefusesAPictureLargerThanAn8KScreenshotBeforeReadingIt) {
    const Measured m =
        runMeasured("extract " + shellQuoted(large()) + " " + shellQuoted(dir + "/x.cube"), dir);
    EXPECT_EQ(m.run.exitCode, 1) << m.run.err;
    EXPECT_THAT(m.run.err, HasSubstr("16384x16384 pixels, more than extract searches for a patch"));
    EXPECT_THAT(m.run.err, HasSubstr("crop it around the patch"));
    EXPECT_LT(m.peakMiB, kBoundMiB);
}

} // namespace
