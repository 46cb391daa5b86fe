// SPDX-License-Identifier: Apache-2.0
// Shapers and input ranges survive the formats that hold them: a Resolve .cube with a 1D shaper
// over 0..16 converted to .clf, .ctf and .csp and back (it used to lose the shaper: 172 8-bit
// steps, exit 0), checked with OpenColorIO reading the original and the round-tripped files; and
// ociobakelut's format names reach the right writers.
#include "OcioTestUtil.h"

#include "lut/formats/Convert.h"
#include "lut/formats/Registry.h"
#include "lut/io/FormatRegistry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace lut::test;

namespace {

std::string workDir() {
    const std::string d = tempDir() + "-shaper";
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

// An HDR grade as Resolve writes it: a log-like shaper over 0..16, then a 9^3 cube mixing
// channels.
std::string writeHdrCube(const std::string& dir) {
    const std::string path = dir + "/hdr.cube";
    std::ofstream f(path);
    f.precision(9);
    // No TITLE: OpenColorIO 2.1's Resolve reader refuses it.
    f << "LUT_1D_SIZE 64\nLUT_3D_SIZE 9\nLUT_1D_INPUT_RANGE 0 16\n"
         "LUT_3D_INPUT_RANGE 0 1\n";
    for (int i = 0; i < 64; ++i) {
        const double x = 16.0 * i / 63.0;
        const double y = std::log2(x * 64.0 + 1.0) / std::log2(16.0 * 64.0 + 1.0);
        f << y << " " << y << " " << y << "\n";
    }
    for (int b = 0; b < 9; ++b)
        for (int g = 0; g < 9; ++g)
            for (int r = 0; r < 9; ++r) {
                const double R = r / 8.0, G = g / 8.0, B = b / 8.0;
                f << 0.9 * R + 0.05 * G << " " << std::pow(G, 1.2) << " " << 0.8 * B + 0.1 * R
                  << "\n";
            }
    return path;
}

// OCIO's processors on two files compared on inputs spread over 0..16 (dense in the darks,
// where the shaper is steep).
double worstOverHdr(const std::string& a, const std::string& b) {
    const auto pa = ocioFileProcessor(a), pb = ocioFileProcessor(b);
    double worst = 0.0;
    const int n = 25;
    for (int k = 0; k < n * n * n; ++k) {
        const int idx[3] = {k % n, (k / n) % n, k / (n * n)};
        glm::vec3 x;
        for (int c = 0; c < 3; ++c)
            x[c] = 16.0f * std::pow(float(idx[c]) / (n - 1), 3.0f);
        const glm::vec3 va = ocioEval(pa, x), vb = ocioEval(pb, x);
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::fabs(double(va[c]) - vb[c]));
    }
    return worst;
}

TEST(ShaperRoundTrip, CubeWithShaperThroughClfCtfCsp) {
    const std::string dir = workDir();
    const std::string cube = writeHdrCube(dir);
    // .clf/.ctf hold the shaper exactly; OCIO reads a .csp prelut as a cubic through the points.
    const struct {
        const char* ext;
        double storage;
        double function;
    } cases[] = {{".clf", 1e-6, 1e-5}, {".ctf", 1e-6, 1e-5}, {".csp", 1e-3, 1e-3}};
    for (const auto& c : cases) {
        SCOPED_TRACE(c.ext);
        const std::string mid = dir + "/mid" + c.ext,
                          back = dir + "/back" + std::string(c.ext + 1) + ".cube";
        const auto there = lut::formats::convertLut(cube, mid);
        ASSERT_TRUE(there.readBack);
        ASSERT_TRUE(there.storage);
        EXPECT_LE(there.storage->maxAbs, c.storage);
        for (const auto& d : there.writeDiagnostics)
            EXPECT_EQ(d.message.find("shaper was baked"), std::string::npos) << d.str();
        // The shaper's input range is in the file: OCIO evaluates the same function over 0..16.
        EXPECT_LE(worstOverHdr(cube, mid), c.function);
        const auto home = lut::formats::convertLut(mid, back);
        ASSERT_TRUE(home.readBack && home.readBack->shaper);
        EXPECT_EQ(home.readBack->shaper->domainMax(), glm::vec3(16.0f));
        EXPECT_LE(worstOverHdr(cube, back), c.function);
    }
}

TEST(ShaperRoundTrip, ResolveCorpusFileThroughClf) {
    const std::string dir = workDir();
    const std::string src = corpusPath("resolve_1d3d.cube"), mid = dir + "/r.clf";
    const auto r = lut::formats::convertLut(src, mid);
    ASSERT_TRUE(r.storage);
    EXPECT_LE(r.storage->maxAbs, 1e-6);
    const auto pa = ocioFileProcessor(src), pb = ocioFileProcessor(mid);
    for (float x = -1.5f; x <= 3.5f; x += 0.0625f) {
        const glm::vec3 in(x, 3.0f - x, 0.5f * x);
        const glm::vec3 a = ocioEval(pa, in), b = ocioEval(pb, in);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(a[c], b[c], 1e-5) << x;
    }
}

TEST(FormatAliases, OcioBakerNamesReachOurWriters) {
    lut::formats::registerBuiltinFormats();
    auto& reg = lut::FormatRegistry::instance();
    const std::pair<const char*, const char*> names[] = {{"resolve_cube", "cube"},
                                                         {"iridas_cube", "cube"},
                                                         {"cinespace", "csp"},
                                                         {"truelight", "cub"},
                                                         {"iridas_itx", "itx"},
                                                         {"3dl", "flame"},
                                                         {"flame", "flame"},
                                                         {"lustre", "lustre"},
                                                         {"houdini", "houdini"},
                                                         {"Academy/ASC Common LUT Format", "clf"},
                                                         {"Color Transform Format", "ctf"}};
    for (const auto& [alias, name] : names) {
        const lut::Format* f = reg.byName(alias);
        ASSERT_NE(f, nullptr) << alias;
        EXPECT_EQ(f->name(), name) << alias;
    }
    // The dialect the alias names: a shaper + cube file written as resolve_cube keeps its
    // LUT_1D; as iridas_cube it is baked into one 3D table.
    const std::string dir = workDir();
    const lut::LutFile hdr = lut::formats::readLut(writeHdrCube(dir));
    lut::formats::writeLut(dir + "/r.cube", hdr, {}, "resolve_cube");
    lut::formats::writeLut(dir + "/i.cube", hdr, {}, "iridas_cube");
    std::stringstream r, i;
    r << std::ifstream(dir + "/r.cube").rdbuf();
    i << std::ifstream(dir + "/i.cube").rdbuf();
    EXPECT_NE(r.str().find("LUT_1D_SIZE 64"), std::string::npos);
    EXPECT_EQ(i.str().find("LUT_1D_SIZE"), std::string::npos);
    lut::formats::writeLut(dir + "/c.csp", hdr, {}, "cinespace");
    std::stringstream c;
    c << std::ifstream(dir + "/c.csp").rdbuf();
    EXPECT_EQ(c.str().rfind("CSPLUTV100", 0), 0u);
}

} // namespace
