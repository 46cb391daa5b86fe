// SPDX-License-Identifier: Apache-2.0
// .cube writing: bit-exact round trips, what the header holds, the shaper rules, atomic writes,
// and OpenColorIO (an independent reader) agreeing with our reading of what we wrote.
#include "OcioTestUtil.h"
#include "TestSupport.h"

#include "lut/formats/Cube.h"
#include "lut/formats/Registry.h"
#include "lut/interp/Sampler.h"

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace OCIO = OCIO_NAMESPACE;
using namespace lut;
using namespace lut::formats;

namespace {

using lut::test::fileBytes;

bool sameBits(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec3)) == 0;
}

Lut3D randomLut(int size, unsigned seed, float lo, float hi) {
    Lut3D l(size);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(lo, hi);
    for (auto& v : l.entries())
        v = glm::vec3(u(rng), u(rng), u(rng));
    return l;
}

} // namespace

TEST(CubeWrite, RoundTripIsBitExactForAnyFiniteFloat) {
    Lut3D l(17);
    std::mt19937 rng(7);
    auto& e = l.entries();
    // Random bit patterns (every exponent, denormals, negative zero) ...
    for (auto& v : e)
        for (int c = 0; c < 3; ++c) {
            std::uint32_t bits;
            float f;
            do {
                bits = static_cast<std::uint32_t>(rng());
                std::memcpy(&f, &bits, 4);
            } while (!std::isfinite(f));
            v[c] = f;
        }
    // ... and the named extremes.
    const float special[] = {1e-30f, -5.0f,       1e20f,       0.0f,    -0.0f,
                             1.0f,   FLT_MAX,     -FLT_MAX,    FLT_MIN, FLT_TRUE_MIN,
                             0.1f,   1.0f / 3.0f, 16777216.0f, -1e-45f};
    for (std::size_t i = 0; i < std::size(special); ++i)
        e[i] = glm::vec3(special[i], -special[i], special[i]);
    l.setTitle("round trip");
    l.comments() = {"first", " indented", ""};
    l.setDomain(glm::vec3(-0.125f, 0.0f, 1e-3f), glm::vec3(1.5f, 3.0f, 7.0f));
    LutFile f;
    f.cube = l;
    Diagnostics diags;
    const std::string text = writeCubeString(f, &diags);
    EXPECT_TRUE(diags.empty());
    const LutFile back = parseCube(text, "rt.cube");
    ASSERT_TRUE(back.cube);
    EXPECT_TRUE(sameBits(back.cube->entries(), l.entries()));
    EXPECT_EQ(back.cube->title(), "round trip");
    EXPECT_EQ(back.cube->comments(), l.comments());
    EXPECT_EQ(back.cube->domainMin(), l.domainMin());
    EXPECT_EQ(back.cube->domainMax(), l.domainMax());
    EXPECT_EQ(back.dialect, "adobe");
    // LF only, and the written file is clean Adobe 1.0 (strict finds nothing).
    EXPECT_EQ(text.find('\r'), std::string::npos);
    CubeReadOptions strict;
    strict.strict = true;
    EXPECT_TRUE(parseCube(text, "rt.cube", strict).diagnostics.empty());
}

TEST(CubeWrite, HeaderLayout) {
    Lut3D l = Lut3D::identity(2);
    l.setTitle("Look");
    l.comments() = {"made by a test"};
    LutFile f;
    f.cube = l;
    // Default domain: no DOMAIN lines; comments first, then TITLE, then the size.
    EXPECT_EQ(writeCubeString(f), "# made by a test\nTITLE \"Look\"\nLUT_3D_SIZE 2\n"
                                  "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n");
    f.cube->setDomain(glm::vec3(0.0f), glm::vec3(2.0f, 2.0f, 4.0f));
    const std::string t = writeCubeString(f);
    EXPECT_NE(t.find("LUT_3D_SIZE 2\nDOMAIN_MIN 0 0 0\nDOMAIN_MAX 2 2 4\n0 0 0\n"),
              std::string::npos)
        << t;
}

