// SPDX-License-Identifier: Apache-2.0
// Format::readMemory / writeMemory: every format reads and writes bytes in memory (standard
// input and output). Every writer encodes in memory; the cube, nutexb, strip and hald formats
// decode in memory too (touching no file), OpenColorIO's reader goes through a private temporary
// file (its FileTransform opens a path); either way the result equals reading the same bytes
// from a file, and messages name the caller's name for the data, never a temporary path.
#include "TestSupport.h"

#include "lut/Error.h"
#include "lut/formats/Registry.h"
#include "lut/io/FormatRegistry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <utility>
#include <vector>

namespace {

using lut::test::fileBytes;

const lut::Format& format(const std::string& name) {
    lut::formats::registerBuiltinFormats();
    const lut::Format* f = lut::FormatRegistry::instance().byName(name);
    EXPECT_NE(f, nullptr) << name;
    return *f;
}

} // namespace

TEST(ReadMemory, EveryWritableFormatRoundTripsThroughMemoryAsThroughAFile) {
    const std::string dir = lut::test::tempDir();
    lut::LutFile src;
    lut::Lut3D cube = lut::Lut3D::identity(4);
    cube.at(1, 2, 3) = {0.25f, 0.5f, 0.75f};
    src.cube = cube;
    // Known entries, so every format has something that could be lost.
    // {writer, reader}: .spi3d is read and written by lutkit (OpenColorIO reads it too).
    const std::pair<const char*, const char*> formats[] = {
        {"cube", "cube"}, {"nutexb", "nutexb"}, {"strip", "strip"}, {"spi3d", "spi3d"}};
    for (const auto& [name, readerName] : formats) {
        const lut::Format& f = format(name);
        const lut::Format& r = format(readerName);
        const std::string ext = f.extensions().front();
        const std::string filePath = dir + "/f" + ext;
        lut::FormatOptions o;
        f.write(filePath, src, o);
        const std::string bytes = f.writeMemory(src, "mem" + ext, o);
        EXPECT_EQ(bytes, fileBytes(filePath)) << name << ": memory and file bytes differ";
        const lut::LutFile a = r.read(filePath, o);
        const lut::LutFile b = r.readMemory(bytes, "mem" + ext, o);
        ASSERT_TRUE(a.cube && b.cube) << name;
        EXPECT_EQ(a.cube->entries(), b.cube->entries()) << name;
    }
}

TEST(ReadMemory, ErrorsNameTheGivenNameNotATemporaryFile) {
    for (const char* name : {"cube", "spi3d", "strip"}) {
        const lut::Format& f = format(name);
        const std::string label = std::string("stdin") + f.extensions().front();
        try {
            (void)f.readMemory("LUT_3D_SIZE 2\n0 0 0\n", label, {});
            FAIL() << name << " accepted garbage";
        } catch (const lut::Error& e) {
            const std::string msg = e.what();
            EXPECT_NE(msg.find(label), std::string::npos) << msg;
            EXPECT_EQ(msg.find("lutkit-"), std::string::npos) << msg;
            EXPECT_EQ(msg.find("/tmp"), std::string::npos) << msg;
        }
    }
}

