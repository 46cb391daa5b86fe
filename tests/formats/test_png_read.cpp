// SPDX-License-Identifier: Apache-2.0
// The native PNG reader (formats/src/imageio/PngCodec.cpp: libdeflate + PngUnfilter for the common
// files, libpng for the others) against OpenImageIO's decoding of the same files, and against the
// samples the test itself wrote. The files are written here, filters and Adam7 plainly from the
// specification (https://www.w3.org/TR/png/, sections 8.2 and 9), so every filter type is
// certainly in them: rows cycle through None, Sub, Up, Average and Paeth on random samples.
#include "imageio/ImageCodec.h"

#include "lut/Error.h"

#include "TestSupport.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace {

using Bytes = std::vector<unsigned char>;

void put32(Bytes& b, std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8)
        b.push_back(static_cast<unsigned char>(v >> s));
}

void chunk(Bytes& png, const char* type, const Bytes& data) {
    put32(png, static_cast<std::uint32_t>(data.size()));
    Bytes body(type, type + 4);
    body.insert(body.end(), data.begin(), data.end());
    png.insert(png.end(), body.begin(), body.end());
    put32(png, static_cast<std::uint32_t>(crc32(0, body.data(), static_cast<uInt>(body.size()))));
}

int paeth(int a, int b, int c) { // section 9.4, as written there
    const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

// Row `cur` (n bytes) filtered with `type` against the previous row `prev` (zeros for the first).
Bytes filterRow(int type, const Bytes& cur, const Bytes& prev, std::size_t bpp) {
    Bytes out{static_cast<unsigned char>(type)};
    for (std::size_t i = 0; i < cur.size(); ++i) {
        const int a = i >= bpp ? cur[i - bpp] : 0, b = prev[i], c = i >= bpp ? prev[i - bpp] : 0;
        const int pred = type == 0   ? 0
                         : type == 1 ? a
                         : type == 2 ? b
                         : type == 3 ? (a + b) / 2
                                     : paeth(a, b, c);
        out.push_back(static_cast<unsigned char>((cur[i] - pred) & 0xff));
    }
    return out;
}

// A PNG of the big-endian samples `s` (w x h x ch, depth 8 or 16); row y of a pass is filtered
// with (y + pass) % 5. Adam7 when `interlaced`.
std::string writePng(const std::string& name, int w, int h, int ch, int depth, const Bytes& s,
                     bool interlaced) {
    const int colour = ch == 1 ? 0 : ch == 2 ? 4 : ch == 3 ? 2 : 6;
    const std::size_t bpp = static_cast<std::size_t>(ch * depth / 8);
    struct Pass {
        int x0, y0, dx, dy;
    };
    const std::vector<Pass> passes =
        interlaced ? std::vector<Pass>{{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4},
                                       {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}}
                   : std::vector<Pass>{{0, 0, 1, 1}};
    Bytes raw;
    for (std::size_t p = 0; p < passes.size(); ++p) {
        const Pass& q = passes[p];
        Bytes prev;
        for (int y = q.y0, row = 0; y < h; y += q.dy, ++row) {
            Bytes cur;
            for (int x = q.x0; x < w; x += q.dx)
                cur.insert(cur.end(), s.begin() + static_cast<long>((std::size_t(y) * w + x) * bpp),
                           s.begin() + static_cast<long>((std::size_t(y) * w + x + 1) * bpp));
            if (cur.empty())
                break; // an empty pass has no rows at all
            if (prev.empty())
                prev.assign(cur.size(), 0);
            const Bytes f = filterRow(static_cast<int>((row + p) % 5), cur, prev, bpp);
            raw.insert(raw.end(), f.begin(), f.end());
            prev = cur;
        }
    }
    Bytes png{137, 'P', 'N', 'G', 13, 10, 26, 10}, ihdr;
    put32(ihdr, static_cast<std::uint32_t>(w));
    put32(ihdr, static_cast<std::uint32_t>(h));
    ihdr.insert(ihdr.end(), {static_cast<unsigned char>(depth), static_cast<unsigned char>(colour),
                             0, 0, static_cast<unsigned char>(interlaced ? 1 : 0)});
    chunk(png, "IHDR", ihdr);
    uLongf zn = compressBound(static_cast<uLong>(raw.size()));
    Bytes z(zn);
    EXPECT_EQ(compress2(z.data(), &zn, raw.data(), static_cast<uLong>(raw.size()), 6), Z_OK);
    z.resize(zn);
    const std::size_t half = z.size() / 2; // two IDAT chunks: the reader joins them
    chunk(png, "IDAT", Bytes(z.begin(), z.begin() + static_cast<long>(half)));
    chunk(png, "IDAT", Bytes(z.begin() + static_cast<long>(half), z.end()));
    chunk(png, "IEND", {});
    const std::string path = lut::test::tempDir() + "/" + name;
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    return path;
}

// The samples of `path` as our reader gives them (16-bit: host order), read in two strips.
std::vector<std::uint32_t> readOurs(const std::string& path) {
    auto src = lut::formats::openImageSource(path);
    const auto& info = src->info();
    const std::size_t rb = lut::formats::rowBytes(info);
    Bytes buf(rb * static_cast<std::size_t>(info.height));
    const int mid = info.height / 2;
    src->readRows(0, mid, buf.data());
    src->readRows(mid, info.height, buf.data() + rb * static_cast<std::size_t>(mid));
    src->finish();
    std::vector<std::uint32_t> v;
    if (info.type == lut::formats::PixelType::UInt16) {
        for (std::size_t i = 0; i < buf.size(); i += 2) {
            std::uint16_t x;
            std::memcpy(&x, buf.data() + i, 2);
            v.push_back(x);
        }
    } else {
        v.assign(buf.begin(), buf.end());
    }
    return v;
}

// The same through OpenImageIO, in the file's own integer type.
std::vector<std::uint32_t> readOiio(const std::string& path, int depth) {
    OIIO::ImageSpec config; // the samples as stored: no premultiplication by alpha
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    EXPECT_TRUE(in) << path;
    if (!in)
        return {};
    const std::size_t n = static_cast<std::size_t>(in->spec().width) * in->spec().height *
                          static_cast<std::size_t>(in->spec().nchannels);
    std::vector<std::uint32_t> v;
    if (depth == 16) {
        std::vector<std::uint16_t> b(n);
        EXPECT_TRUE(
            in->read_image(0, 0, 0, in->spec().nchannels, OIIO::TypeDesc::UINT16, b.data()));
        v.assign(b.begin(), b.end());
    } else {
        Bytes b(n);
        EXPECT_TRUE(in->read_image(0, 0, 0, in->spec().nchannels, OIIO::TypeDesc::UINT8, b.data()));
        v.assign(b.begin(), b.end());
    }
    return v;
}

// The samples the test wrote, as numbers.
std::vector<std::uint32_t> truth(const Bytes& s, int depth) {
    std::vector<std::uint32_t> v;
    for (std::size_t i = 0; i < s.size(); i += depth / 8)
        v.push_back(depth == 16 ? (std::uint32_t(s[i]) << 8) | s[i + 1] : s[i]);
    return v;
}

Bytes randomSamples(std::size_t n, unsigned seed) {
    std::mt19937 rng(seed);
    Bytes s(n);
    for (auto& b : s) // runs of near values too, so Paeth and Average take every branch
        b = static_cast<unsigned char>(rng() % 4 == 0 ? rng() : (rng() % 7) * 37);
    return s;
}

void checkFile(int w, int h, int ch, int depth, bool interlaced) {
    const Bytes s =
        randomSamples(std::size_t(w) * h * ch * depth / 8, unsigned(w * 131 + ch * depth));
    const std::string name = "png_read_" + std::to_string(w) + "x" + std::to_string(h) + "_" +
                             std::to_string(ch) + "ch_" + std::to_string(depth) +
                             (interlaced ? "_adam7" : "") + ".png";
    const std::string path = writePng(name, w, h, ch, depth, s, interlaced);
    const auto ours = readOurs(path);
    const auto oiio = readOiio(path, depth);
    const auto expected = truth(s, depth);
    ASSERT_EQ(oiio, expected) << name << ": OIIO does not read the test's file as written";
    ASSERT_EQ(ours.size(), oiio.size()) << name;
    for (std::size_t i = 0; i < ours.size(); ++i)
        ASSERT_EQ(ours[i], oiio[i]) << name << ": sample " << i << " (pixel " << i / ch << ")";
}

} // namespace

