// Format::readMemory / writeMemory: every format reads and writes bytes in memory (standard
// input and output). The cube and nutexb formats parse and make bytes directly, the others go
// through a private temporary file; either way the result equals reading the same bytes from a
// file, and messages name the caller's name for the data, never a temporary path.
#include "TestSupport.h"

#include "lut/Error.h"
#include "lut/formats/Registry.h"
#include "lut/io/FormatRegistry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

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
    // {writer, reader}: OCIO's bake formats are read back by the one "ocio" reader.
    const std::pair<const char*, const char*> formats[] = {
        {"cube", "cube"}, {"nutexb", "nutexb"}, {"strip", "strip"}, {"spi3d", "ocio"}};
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