TEST(CubeWrite, FixedDecimalsWhenAsked) {
    LutFile f;
    f.cube = Lut3D::identity(2);
    CubeWriteOptions o;
    o.decimals = 6;
    const std::string t = writeCubeString(f, nullptr, o);
    EXPECT_NE(t.find("1.000000 0.000000 0.000000\n"), std::string::npos) << t;
}

TEST(CubeWrite, TitleQuotesAndNonFiniteValuesAreReported) {
    Lut3D l = Lut3D::identity(2);
    l.setTitle("say \"hi\"");
    l.at(0, 0, 0) = glm::vec3(NAN, INFINITY, -INFINITY);
    LutFile f;
    f.cube = l;
    Diagnostics d;
    const std::string t = writeCubeString(f, &d);
    ASSERT_EQ(d.size(), 2u);
    const LutFile back = parseCube(t, "nf.cube");
    EXPECT_EQ(back.cube->title(), "say 'hi'");
    EXPECT_EQ(back.cube->at(0, 0, 0), glm::vec3(0.0f, FLT_MAX, -FLT_MAX));
}

TEST(CubeWrite, ShaperAndCubeInResolveDialect) {
    const LutFile src = readCube(lut::test::dataPath("cube/resolve_shaper_3d.cube"));
    Diagnostics d;
    const std::string t = writeCubeString(src, &d);
    EXPECT_TRUE(d.empty());
    EXPECT_NE(
        t.find("LUT_1D_SIZE 4\nLUT_1D_INPUT_RANGE 0 4\nLUT_3D_SIZE 2\nLUT_3D_INPUT_RANGE 0 1\n"),
        std::string::npos)
        << t;
    const LutFile back = parseCube(t, "r.cube");
    EXPECT_EQ(back.dialect, "resolve");
    ASSERT_TRUE(back.shaper && back.cube);
    EXPECT_TRUE(sameBits(back.shaper->entries(), src.shaper->entries()));
    EXPECT_TRUE(sameBits(back.cube->entries(), src.cube->entries()));
    EXPECT_EQ(back.shaper->domainMax(), glm::vec3(4.0f));
    EXPECT_EQ(back.cube->title(), "Generated by Resolve");
}

TEST(CubeWrite, ShaperWithPerChannelDomainIsBakedWithADiagnostic) {
    LutFile f;
    f.shaper = Lut1D::identity(16);
    f.shaper->setDomain(glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, 4.0f));
    // A cube that squares its input: the baked result must be shaper then cube.
    Lut3D c(9);
    for (int b = 0; b < 9; ++b)
        for (int g = 0; g < 9; ++g)
            for (int r = 0; r < 9; ++r) {
                const glm::vec3 x = c.latticeInput(r, g, b);
                c.at(r, g, b) = x * x;
            }
    f.cube = c;
    Diagnostics d;
    const std::string t = writeCubeString(f, &d);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NE(d[0].message.find("shaper baked"), std::string::npos);
    const LutFile back = parseCube(t, "b.cube");
    EXPECT_EQ(back.dialect, "adobe");
    EXPECT_FALSE(back.shaper);
    ASSERT_TRUE(back.cube);
    EXPECT_EQ(back.cube->domainMax(), glm::vec3(1.0f, 2.0f, 4.0f));
    // Input 2.0 in blue (the shaper's blue domain is 0..4) -> shaper gives 0.5 -> cube squares.
    EXPECT_NEAR(back.cube->at(8, 8, 4).z, 0.25f, 1e-6f);
    EXPECT_NEAR(back.cube->at(8, 8, 4).x, 1.0f, 1e-6f);
}

TEST(CubeWrite, OneDOnly) {
    LutFile f;
    f.shaper = Lut1D::identity(3);
    f.shaper->setTitle("ramp");
    EXPECT_EQ(writeCubeString(f), "TITLE \"ramp\"\nLUT_1D_SIZE 3\n0 0 0\n0.5 0.5 0.5\n1 1 1\n");
}