// Every colour type without a palette, 8 and 16 bits (1 to 8 bytes per pixel), every filter type.
TEST(PngRead, EveryFilterAndLayoutMatchesOiio) {
    for (int depth : {8, 16})
        for (int ch : {1, 2, 3, 4}) {
            checkFile(61, 17, ch, depth, false);
            checkFile(1, 9, ch, depth, false); // one pixel a row: only the first-pixel cases
        }
}

// Interlaced files take libpng's path; the same samples.
TEST(PngRead, InterlacedMatchesOiio) {
    for (int depth : {8, 16})
        for (int ch : {1, 3, 4})
            checkFile(37, 21, ch, depth, true);
}

// A damaged file is refused with libpng's message, as before the fast path: an IDAT CRC error
// and a file cut inside its data.
TEST(PngRead, DamagedFilesKeepLibpngsMessages) {
    const Bytes s = randomSamples(40 * 30 * 3, 7);
    const std::string path = writePng("png_read_damaged.png", 40, 30, 3, 8, s, false);
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    const auto readAll = [](const std::string& p) {
        auto src = lut::formats::openImageSource(p);
        Bytes buf(lut::formats::rowBytes(src->info()) *
                  static_cast<std::size_t>(src->info().height));
        src->readRows(0, src->info().height, buf.data());
        src->finish();
    };
    const std::string bad = lut::test::tempDir() + "/png_read_crc.png";
    std::string crc = bytes;
    const std::size_t idatLength =
        (std::size_t(std::uint8_t(bytes[33])) << 8 | std::uint8_t(bytes[34])) << 16 |
        std::size_t(std::uint8_t(bytes[35])) << 8 | std::uint8_t(bytes[36]);
    crc[33 + 8 + idatLength] ^= 0x55; // the first IDAT's CRC
    std::ofstream(bad, std::ios::binary) << crc;
    try {
        readAll(bad);
        FAIL() << "a CRC error was not reported";
    } catch (const lut::Error& e) {
        EXPECT_NE(std::string(e.what()).find("png_read_crc.png: cannot read PNG: IDAT: CRC error"),
                  std::string::npos)
            << e.what();
    }
    const std::string cut = lut::test::tempDir() + "/png_read_cut.png";
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() - 40);
    EXPECT_THROW(readAll(cut), lut::Error);
}

