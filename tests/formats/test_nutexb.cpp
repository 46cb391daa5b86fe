// SPDX-License-Identifier: Apache-2.0
// nutexb: byte-exact writing (reference SHA-256 and bytes built here from nutexb.md's formulas,
// never from our own writer), reading tiled/linear/sRGB files built by an independent script
// (tests/data/nutexb/make_corpus.py), options, and exact 8-bit round trips.
#include "lut/formats/Nutexb.h"
#include "lut/formats/Registry.h"
#include "nutexb/BlockLinear.h"
#include "nutexb/NutexbCodec.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <fstream>
#include <sstream>

namespace nx = lut::formats::nutexb;
using lut::test::dataPath;
using lut::test::tempDir;

namespace {

// A plain FIPS 180-4 SHA-256, the oracle for the reference hash.
std::string sha256Hex(const std::string& msg) {
    static const std::uint32_t k[64] = {
        0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4,
        0xab1c5ed5, 0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe,
        0x9bdc06a7, 0xc19bf174, 0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f,
        0x4a7484aa, 0x5cb0a9dc, 0x76f988da, 0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7,
        0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967, 0x27b70a85, 0x2e1b2138, 0x4d2c6dfc,
        0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85, 0xa2bfe8a1, 0xa81a664b,
        0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070, 0x19a4c116,
        0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
        0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7,
        0xc67178f2};
    std::uint32_t h[8] = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                          0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
    std::string m = msg;
    const std::uint64_t bits = static_cast<std::uint64_t>(msg.size()) * 8;
    m.push_back(static_cast<char>(0x80));
    while (m.size() % 64 != 56)
        m.push_back('\0');
    for (int i = 7; i >= 0; --i)
        m.push_back(static_cast<char>((bits >> (8 * i)) & 0xFF));
    auto rotr = [](std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); };
    for (std::size_t off = 0; off < m.size(); off += 64) {
        std::uint32_t w[64];
        for (int i = 0; i < 16; ++i)
            w[i] =
                (static_cast<std::uint32_t>(static_cast<unsigned char>(m[off + 4 * i])) << 24) |
                (static_cast<std::uint32_t>(static_cast<unsigned char>(m[off + 4 * i + 1])) << 16) |
                (static_cast<std::uint32_t>(static_cast<unsigned char>(m[off + 4 * i + 2])) << 8) |
                static_cast<std::uint32_t>(static_cast<unsigned char>(m[off + 4 * i + 3]));
        for (int i = 16; i < 64; ++i) {
            const std::uint32_t s0 = rotr(w[i - 15], 7) ^ rotr(w[i - 15], 18) ^ (w[i - 15] >> 3);
            const std::uint32_t s1 = rotr(w[i - 2], 17) ^ rotr(w[i - 2], 19) ^ (w[i - 2] >> 10);
            w[i] = w[i - 16] + s0 + w[i - 7] + s1;
        }
        std::uint32_t a = h[0], b = h[1], c = h[2], d = h[3], e = h[4], f = h[5], g = h[6],
                      hh = h[7];
        for (int i = 0; i < 64; ++i) {
            const std::uint32_t t1 =
                hh + (rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25)) + ((e & f) ^ (~e & g)) + k[i] + w[i];
            const std::uint32_t t2 =
                (rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22)) + ((a & b) ^ (a & c) ^ (b & c));
            hh = g;
            g = f;
            f = e;
            e = d + t1;
            d = c;
            c = b;
            b = a;
            a = t1 + t2;
        }
        h[0] += a;
        h[1] += b;
        h[2] += c;
        h[3] += d;
        h[4] += e;
        h[5] += f;
        h[6] += g;
        h[7] += hh;
    }
    char out[65];
    for (int i = 0; i < 8; ++i)
        std::snprintf(out + 8 * i, 9, "%08x", h[i]);
    return std::string(out, 64);
}

using lut::test::fileBytes;

void put32(std::string& s, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        s[at + i] = static_cast<char>((v >> (8 * i)) & 0xFF);
}