TEST(CubeWrite, EmptyLutIsAnError) {
    EXPECT_THROW(writeCubeString(LutFile{}), Error);
}

TEST(CubeWrite, AtomicFileAndRegistry) {
    const std::string dir = lut::test::tempDir();
    const std::string path = dir + "/out.cube";
    { std::ofstream(path) << "old content"; }
    LutFile f;
    f.cube = randomLut(5, 3, 0.0f, 1.0f);
    const Diagnostics d = writeLut(path, f); // through the registry, picked by extension
    EXPECT_TRUE(d.empty());
    const LutFile back = readCube(path);
    EXPECT_TRUE(sameBits(back.cube->entries(), f.cube->entries()));
    // Nothing but the target is left in the folder (the temporary file was renamed).
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        (void)e;
        ++files;
    }
    EXPECT_EQ(files, 1);
    // A failed write leaves the old file alone.
    EXPECT_THROW(writeCube(dir + "/no/such/dir/x.cube", f), Error);
    EXPECT_EQ(fileBytes(path).substr(0, 11), "LUT_3D_SIZE");
}

// OpenColorIO reads the file we wrote; its tetrahedral processor must agree with our reading of
// the same file evaluated by our tetrahedral sampler.
TEST(CubeWrite, OcioReadsOurOutputAndAgrees) {
    const std::string dir = lut::test::tempDir();
    for (int size : {2, 17, 33}) {
        const std::string path = dir + "/ocio_" + std::to_string(size) + ".cube";
        LutFile f;
        f.cube = randomLut(size, static_cast<unsigned>(size), -0.1f, 1.1f);
        f.cube->setTitle("for OCIO");
        f.cube->comments() = {"written by lutkit tests"};
        writeCube(path, f);

        const LutFile ours = readCube(path);
        const auto sampler = makeSampler(*ours.cube, Interpolation::Tetrahedral);

        OCIO::ConstCPUProcessorRcPtr cpu = test::ocioFileProcessor(path);

        std::mt19937 rng(99);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        float worst = 0.0f;
        for (int i = 0; i < 4000; ++i) {
            glm::vec3 in(u(rng), u(rng), u(rng));
            if (i < 8)
                in = glm::vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1); // the corners
            float rgb[3] = {in.x, in.y, in.z};
            cpu->applyRGB(rgb);
            const glm::vec3 mine = sampler->sample(in);
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::fabs(mine[c] - rgb[c]));
        }
        EXPECT_LT(worst, 1e-5f) << "size " << size;
    }
}

TEST(CubeWrite, SixtyFiveCubedRoundTrip) {
    LutFile f;
    f.cube = randomLut(65, 65, -0.5f, 1.5f);
    const std::string t = writeCubeString(f);
    const LutFile back = parseCube(t, "65.cube");
    EXPECT_TRUE(sameBits(back.cube->entries(), f.cube->entries()));
}

// Values from 8-bit sources repeat a lot (the writer caches their text): still bit-exact, and
// the text of each value is the shortest one (k/255 written as std::to_chars writes it).
TEST(CubeWrite, EightBitValuesRoundTripAndReadWell) {
    Lut3D l(33);
    std::mt19937 rng(8);
    for (auto& v : l.entries())
        v = glm::vec3(static_cast<float>(rng() % 256) / 255.0f,
                      static_cast<float>(rng() % 256) / 255.0f,
                      static_cast<float>(rng() % 256) / 255.0f);
    l.at(0, 0, 0) = glm::vec3(128.0f / 255.0f, 0.0f, 1.0f);
    LutFile f;
    f.cube = l;
    const std::string t = writeCubeString(f);
    EXPECT_NE(t.find("\n0.5019608 0 1\n"), std::string::npos); // 128/255 in its shortest form
    const LutFile back = parseCube(t, "8bit.cube");
    EXPECT_TRUE(sameBits(back.cube->entries(), l.entries()));
}
