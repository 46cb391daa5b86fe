// SPDX-License-Identifier: Apache-2.0
// Hostile and broken images (issue 29), through the built lutkit: tiled files read by tiles and
// written tiled, a codec's error after a read is an error naming the file, memory bounded by
// what the file holds (checked on its header before anything is allocated, in every command),
// every part of a multi-part file kept or refused naming --subimage. Files are made by oiiotool
// or byte by byte here; pixels are checked against OpenImageIO's own reading of the input through
// a LUT whose result is a formula (1 - x).
#include "HostileSupport.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

using namespace lut::robust;
using ::testing::HasSubstr;
using ::testing::StartsWith;

namespace {

// --- Tiles ----------------------------------------------------------------------------------

// OpenImageIO 2.4's read_scanlines() divides by zero on a tiled file: apply died with SIGFPE
// (exit 136). Tiles are read as tiles, partial ones at the edges included, and kept.
TEST(HostileImages, TiledOpenExrIsReadByTilesAndWrittenWithItsTiles) {
    const std::string dir = lut::test::tempDir();
    oiiotool("--pattern fill:topleft=0.1,0.2,0.3:topright=0.9,0.5,0.1:bottomleft=0,1,0.5:"
             "bottomright=0.7,0.7,0.7 80x56 3 -d half --tile 32 32 --compression zip -o " +
             shellQuoted(dir + "/tiled.exr"));
    const auto r =
        lut::test::runCli("apply --lut " + shellQuoted(invertCube(dir)) + " " +
                          shellQuoted(dir + "/tiled.exr") + " -o " + shellQuoted(dir + "/out.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const OiioImage in = oiioRead(dir + "/tiled.exr"), out = oiioRead(dir + "/out.exr");
    EXPECT_EQ(out.tileWidth, 32);
    EXPECT_EQ(out.tileHeight, 32);
    EXPECT_LT(worstInverted(in, out), 1e-3); // half: 11 bits
}

// A LUT strip stored in tiles (oiiotool from a neutral strip written here from the layout's
// formula): `info` read it with read_scanlines() and died with SIGFPE.
TEST(HostileImages, TiledTiffLutStripIsRead) {
    const std::string dir = lut::test::tempDir();
    std::string ppm = "P6\n256 16\n255\n";
    for (int g = 0; g < 16; ++g)
        for (int x = 0; x < 256; ++x) // unreal layout: x = r + 16 b, y = g
            for (int v : {x % 16, g, x / 16})
                ppm += static_cast<char>(static_cast<int>(std::lround(v * 255.0 / 15.0)));
    writeBytes(dir + "/strip.ppm", ppm);
    oiiotool(shellQuoted(dir + "/strip.ppm") + " --tile 16 16 -o " +
             shellQuoted(dir + "/strip.tif"));
    ASSERT_EQ(oiioRead(dir + "/strip.tif").tileWidth, 16);
    const auto r = lut::test::runCli("info " + shellQuoted(dir + "/strip.tif") + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("\"neutral\": \"exact\""));
}

// Maya IFF is always tiled (64x64): the same SIGFPE.
TEST(HostileImages, IffImageIsReadByTiles) {
    const std::string dir = lut::test::tempDir();
    oiiotool("--pattern fill:top=0.2,0.4,0.6:bottom=0.9,0.1,0.3 100x70 3 -d uint8 -o " +
             shellQuoted(dir + "/in.iff"));
    const auto r =
        lut::test::runCli("apply --lut " + shellQuoted(invertCube(dir)) + " " +
                          shellQuoted(dir + "/in.iff") + " -o " + shellQuoted(dir + "/out.tif"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_LT(worstInverted(oiioRead(dir + "/in.iff"), oiioRead(dir + "/out.tif")),
              0.5 / 255.0 + 1e-6);
}

// --- Missing pixels are errors ----------------------------------------------------------------

// A compressed TIFF cut short (an interrupted copy): the strips it still lists fail to decode,
// which libtiff reports through OpenImageIO's error state while read_scanlines() returns true.
// It was graded and written with its missing rows black, exit 0. It is refused before decoding
// now, naming the first strip the end of the file cuts: handed to OpenImageIO, such a strip was
// inflated together with whatever memory followed the bytes read (valgrind: zlib's inflate on
// uninitialised bytes; under the fuzzer, a corrupted heap).
TEST(HostileImages, CompressedTiffCutShortIsAnErrorAndNothingIsWritten) {
    const std::string dir = lut::test::tempDir();
    oiiotool("--pattern fill:top=0.2,0.4,0.6:bottom=0.9,0.1,0.3 256x256 3 -d uint8 "
             "--compression zip -o " +
             shellQuoted(dir + "/full.tif"));
    const std::string full = fileBytes(dir + "/full.tif");
    ASSERT_EQ(full.substr(0, 8), std::string("II*\0\x08\0\0\0", 8)); // directory first
    writeBytes(dir + "/cut.tif", full.substr(0, full.size() * 6 / 10));
    const auto r =
        lut::test::runCli("apply --lut " + shellQuoted(invertCube(dir)) + " " +
                          shellQuoted(dir + "/cut.tif") + " -o " + shellQuoted(dir + "/out.tif"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(stripDir(r.err, dir), StartsWith("lutkit: error: cut.tif: TIFF strip "));
    EXPECT_THAT(r.err,
                HasSubstr(") runs past the end of the file (" +
                          std::to_string(full.size() * 6 / 10) + " bytes): truncated or corrupt"));
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.tif"));
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"cut.tif", "full.tif", "invert.cube"}));
}

// Uncompressed, the same cut is seen in the header: the strips' bytes are not in the file.
TEST(HostileImages, UncompressedTiffCutShortIsRefusedBeforeDecoding) {
    const std::string dir = lut::test::tempDir();
    oiiotool("--pattern constant:color=0.5,0.5,0.5 64x64 3 -d uint8 --compression none -o " +
             shellQuoted(dir + "/full.tif"));
    const std::string full = fileBytes(dir + "/full.tif");
    writeBytes(dir + "/cut.tif", full.substr(0, full.size() / 2));
    const auto r =
        lut::test::runCli("apply --lut " + shellQuoted(invertCube(dir)) + " " +
                          shellQuoted(dir + "/cut.tif") + " -o " + shellQuoted(dir + "/out.tif"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(stripDir(r.err, dir),
                HasSubstr("cut.tif: declares 64x64 pixels (12288 bytes as stored) in "));
    EXPECT_THAT(r.err, HasSubstr("more than uncompressed data can hold (at most 1:1): "
                                 "truncated or corrupt"));
}

// A 16-bit LUT strip whose second half is missing read as a black LUT that `info` and `convert`
// accepted.
TEST(HostileImages, Truncated16BitTiffLutStripIsRefused) {
    const std::string dir = lut::test::tempDir();
    oiiotool("--pattern fill:left=0,0,0:right=1,1,1 256x16 3 -d uint16 --compression zip -o " +
             shellQuoted(dir + "/strip.tif"));
    const std::string full = fileBytes(dir + "/strip.tif");
    writeBytes(dir + "/cut.tif", full.substr(0, full.size() / 2));
    for (const std::string cmd : {"info", "convert"}) {
        const auto r =
            lut::test::runCli(cmd + " " + shellQuoted(dir + "/cut.tif") +
                              (cmd == "convert" ? " " + shellQuoted(dir + "/out.cube") : ""));
        EXPECT_EQ(r.exitCode, 1) << cmd;
        EXPECT_THAT(stripDir(r.err, dir), HasSubstr("cut.tif: ")) << cmd;
    }
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.cube"));
}

// A JPEG's frame header patched to claim more pixels than its data holds: libjpeg fills the rest
// with grey and only warns ("premature end of data segment"); it was written out, exit 0.
TEST(HostileImages, JpegClaimingMorePixelsThanItHoldsIsRefused) {
    const std::string dir = lut::test::tempDir();
    oiiotool("--pattern fill:top=0.2,0.4,0.6:bottom=0.9,0.1,0.3 64x64 3 -d uint8 -o " +
             shellQuoted(dir + "/small.jpg"));
    const std::string jpg = fileBytes(dir + "/small.jpg");
    std::size_t sof = 2;
    while (sof + 4 < jpg.size() && static_cast<unsigned char>(jpg[sof + 1]) != 0xC0)
        sof += 2 + (static_cast<unsigned char>(jpg[sof + 2]) << 8 |
                    static_cast<unsigned char>(jpg[sof + 3]));
    ASSERT_LT(sof + 9, jpg.size()) << "no baseline frame header";
    auto claim = [&](int w, int h, const std::string& name) {
        std::string s = jpg;
        s[sof + 5] = char(h >> 8), s[sof + 6] = char(h), s[sof + 7] = char(w >> 8);
        s[sof + 8] = char(w);
        writeBytes(dir + "/" + name, s);
    };
    claim(4000, 4000, "claims4000.jpg"); // beyond what its bytes can hold: the header says so
    claim(128, 128, "claims128.jpg");    // plausible: libjpeg's warning says so
    for (const std::string name : {"claims4000.jpg", "claims128.jpg"}) {
        const auto r = lut::test::runCli("apply --lut " + shellQuoted(invertCube(dir)) + " " +
                                         shellQuoted(dir + "/" + name) + " -o " +
                                         shellQuoted(dir + "/out.png"));
        EXPECT_EQ(r.exitCode, 1) << name;
        EXPECT_FALSE(std::filesystem::exists(dir + "/out.png")) << name;
        if (name == "claims4000.jpg") {
            EXPECT_THAT(stripDir(r.err, dir),
                        HasSubstr("claims4000.jpg: declares 4000x4000 pixels (48000000 bytes as "
                                  "stored) in "));
        } else {
            EXPECT_THAT(stripDir(r.err, dir),
                        HasSubstr("claims128.jpg: cannot read image data: JPEG error: Corrupt "
                                  "JPEG data: premature end of data segment"));
        }
    }
}

// --- Memory bounded by the file, checked before anything is allocated ------------------------

struct Lying {
    std::string name;
    std::string bytes;
    std::string message; // what the error says after "lutkit: error: NAME: "
};

std::vector<Lying> lyingHeaders() {
    std::vector<Lying> files;
    // TGA (no magic number: named .tga): RLE, 65535x65535, 82 bytes.
    std::string tga =
        std::string("\0\0\x0a", 3) + std::string(9, '\0') + le16(65535) + le16(65535) + "\x20\x08";
    tga.resize(82, '\x7f');
    files.push_back({"big.tga", tga, "image is 65535x65535 with 4 channels, over the limit"});
    // PNG: 16384x16384 RGBA (at the pixel limit) in a 15-byte IDAT, 206 bytes.
    std::string png =
        std::string("\x89PNG\r\n\x1a\n", 8) +
        pngChunk("IHDR", be32(16384) + be32(16384) + std::string("\x08\x06\0\0\0", 5)) +
        pngChunk("tEXt", "Comment" + std::string(1, '\0') + std::string(121, 'x')) +
        pngChunk("IDAT", std::string("\x78\x9c\x63\x60\x00\x00\x00\x02\x00\x01", 10)) +
        pngChunk("IEND", "");
    files.push_back({"claims.png", png,
                     "declares 16384x16384 pixels (1073758208 bytes as stored) "
                     "in 10 bytes of PNG data, more than deflate data can "
                     "hold (at most 1032:1): truncated or corrupt"});
    // Radiance HDR: 1x100000000, 64 bytes (a width of 1 is stored flat, 4 bytes a pixel).
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000000 +X 1\n";
    hdr.resize(64, '\0');
    files.push_back({"tall.hdr", hdr,
                     "declares 1x100000000 pixels (400000000 bytes as stored) in 11 bytes of HDR "
                     "data, more than uncompressed data can hold (at most 1:1)"});
    // TIFF: 2^31 x 2 and 65535x65535 (past the pixel limit), 16000x16000 (within it, not in 16
    // bytes): 168 bytes each, uncompressed, one strip.
    auto tiff = [](std::uint32_t w, std::uint32_t h) {
        const std::uint32_t tags[][4] = {{256, 4, 1, w}, {257, 4, 1, h}, {258, 3, 1, 8},
                                         {259, 3, 1, 1}, {262, 3, 1, 1}, {273, 4, 1, 152},
                                         {277, 3, 1, 1}, {278, 4, 1, h}, {279, 4, 1, 16},
                                         {284, 3, 1, 1}, {296, 3, 1, 1}, {0, 0, 0, 0}};
        std::string s = std::string("II*\0", 4) + le32(8) + le16(11);
        for (int i = 0; i < 11; ++i)
            s += le16(tags[i][0]) + le16(tags[i][1]) + le32(tags[i][2]) + le32(tags[i][3]);
        s += le32(0);
        s.resize(168, '\x7f');
        return s;
    };
    files.push_back({"wide.tif", tiff(2147483648u, 2),
                     "image is 2147483648x2 with 1 channels, over the limit"});
    files.push_back(
        {"square.tif", tiff(65535, 65535), "image is 65535x65535 with 1 channels, over the limit"});
    files.push_back({"mid.tif", tiff(16000, 16000),
                     "declares 16000x16000 pixels (256000000 bytes as stored) in 16 bytes of TIFF "
                     "data, more than uncompressed data can hold (at most 1:1)"});
    // PSD: a 2 GB colour mode block in a 62-byte file.
    std::string psd = std::string("8BPS\0\x01", 6) + std::string(6, '\0') +
                      std::string("\0\x03", 2) + be32(2) + be32(2) +
                      std::string("\0\x08\0\x03", 4) + be32(0x7fffffff);
    psd.resize(62, '\0');
    files.push_back({"huge.psd", psd,
                     "PSD colour mode data declares 2147483647 bytes, but only 32 follow in the "
                     "file (truncated or corrupt)"});
    // DPX (little-endian, one 16x12 16-bit RGB element at byte 2048, which OpenImageIO reads)
    // whose user data size says 2 GB: OpenImageIO allocated it whole when it opened the file
    // (14 GB peak, 71 s; 4 GB aborted on an assertion; found by fuzz_image_apply in CI); and a
    // run-length encoded element 268435456 pixels wide, which OpenImageIO cannot decode but sized
    // a row buffer for first (384 GB asked for).
    auto dpx = [](std::uint32_t user, std::uint32_t w, std::uint32_t h, unsigned encoding) {
        std::string s(2048 + 1152, '\0');
        auto put = [&](std::size_t at, const std::string& v) { s.replace(at, v.size(), v); };
        put(0, "XPDS");
        put(4, le32(2048));
        put(8, "V2.0");
        put(16, le32(static_cast<std::uint32_t>(s.size())));
        put(24, le32(1664) + le32(384) + le32(user));
        put(768, le16(0) + le16(1) + le32(w) + le32(h));
        s[800] = 50; // RGB
        s[803] = 16; // bits
        put(804, le16(0) + le16(encoding) + le32(2048));
        return s;
    };
    files.push_back({"userdata.dpx", dpx(0x7ffffff0u, 16, 12, 0),
                     "DPX user data (its size at byte 32) declares 2147483632 bytes, but only "
                     "1152 follow in the file (truncated or corrupt)"});
    files.push_back({"rle.dpx", dpx(0, 1u << 28, 1, 1),
                     "DPX image element 1 is run-length encoded, which OpenImageIO's DPX reader "
                     "does not decode"});
    // PNM: a binary 16000x16000 RGB header followed by 3 bytes (the native reader's scanline
    // buffer and preview's frame were sized from it).
    files.push_back({"big.ppm", std::string("P6\n16000 16000\n255\nabc"),
                     "declares 16000x16000 pixels (768000000 bytes as stored) in 3 bytes of PNM "
                     "data, more than uncompressed data can hold (at most 1:1)"});
    // GIF whose version is garbage ("GIF8\x7f\x05": giflib checks "GIF" only) and whose screen is
    // 32639x14718: the scanner took it for no GIF, OpenImageIO allocated a 1.9 GB canvas (found
    // by fuzz_image_oiio).
    files.push_back({"version.gif",
                     std::string("GIF8\x7f\x05\x7f\x7f\x7e\x39\x61\x60\xea\x60\xea\0\0\0;", 19),
                     "image is 32639x14718 with 4 channels, over the limit"});
    // PNG: interlaced 16-bit RGBA 8000x8000, its IDAT tiny, the file padded with a private chunk
    // (the old check counted the file's bytes, not the image data's: 2 GB allocated).
    std::string padded =
        std::string("\x89PNG\r\n\x1a\n", 8) +
        pngChunk("IHDR", be32(8000) + be32(8000) + std::string("\x10\x06\0\0\x01", 5)) +
        pngChunk("prIv", std::string(600000, '\0')) +
        pngChunk("IDAT", std::string("\x78\x9c\x63\x60\x00\x00\x00\x02\x00\x01", 10)) +
        pngChunk("IEND", "");
    files.push_back({"padded.png", padded,
                     "declares 8000x8000 pixels (512000000 bytes as stored) in 10 bytes of PNG "
                     "data"});
    return files;
}

// Every command that reads an image refuses each of them with its one line, within a few MiB:
// preview allocated the whole float frame first (an 82-byte TGA: 4.3 GB and 41 s; a 206-byte PNG
// apply refused: 4.2 GB; the HDR: 1.7 GB), TIFF/TGA/HDR/PSD were held to no limit at all through
// OpenImageIO (the 168-byte TIFF climbed past 3.9 GB; the 62-byte PSD took 2.1 GB).
TEST(HostileImages, LyingHeadersAreRefusedByEveryCommandBeforeAllocating) {
    const std::string dir = lut::test::tempDir();
    const std::string lut = invertCube(dir);
    for (const Lying& f : lyingHeaders()) {
        writeBytes(dir + "/" + f.name, f.bytes);
        const std::string p = shellQuoted(dir + "/" + f.name);
        std::vector<std::string> commands = {
            "apply --lut " + shellQuoted(lut) + " " + p + " -o " + shellQuoted(dir + "/out.tif"),
            "preview " + p + " -o " + shellQuoted(dir + "/out.png"),
            "embed " + p + " " + shellQuoted(dir + "/out.png"),
            "extract " + p + " " + shellQuoted(dir + "/o.cube"),
            "fit " + p + " " + p + " " + shellQuoted(dir + "/o.cube")};
        if (f.name.find(".png") != std::string::npos || f.name.find(".tif") != std::string::npos)
            commands.push_back("info " + p); // the LUT image formats
        for (const std::string& args : commands) {
            const Measured m = runMeasured(args, dir);
            SCOPED_TRACE(args);
            EXPECT_EQ(m.run.exitCode, 1);
            EXPECT_THAT(stripDir(m.run.err, dir), HasSubstr(f.name + ": " + f.message));
            if (!kMemorySanitized) {
                EXPECT_LT(m.peakMiB, 64.0);
            }
        }
    }
}

// --max-memory holds across the files a batch runs at once: each reserves what it will hold
// (here OpenImageIO's TGA reader decodes the whole 48 MiB image) before decoding. Two such
// files on two threads under --max-memory 80M run one after the other; they ran together. The
// baseline is the same command on a tiny TGA (OpenImageIO's libraries alone are ~140 MiB).
TEST(HostileImages, MaxMemoryHoldsAcrossFilesDecodedAtOnce) {
    if (kMemorySanitized)
        GTEST_SKIP() << "peak memory is not measurable under a sanitizer";
    const std::string dir = lut::test::tempDir();
    std::filesystem::create_directories(dir + "/in");
    std::filesystem::create_directories(dir + "/tiny");
    for (const char* name : {"a.tga", "b.tga"}) {
        oiiotool("--pattern constant:color=0.2,0.4,0.6,1 4096x3072 4 -d uint8 --compression rle "
                 "-o " +
                 shellQuoted(dir + "/in/" + name));
        oiiotool("--pattern constant:color=0.2,0.4,0.6,1 16x16 4 -d uint8 --compression rle -o " +
                 shellQuoted(dir + "/tiny/" + name));
    }
    const std::string lut = invertCube(dir);
    const Measured base =
        runMeasured("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/tiny") + " -o " +
                        shellQuoted(dir + "/tiny-out/") + " --threads 2 -q",
                    dir);
    ASSERT_EQ(base.run.exitCode, 0) << base.run.err;
    const Measured m =
        runMeasured("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/in") + " -o " +
                        shellQuoted(dir + "/out/") + " --threads 2 --max-memory 80M -q",
                    dir);
    ASSERT_EQ(m.run.exitCode, 0) << m.run.err;
    const double frame = 4096.0 * 3072 * 4 / (1 << 20);
    EXPECT_LT(m.peakMiB, base.peakMiB + 1.5 * frame) << "both frames were held at once";
    EXPECT_LT(worstInverted(oiioRead(dir + "/in/a.tga"), oiioRead(dir + "/out/a.tga")),
              0.5 / 255 + 1e-6);
    std::filesystem::remove_all(dir + "/out"); // 96 MiB of output
    std::filesystem::remove_all(dir + "/in");
}

// --- Several images in one file --------------------------------------------------------------

// A two-part OpenEXR was written with its first part only, exit 0. Every part is graded and kept.
TEST(HostileImages, TwoPartOpenExrKeepsBothParts) {
    const std::string dir = lut::test::tempDir();
    oiiotool("--pattern fill:top=0.1,0.2,0.3:bottom=0.9,0.8,0.7 40x24 3 --pattern "
             "checker:width=4:height=4 40x24 3 --siappend -d half -o " +
             shellQuoted(dir + "/two.exr"));
    ASSERT_EQ(oiioRead(dir + "/two.exr").subimages, 2);
    const std::string lut = invertCube(dir);
    const auto r =
        lut::test::runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/two.exr") +
                          " -o " + shellQuoted(dir + "/out.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_EQ(oiioRead(dir + "/out.exr").subimages, 2);
    for (int part = 0; part < 2; ++part)
        EXPECT_LT(worstInverted(oiioRead(dir + "/two.exr", part), oiioRead(dir + "/out.exr", part)),
                  1e-3)
            << "part " << part;

    // A format that holds one image: refused naming --subimage; with it, that part.
    const auto png =
        lut::test::runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/two.exr") +
                          " -o " + shellQuoted(dir + "/out.png"));
    EXPECT_EQ(png.exitCode, 1);
    EXPECT_EQ(stripDir(png.err, dir),
              "lutkit: error: two.exr: holds 2 images (OpenEXR parts) and out.png's format holds "
              "one: write .exr or .tif to keep every one, or pick one with --subimage N (0 to "
              "1)\n");
    const auto one =
        lut::test::runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/two.exr") +
                          " -o " + shellQuoted(dir + "/one.exr") + " --subimage 1");
    ASSERT_EQ(one.exitCode, 0) << one.err;
    EXPECT_EQ(oiioRead(dir + "/one.exr").subimages, 1);
    EXPECT_LT(worstInverted(oiioRead(dir + "/two.exr", 1), oiioRead(dir + "/one.exr")), 1e-3);

    // preview shows one image: it asks which.
    const auto preview = lut::test::runCli("preview " + shellQuoted(dir + "/two.exr") + " -o " +
                                           shellQuoted(dir + "/p.exr"));
    EXPECT_EQ(preview.exitCode, 1);
    EXPECT_THAT(stripDir(preview.err, dir),
                HasSubstr("two.exr: holds 2 images (OpenEXR parts): pick one with --subimage N "
                          "(0 to 1)"));
}

// Pages of a TIFF and MIP levels of a texture are kept the same way.
TEST(HostileImages, TiffPagesAndMipLevelsAreKept) {
    const std::string dir = lut::test::tempDir();
    oiiotool("--pattern fill:top=0.1,0.2,0.3:bottom=0.9,0.8,0.7 32x16 3 --pattern "
             "checker:width=4:height=4 32x16 3 --siappend -d uint16 -o " +
             shellQuoted(dir + "/pages.tif"));
    oiiotool("--pattern fill:top=0.1,0.2,0.3:bottom=0.9,0.8,0.7 64x32 3 -d half --tile 16 16 "
             "-otex " +
             shellQuoted(dir + "/tex.exr"));
    const std::string lut = invertCube(dir);
    for (const std::string name : {"pages.tif", "tex.exr"}) {
        const std::string out = dir + "/out-" + name;
        const auto r = lut::test::runCli("apply --lut " + shellQuoted(lut) + " " +
                                         shellQuoted(dir + "/" + name) + " -o " + shellQuoted(out));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const OiioImage in = oiioRead(dir + "/" + name);
        const OiioImage got = oiioRead(out);
        EXPECT_EQ(got.subimages, in.subimages) << name;
        EXPECT_EQ(got.mipLevels, in.mipLevels) << name;
        for (int s = 0; s < in.subimages; ++s)
            for (int m = 0; m < in.mipLevels; ++m)
                EXPECT_LT(worstInverted(oiioRead(dir + "/" + name, s, m), oiioRead(out, s, m)),
                          1e-3)
                    << name << " subimage " << s << " level " << m;
    }
}

// --- Standard input -------------------------------------------------------------------------

// `lutkit info - < /dev/zero` read 2 GB before refusing it; an image command now stops after the
// first MiB (no image starts so), info at the largest binary LUT a stream can be (a 256^3
// nutexb).
TEST(HostileImages, StandardInputIsBoundedByWhatItCanBe) {
    const std::string dir = lut::test::tempDir();
    const Measured info = runMeasured("info -", dir, "/dev/zero");
    EXPECT_EQ(info.run.exitCode, 1);
    EXPECT_THAT(info.run.err, HasSubstr("lutkit: error: -: standard input is over the "));
    if (!kMemorySanitized) {
        EXPECT_LT(info.peakMiB, 256.0);
    }
    const Measured apply = runMeasured("apply --lut " + shellQuoted(invertCube(dir)) + " - -o " +
                                           shellQuoted(dir + "/o.png"),
                                       dir, "/dev/zero");
    EXPECT_EQ(apply.run.exitCode, 1);
    EXPECT_THAT(apply.run.err,
                HasSubstr("lutkit: error: -: standard input is not an image lutkit reads"));
    if (!kMemorySanitized) {
        EXPECT_LT(apply.peakMiB, 32.0);
    }
}

} // namespace