// The neutral 16^3 file from nutexb.md alone: the 16^3 closed-form offset, the mip table, the
// footer table.
std::string referenceNeutral16() {
    std::string s(16560, '\0');
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                const int off = 8192 * (g >> 3) + 512 * b + 256 * (r >> 3) + 64 * ((g >> 1) & 3) +
                                32 * ((r >> 2) & 1) + 16 * (g & 1) + 4 * (r & 3);
                s[off] = static_cast<char>(17 * r);
                s[off + 1] = static_cast<char>(17 * g);
                s[off + 2] = static_cast<char>(17 * b);
                s[off + 3] = static_cast<char>(255);
            }
    put32(s, 16384, 16384);
    const std::size_t F = 16384 + 0x40;
    std::memcpy(&s[F], " XNT", 4);
    std::memcpy(&s[F + 4], "color_grading_lut", 17);
    put32(s, F + 0x44, 16);
    put32(s, F + 0x48, 16);
    put32(s, F + 0x4C, 16);
    put32(s, F + 0x50, 0x400);
    put32(s, F + 0x54, 8);
    put32(s, F + 0x58, 1);
    put32(s, F + 0x5C, 0x1000);
    put32(s, F + 0x60, 1);
    put32(s, F + 0x64, 16384);
    std::memcpy(&s[F + 0x68], " XET", 4);
    s[F + 0x6C] = 1;
    s[F + 0x6E] = 2;
    return s;
}

// The graded pattern of make_corpus.py.
std::array<int, 3> graded(int x, int y, int z) {
    return {(x * 37 + y * 11 + z * 5) % 256, (x * 3 + y * 71 + z * 13) % 256,
            (x * 7 + y * 17 + z * 101) % 256};
}

const char* kReferenceSha = "0320481c091b10c63b605ce1045e66d15fcc0b568ca99d91400bb566f816f272";

} // namespace