// The cube and nutexb formats touch no file in memory (the editor's export preview writes and
// reads them back at every adjustment), nor do OpenColorIO's writers: with the temporary folder
// missing they still work.
TEST(ReadMemory, CubeNutexbAndOcioWritersNeedNoTemporaryFolder) {
    lut::LutFile src;
    src.cube = lut::Lut3D::identity(16);
    const std::string missing = lut::test::tempDir() + "/no-such-folder";
    const char* old = std::getenv("TMPDIR");
    const std::string saved = old ? old : "";
    ::setenv("TMPDIR", missing.c_str(), 1);
    for (const char* name : {"cube", "nutexb"}) {
        const lut::Format& f = format(name);
        const std::string label = std::string("mem") + f.extensions().front();
        lut::Diagnostics d;
        std::string bytes;
        EXPECT_NO_THROW(bytes = f.writeMemory(src, label, {}, &d)) << name;
        EXPECT_NO_THROW((void)f.readMemory(bytes, label, {})) << name;
        for (const auto& x : d)
            EXPECT_EQ(x.path, label) << name << ": " << x.message;
    }
    // OpenColorIO's writers, with a shaper where the format keeps one (clf, csp)
    lut::LutFile shaped = src;
    shaped.shaper = lut::Lut1D(64);
    for (int i = 0; i < 64; ++i) {
        const float v = std::pow(i / 63.0f, 0.5f);
        shaped.shaper->entries()[static_cast<std::size_t>(i)] = glm::vec3(v);
    }
    for (const char* name : {"spi3d", "flame", "clf", "csp"}) {
        const lut::Format& f = format(name);
        const std::string label = std::string("mem") + f.extensions().front();
        std::string bytes;
        EXPECT_NO_THROW(bytes = f.writeMemory(shaped, label, {})) << name;
        EXPECT_FALSE(bytes.empty()) << name;
    }
    if (old)
        ::setenv("TMPDIR", saved.c_str(), 1);
    else
        ::unsetenv("TMPDIR");
}

namespace {

// The LUT image outputs: the name's extension picks the image format, bitDepth 16 a 16-bit PNG.
struct ImageOut {
    const char* ext;
    int bits; // 0 = the format's default (8 for PNG and TIFF, float for EXR)
};
constexpr ImageOut kImageOuts[] = {{".png", 0}, {".png", 16}, {".tif", 0}, {".exr", 0}};

// Restores TMPDIR at the end of a scope.
class TmpDirSetting {
public:
    explicit TmpDirSetting(const std::string& value) {
        if (const char* old = std::getenv("TMPDIR"))
            m_saved = old;
        m_had = std::getenv("TMPDIR") != nullptr;
        ::setenv("TMPDIR", value.c_str(), 1);
    }
    ~TmpDirSetting() {
        if (m_had)
            ::setenv("TMPDIR", m_saved.c_str(), 1);
        else
            ::unsetenv("TMPDIR");
    }

private:
    std::string m_saved;
    bool m_had = false;
};

lut::LutFile gradedLut(int n) {
    lut::LutFile src;
    lut::Lut3D cube = lut::Lut3D::identity(n);
    cube.at(1, 2, 3) = {0.25f, 0.5f, 0.75f}; // something a wrong layout or depth would move
    src.cube = cube;
    return src;
}

// The pixels oiiotool reads from a file: (x, y) -> the first four values it prints (integer
// files: the stored codes; float files: the values).
std::map<std::pair<int, int>, std::vector<double>> oiiotoolPixels(const std::string& path) {
    const auto r = lut::test::runCommand("oiiotool --dumpdata " + lut::test::shellQuoted(path));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    std::map<std::pair<int, int>, std::vector<double>> px;
    std::istringstream in(r.out);
    std::string line;
    while (std::getline(in, line)) {
        int x = 0, y = 0, used = 0;
        if (std::sscanf(line.c_str(), " Pixel (%d, %d):%n", &x, &y, &used) != 2)
            continue;
        std::istringstream values(line.substr(static_cast<std::size_t>(used)));
        std::vector<double> v;
        double d = 0.0;
        while (v.size() < 4 && values >> d)
            v.push_back(d);
        px[{x, y}] = v;
    }
    return px;
}

// The bytes with every TIFF/EXIF DateTime value ("2026:12:07 02:15:45", the second the file was
// written) blanked: two writes of the same picture straddling a second differ only there (seen
// under ThreadSanitizer, where a write takes long enough).
std::string withoutWriteTime(std::string b) {
    static const std::regex stamp("[0-9]{4}:[0-9]{2}:[0-9]{2} [0-9]{2}:[0-9]{2}:[0-9]{2}");
    return std::regex_replace(b, stamp, "YYYY:MM:DD hh:mm:ss");
}

} // namespace