namespace {

// The chunks of a PNG file's bytes: {type, data}.
std::vector<std::pair<std::string, Bytes>> chunksOf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const Bytes b((std::istreambuf_iterator<char>(in)), {});
    std::vector<std::pair<std::string, Bytes>> v;
    for (std::size_t at = 8; at + 12 <= b.size();) {
        const std::size_t len = std::size_t(b[at]) << 24 | std::size_t(b[at + 1]) << 16 |
                                std::size_t(b[at + 2]) << 8 | b[at + 3];
        v.emplace_back(std::string(b.begin() + long(at) + 4, b.begin() + long(at) + 8),
                       Bytes(b.begin() + long(at) + 8, b.begin() + long(at + 8 + len)));
        at += 12 + len;
    }
    return v;
}

std::string writeChunks(const std::string& path,
                        const std::vector<std::pair<std::string, Bytes>>& chunks) {
    Bytes png{137, 'P', 'N', 'G', 13, 10, 26, 10};
    for (const auto& [type, data] : chunks)
        chunk(png, type.c_str(), data);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    return path;
}

// Our reader, `rows` rows per call (the fast path streams: a fault can show after rows were given).
Bytes readInStrips(const std::string& path, int rows) {
    auto src = lut::formats::openImageSource(path);
    const std::size_t rb = lut::formats::rowBytes(src->info());
    Bytes buf(rb * static_cast<std::size_t>(src->info().height));
    for (int y = 0; y < src->info().height; y += rows)
        src->readRows(y, std::min(src->info().height, y + rows),
                      buf.data() + rb * static_cast<std::size_t>(y));
    src->finish();
    return buf;
}

} // namespace

TEST(PngRead, AFaultAfterRowsWereGivenIsLibpngsToJudge) {
    // The fast path inflates as rows are asked for, so it can meet a fault after it gave rows:
    // libpng then reads the file from its start (the given rows again, dropped) and judges it as
    // it judged the whole file before. A CRC error in the second IDAT is libpng's error; bytes
    // after the zlib stream's end, which libpng reads past, give libpng's (and OIIO's) samples.
    const int w = 300, h = 200;
    const Bytes s = randomSamples(std::size_t(w) * h * 3, 19);
    // tempDir() empties the test's folder (writePng calls it): our files go to a sibling.
    const std::string written = writePng("png_read_two_idat.png", w, h, 3, 8, s, false);
    const std::string dir = written.substr(0, written.rfind('/')) + ".work";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string good = dir + "/two_idat.png";
    std::filesystem::copy_file(written, good);
    const std::vector<std::uint32_t> want = truth(s, 8);
    ASSERT_EQ(readOiio(good, 8), want);
    for (int rows : {1, 7, h}) {
        const Bytes got = readInStrips(good, rows);
        EXPECT_EQ(std::vector<std::uint32_t>(got.begin(), got.end()), want) << rows;
    }

    auto chunks = chunksOf(good);
    ASSERT_EQ(chunks.size(), 4u); // IHDR, IDAT, IDAT, IEND
    {
        const std::string path = dir + "/png_read_crc2.png";
        {
            std::ifstream in(good, std::ios::binary);
            std::string bytes((std::istreambuf_iterator<char>(in)), {});
            ASSERT_GT(bytes.size(), 100u);
            bytes[bytes.size() - 12 - 1] ^= 0x33; // the second IDAT's CRC (IEND is the last 12)
            std::ofstream(path, std::ios::binary) << bytes;
        }
        try {
            readInStrips(path, 1);
            FAIL() << "a CRC error in the second IDAT was not reported";
        } catch (const lut::Error& e) {
            EXPECT_NE(std::string(e.what()).find("png_read_crc2.png: cannot read PNG: IDAT: CRC "
                                                 "error"),
                      std::string::npos)
                << e.what();
        }
    }
    {
        auto extra = chunks;
        extra[2].second.insert(extra[2].second.end(), {0, 1, 2, 3, 'x', 'y'});
        const std::string path = writeChunks(dir + "/png_read_extra.png", extra);
        ASSERT_EQ(readOiio(path, 8), want) << "libpng reads past the stream's end";
        for (int rows : {1, 13, h}) {
            const Bytes got = readInStrips(path, rows);
            EXPECT_EQ(std::vector<std::uint32_t>(got.begin(), got.end()), want) << rows;
        }
    }
}