TEST(Sha256, KnownVectors) {
    EXPECT_EQ(sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    EXPECT_EQ(sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(Nutexb, SpecBuiltNeutralHasReferenceHash) {
    EXPECT_EQ(sha256Hex(referenceNeutral16()), kReferenceSha);
    EXPECT_EQ(fileBytes(dataPath("nutexb/neutral16.nutexb")), referenceNeutral16());
}

TEST(Nutexb, WriterNeutral16IsByteIdenticalToReference) {
    const std::string bytes = nx::writeBytes(lut::Lut3D::identity(16), "", true);
    ASSERT_EQ(bytes.size(), 16560u);
    EXPECT_EQ(bytes, referenceNeutral16());
    EXPECT_EQ(sha256Hex(bytes), kReferenceSha);
}

TEST(Nutexb, RegisteredFormatWritesReferenceFileByDefault) {
    const std::string out = tempDir() + "/color_grading_lut.nutexb";
    lut::LutFile f;
    f.cube = lut::Lut3D::identity(33); // resampled to the default 16^3
    const auto diags = lut::formats::writeLut(out, f);
    EXPECT_EQ(sha256Hex(fileBytes(out)), kReferenceSha);
    bool saysResampled = false;
    for (const auto& d : diags)
        saysResampled |= d.message.find("33^3 -> 16^3") != std::string::npos;
    EXPECT_TRUE(saysResampled);
}

TEST(Nutexb, ReadsReferenceAsExactNeutral) {
    const lut::LutFile f = lut::formats::readLut(dataPath("nutexb/neutral16.nutexb"));
    ASSERT_TRUE(f.cube);
    EXPECT_EQ(f.format, "nutexb");
    EXPECT_EQ(f.dialect, "tiled");
    EXPECT_EQ(f.sourceBitDepth, 8);
    EXPECT_EQ(f.cube->size(), 16);
    EXPECT_EQ(f.cube->title(), "color_grading_lut");
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                const glm::vec3 v = f.cube->at(r, g, b);
                ASSERT_EQ(v.x, static_cast<float>(17 * r) / 255.0f);
                ASSERT_EQ(v.y, static_cast<float>(17 * g) / 255.0f);
                ASSERT_EQ(v.z, static_cast<float>(17 * b) / 255.0f);
            }
    EXPECT_TRUE(f.diagnostics.empty());
}

TEST(Nutexb, ReadsTiledLinearAndSrgbFromIndependentBuilder) {
    for (const char* name : {"graded4_tiled", "graded4_linear", "graded4_srgb"}) {
        SCOPED_TRACE(name);
        const lut::LutFile f =
            lut::formats::readLut(dataPath(std::string("nutexb/") + name + ".nutexb"));
        ASSERT_TRUE(f.cube);
        ASSERT_EQ(f.cube->size(), 4);
        EXPECT_EQ(f.dialect, std::string(name) == "graded4_linear" ? "linear" : "tiled");
        for (int z = 0; z < 4; ++z)
            for (int y = 0; y < 4; ++y)
                for (int x = 0; x < 4; ++x) {
                    const auto e = graded(x, y, z);
                    const glm::vec3 v = f.cube->at(x, y, z);
                    ASSERT_EQ(v.x, static_cast<float>(e[0]) / 255.0f);
                    ASSERT_EQ(v.y, static_cast<float>(e[1]) / 255.0f);
                    ASSERT_EQ(v.z, static_cast<float>(e[2]) / 255.0f);
                }
    }
}

TEST(Nutexb, WritesLinearTiledAndNameLikeTheIndependentBuilder) {
    lut::Lut3D lut(4);
    for (int z = 0; z < 4; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
                const auto e = graded(x, y, z);
                lut.at(x, y, z) = glm::vec3(e[0] / 255.0f, e[1] / 255.0f, e[2] / 255.0f);
            }
    EXPECT_EQ(nx::writeBytes(lut, "", true), fileBytes(dataPath("nutexb/graded4_tiled.nutexb")));
    EXPECT_EQ(nx::writeBytes(lut, "", false), fileBytes(dataPath("nutexb/graded4_linear.nutexb")));

    const std::string named = nx::writeBytes(lut, "my_stage_lut", true);
    const nx::Header h = nx::parseHeader(named, "mem");
    EXPECT_EQ(h.name, "my_stage_lut");
    EXPECT_THROW(nx::writeBytes(lut, std::string(64, 'a'), true), lut::Error);
    EXPECT_NO_THROW(nx::writeBytes(lut, std::string(63, 'a'), true));
}

TEST(Nutexb, OtherSizesHaveTheDocumentedLength) {
    EXPECT_EQ(nx::writeBytes(lut::Lut3D::identity(32), "", true).size(), 131072u + 0xB0);
    EXPECT_EQ(nx::writeBytes(lut::Lut3D::identity(8), "", true).size(), 4096u + 0xB0);
    EXPECT_EQ(nx::writeBytes(lut::Lut3D::identity(33), "", true).size(), 368640u + 0xB0);
    EXPECT_EQ(nx::writeBytes(lut::Lut3D::identity(33), "", false).size(), 33u * 33 * 33 * 4 + 0xB0);
    // Padding of the 8^3 volume is zero: only 2048 of 4096 data bytes carry texels (alpha 255).
    const std::string b8 = nx::writeBytes(lut::Lut3D::identity(8), "", true);
    int alpha = 0;
    for (std::size_t i = 0; i < 4096; ++i)
        alpha += static_cast<unsigned char>(b8[i]) == 255;
    EXPECT_GE(alpha, 512);
    std::size_t nonzeroPad = 0;
    const auto g = nx::tileGeometry(8, 8, 8, 4);
    std::vector<bool> used(4096, false);
    for (int z = 0; z < 8; ++z)
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x)
                for (int k = 0; k < 4; ++k)
                    used[nx::tiledOffset(g, x, y, z) + k] = true;
    for (std::size_t i = 0; i < 4096; ++i)
        if (!used[i] && b8[i] != 0)
            ++nonzeroPad;
    EXPECT_EQ(nonzeroPad, 0u);
}

TEST(Nutexb, SizeOptionLinearOptionAndRoundTripAnySize) {
    const std::string dir = tempDir();
    for (int n : {2, 5, 16, 17, 33}) {
        for (bool tiled : {true, false}) {
            SCOPED_TRACE(std::to_string(n) + (tiled ? " tiled" : " linear"));
            lut::Lut3D lut(n);
            for (std::size_t i = 0; i < lut.entryCount(); ++i)
                lut.entries()[i] = glm::vec3(static_cast<float>((i * 13) % 256) / 255.0f,
                                             static_cast<float>((i * 101 + 7) % 256) / 255.0f,
                                             static_cast<float>((i * 59 + 3) % 256) / 255.0f);
            lut::LutFile f;
            f.cube = lut;
            lut::FormatOptions o;
            o.size = n;
            o.setAttribute(lut::formats::nutexb::kTilingAttribute,
                           tiled ? "block-linear" : "linear");
            const std::string path =
                dir + "/x" + std::to_string(n) + (tiled ? "t" : "l") + ".nutexb";
            lut::formats::writeLut(path, f, o);
            const lut::LutFile back = lut::formats::readLut(path);
            ASSERT_TRUE(back.cube);
            ASSERT_EQ(back.cube->size(), n);
            EXPECT_EQ(back.dialect, tiled ? "tiled" : "linear");
            EXPECT_EQ(back.cube->entries(), lut.entries()); // bit-exact: v = byte/255 both ways
        }
    }
}

TEST(Nutexb, ClampsOutOfRangeAndSaysHowMany) {
    lut::Lut3D lut = lut::Lut3D::identity(16);
    lut.at(0, 0, 0) = glm::vec3(-0.5f, 2.0f, std::numeric_limits<float>::quiet_NaN());
    lut.at(1, 0, 0).x = 1e30f;
    lut::LutFile f;
    f.cube = lut;
    const std::string path = tempDir() + "/clamp.nutexb";
    const auto diags = lut::formats::writeLut(path, f);
    bool found = false;
    for (const auto& d : diags)
        found |= d.message.find("4 channel values outside 0..1") != std::string::npos;
    EXPECT_TRUE(found);
    bool quantised = false;
    for (const auto& d : diags)
        quantised |= d.message.find("quantised to 8 bits") != std::string::npos;
    EXPECT_FALSE(quantised) << "in-range values are exact 8-bit steps here";
    const lut::LutFile back = lut::formats::readLut(path);
    EXPECT_EQ(back.cube->at(0, 0, 0), glm::vec3(0.0f, 1.0f, 0.0f));
    // A value between steps is reported as quantised; bit depth and dither requests are refused
    // with a warning (the format is 8-bit, rounded to nearest).
    lut.at(2, 0, 0) = glm::vec3(0.5f);
    f.cube = lut;
    lut::FormatOptions o;
    o.bitDepth = 16;
    o.dither = true;
    const auto d2 = lut::formats::writeLut(path, f, o);
    int hits = 0;
    for (const auto& d : d2)
        hits += d.message.find("quantised to 8 bits") != std::string::npos ||
                d.message.find("bit depth 16 ignored") != std::string::npos ||
                d.message.find("dither ignored") != std::string::npos;
    EXPECT_EQ(hits, 3);
    EXPECT_EQ(back.cube->at(1, 0, 0).x, 1.0f);
}

TEST(Nutexb, AlphaIgnoredWithDiagnostic) {
    std::string bytes = nx::writeBytes(lut::Lut3D::identity(4), "", false);
    bytes[3] = 0; // alpha of texel (0,0,0)
    bytes[7] = static_cast<char>(128);
    const lut::LutFile f = nx::readBytes(bytes, "mem.nutexb");
    EXPECT_EQ(f.cube->at(0, 0, 0), glm::vec3(0.0f));
    bool found = false;
    for (const auto& d : f.diagnostics)
        found |= d.message.find("2 texels have alpha") != std::string::npos;
    EXPECT_TRUE(found);
}

TEST(Nutexb, RegistryHooksAndNames) {
    lut::formats::registerBuiltinFormats();
    const auto& reg = lut::FormatRegistry::instance();
    const lut::Format* n = reg.byName("nutexb");
    ASSERT_NE(n, nullptr);
    EXPECT_EQ(n->fixedSize(), 16);
    EXPECT_EQ(n->storedBitDepth(), 8);
    const auto byExt = reg.forExtension("x/color_grading_lut.NUTEXB");
    ASSERT_EQ(byExt.size(), 1u);
    EXPECT_EQ(byExt.front(), n);
    ASSERT_NE(reg.byName("strip"), nullptr);
    ASSERT_NE(reg.byName("hald"), nullptr);
    EXPECT_EQ(reg.forExtension("a.png").front(), reg.byName("strip"));
}