// Strip and hald images made in memory are the bytes write() puts in a file, for every output
// kind, and read back in memory as read() reads the file; diagnostics name the given name.
TEST(ReadMemory, LutImagesInMemoryAreTheBytesOfTheirFiles) {
    const std::string dir = lut::test::tempDir();
    const lut::LutFile src = gradedLut(16); // 16^3: a 256x16 strip, a level-4 (64x64) Hald
    for (const char* name : {"strip", "hald"}) {
        const lut::Format& f = format(name);
        for (const auto& out : kImageOuts) {
            const std::string what =
                std::string(name) + " " + out.ext + " " + std::to_string(out.bits);
            lut::FormatOptions o;
            o.bitDepth = out.bits;
            const std::string filePath = dir + "/" + name + std::to_string(out.bits) + out.ext;
            const std::string label = std::string("mem") + out.ext;
            const lut::Diagnostics fileDiags = f.write(filePath, src, o);
            lut::Diagnostics memDiags;
            const std::string bytes = f.writeMemory(src, label, o, &memDiags);
            EXPECT_EQ(withoutWriteTime(bytes), withoutWriteTime(fileBytes(filePath)))
                << what << ": memory and file bytes differ (the write's time aside)";
            ASSERT_EQ(memDiags.size(), fileDiags.size()) << what;
            for (std::size_t i = 0; i < memDiags.size(); ++i) {
                EXPECT_EQ(memDiags[i].path, label) << what;
                EXPECT_EQ(memDiags[i].message, fileDiags[i].message) << what;
            }
            const lut::LutFile a = f.read(filePath, o);
            const lut::LutFile b = f.readMemory(bytes, label, o);
            ASSERT_TRUE(a.cube && b.cube) << what;
            EXPECT_EQ(a.cube->entries(), b.cube->entries()) << what;
            EXPECT_EQ(a.dialect, b.dialect) << what;
            EXPECT_EQ(a.sourceBitDepth, b.sourceBitDepth) << what;
            EXPECT_EQ(a.diagnostics.size(), b.diagnostics.size()) << what;
        }
    }
}

// The editor's "Game engine strip" preview writes and reads a LUT image at every adjustment:
// with the temporary folder missing, strip and hald still read and write in memory (through a
// temporary folder they fail: "cannot create a temporary folder in ...").
TEST(ReadMemory, LutImagesNeedNoTemporaryFolder) {
    const lut::LutFile src = gradedLut(16);
    const TmpDirSetting tmp(lut::test::tempDir() + "/no-such-folder");
    for (const char* name : {"strip", "hald"}) {
        const lut::Format& f = format(name);
        for (const auto& out : kImageOuts) {
            const std::string what = std::string(name) + " " + out.ext;
            const std::string label = std::string("mem") + out.ext;
            lut::FormatOptions o;
            o.bitDepth = out.bits;
            std::string bytes;
            EXPECT_NO_THROW(bytes = f.writeMemory(src, label, o)) << what;
            lut::LutFile back;
            EXPECT_NO_THROW(back = f.readMemory(bytes, label, o)) << what;
            EXPECT_TRUE(back.cube) << what;
        }
    }
}

// A truncated or garbage LUT image read from memory: the error names the given name (never a
// temporary file), for both formats.
TEST(ReadMemory, LutImageErrorsNameTheGivenName) {
    for (const char* name : {"strip", "hald"}) {
        const lut::Format& f = format(name);
        const std::string png = f.writeMemory(gradedLut(16), "x.png", {});
        ASSERT_GT(png.size(), 100u);
        const std::string cases[] = {png.substr(0, png.size() / 2), png.substr(0, 40),
                                     std::string("\x89PNG\r\n\x1a\n", 8) + std::string(64, 'x'),
                                     "not an image at all", std::string()};
        for (const auto& bytes : cases) {
            const std::string label = "clipboard-lut.png";
            try {
                (void)f.readMemory(bytes, label, {});
                ADD_FAILURE() << name << " accepted " << bytes.size() << " bad bytes";
            } catch (const lut::Error& e) {
                const std::string msg = e.what();
                EXPECT_EQ(msg.rfind(label + ": ", 0), 0u) << name << ": " << msg;
                EXPECT_EQ(msg.find("lutkit-"), std::string::npos) << msg;
                EXPECT_EQ(msg.find("/tmp"), std::string::npos) << msg;
            }
        }
    }
}

// The pixels of neutral LUT images made in memory, as oiiotool reads them (the bytes saved to a
// file), against the layouts' formulas in float64: unreal x = r + N*b, y = g; hald i = r + N*g +
// N^2*b at (i mod L^3, i div L^3); value k/(N-1) stored as round(k/(N-1) * (2^bits - 1)) or as a
// float; alpha 1.
TEST(ReadMemory, NeutralLutImagesInMemoryHoldTheLayoutsValuesByOiiotool) {
    if (!lut::test::haveProgram("oiiotool"))
        GTEST_SKIP() << "oiiotool not installed";
    const std::string dir = lut::test::tempDir();
    const int n = 4;
    lut::LutFile neutral;
    neutral.cube = lut::Lut3D::identity(n);
    for (const char* name : {"strip", "hald"}) {
        const bool hald = std::string(name) == "hald";
        const int w = hald ? 8 : n * n, h = hald ? 8 : n;
        for (const auto& out : kImageOuts) {
            lut::FormatOptions o;
            o.bitDepth = out.bits;
            const std::string bytes =
                format(name).writeMemory(neutral, std::string("m") + out.ext, o);
            const std::string path = dir + "/" + name + std::to_string(out.bits) + out.ext;
            std::ofstream(path, std::ios::binary) << bytes;
            const auto px = oiiotoolPixels(path);
            ASSERT_EQ(px.size(), static_cast<std::size_t>(w * h)) << path;
            const bool isFloat = std::string(out.ext) == ".exr";
            const double top = isFloat ? 1.0 : out.bits == 16 ? 65535.0 : 255.0;
            for (int b = 0; b < n; ++b)
                for (int g = 0; g < n; ++g)
                    for (int r = 0; r < n; ++r) {
                        int x = r + n * b, y = g;
                        if (hald) {
                            const int i = r + n * g + n * n * b;
                            x = i % 8;
                            y = i / 8;
                        }
                        const auto& v = px.at({x, y});
                        ASSERT_EQ(v.size(), 4u) << path;
                        const int k[3] = {r, g, b};
                        for (int c = 0; c < 3; ++c) {
                            const double want = k[c] / static_cast<double>(n - 1) * top;
                            if (isFloat)
                                EXPECT_NEAR(v[c], want, 1e-6) << path << " " << x << "," << y;
                            else
                                EXPECT_EQ(v[c], std::round(want)) << path << " " << x << "," << y;
                        }
                        EXPECT_EQ(v[3], top) << path;
                    }
        }
    }
}

// A LUT image to standard output (writeMemory named "-", as `lutkit convert IN - --format strip`
// asks) is a PNG, the bytes of the same image written to a .png file (it was refused: "no image
// writer for this extension", naming a temporary file).
TEST(ReadMemory, ALutImageWithoutExtensionIsAPng) {
    const std::string dir = lut::test::tempDir();
    for (const char* name : {"strip", "hald"}) {
        const lut::Format& f = format(name);
        const std::string file = dir + "/" + name + ".png";
        f.write(file, gradedLut(16), {});
        std::string bytes;
        ASSERT_NO_THROW(bytes = f.writeMemory(gradedLut(16), "-", {})) << name;
        EXPECT_EQ(bytes, fileBytes(file)) << name;
        EXPECT_EQ(bytes.rfind(std::string("\x89PNG\r\n\x1a\n", 8), 0), 0u) << name;
        EXPECT_EQ(f.readMemory(bytes, "-", {}).cube->entries(), f.read(file, {}).cube->entries());
    }
}
