// SPDX-License-Identifier: Apache-2.0
// The OpenColorIO bridge: every Baker format written and read back, hand-written foreign files
// compared with values computed here, and the extension list checked against OCIO itself.
#include "OcioTestUtil.h"
#include "TestSupport.h"

#include "lut/Error.h"
#include "lut/formats/Registry.h"
#include "lut/io/Format.h"

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>

namespace OCIO = OCIO_NAMESPACE;
using lut::test::dataPath;

namespace {

// A smooth, channel-mixing grade inside [0,1]: any swap of index order or channels shows.
glm::vec3 grade(glm::vec3 x) {
    return {0.9f * x.x + 0.05f * x.y * x.y, 0.1f + 0.8f * x.y * (1.0f - 0.2f * x.z),
            0.95f * x.z * x.z + 0.02f + 0.03f * x.x};
}

lut::Lut3D gradeLut(int n) {
    lut::Lut3D l = lut::Lut3D::identity(n);
    for (auto& e : l.entries())
        e = grade(e);
    l.setTitle("ocio bridge test");
    return l;
}

glm::vec3 affine(glm::vec3 x) {
    return {0.1f + 0.8f * x.x, 0.2f + 0.1f * x.x + 0.5f * x.y, 0.9f - 0.7f * x.z};
}

// A fresh folder of our own: TestSupport's tempDir() clears the test's folder on every call.
std::string workDir() {
    const std::string d = lut::test::tempDir() + "-ocio";
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

double maxEntryDiff(const lut::Lut3D& a, const lut::Lut3D& b) {
    double m = 0;
    for (std::size_t i = 0; i < a.entryCount(); ++i)
        for (int c = 0; c < 3; ++c)
            m = std::max(m, std::fabs(double(a.entries()[i][c]) - b.entries()[i][c]));
    return m;
}

struct BakeCase {
    const char* format;
    const char* ext;
    double tolerance; // what the file stores: integers for .3dl, decimal text for the others
};

// .3dl stores 12-bit integers: rounding costs at most half a step, 0.5/4095. The text formats
// print floats with enough digits to come back within float rounding of the value written.
const BakeCase kBakeCases[] = {
    {"flame", ".3dl", 0.5 / 4095 + 1e-6},
    {"lustre", ".3dl", 0.5 / 4095 + 1e-6},
    {"csp", ".csp", 2e-6},
    {"clf", ".clf", 2e-6},
    {"ctf", ".ctf", 2e-6},
    {"cub", ".cub", 2e-6},
    {"itx", ".itx", 2e-6},
    {"houdini", ".lut", 2e-6},
    {"spi3d", ".spi3d", 0.0},
};

} // namespace

TEST(OcioFormat, ReaderClaimsEveryOcioExtensionButCube) {
    lut::formats::registerBuiltinFormats();
    const lut::Format* f = lut::FormatRegistry::instance().byName("ocio");
    ASSERT_NE(f, nullptr);
    std::set<std::string> ours;
    for (const auto& e : f->extensions())
        ours.insert(e);
    std::set<std::string> theirs;
    for (int i = 0; i < OCIO::FileTransform::GetNumFormats(); ++i) {
        std::string e = std::string(".") + OCIO::FileTransform::GetFormatExtensionByIndex(i);
        std::transform(e.begin(), e.end(), e.begin(),
                       [](unsigned char c) { return char(std::tolower(c)); });
        if (e != ".cube")
            theirs.insert(e);
    }
    EXPECT_EQ(ours, theirs);
    EXPECT_EQ(ours.count(".cube"), 0u);
}

TEST(OcioFormat, EveryBakerFormatHasAWriter) {
    lut::formats::registerBuiltinFormats();
    std::set<std::string> exts;
    for (const auto* f : lut::FormatRegistry::instance().all())
        if (f->canWrite())
            for (const auto& e : f->extensions())
                exts.insert(e);
    for (int i = 0; i < OCIO::Baker::getNumFormats(); ++i) {
        const std::string e = std::string(".") + OCIO::Baker::getFormatExtensionByIndex(i);
        EXPECT_EQ(exts.count(e), 1u)
            << "no writer for " << OCIO::Baker::getFormatNameByIndex(i) << " " << e;
    }
}

class OcioBake : public ::testing::TestWithParam<BakeCase> {};

TEST_P(OcioBake, WritesAndReadsBackWithinTheFormatsPrecision) {
    const BakeCase c = GetParam();
    const std::string path = workDir() + "/grade" + c.ext;
    for (const int n : {4, 17}) {
        lut::LutFile file;
        file.cube = gradeLut(n);
        lut::formats::writeLut(path, file, {}, c.format);
        const lut::LutFile back = lut::formats::readLut(path);
        // lutkit's own reader takes .spi3d (Spi3dReadsAsOpenColorIOReadsIt), OpenColorIO the rest.
        EXPECT_EQ(back.format, std::string(c.format) == "spi3d" ? "spi3d" : "ocio");
        ASSERT_TRUE(back.cube);
        ASSERT_EQ(back.cube->size(), n) << c.format;
        EXPECT_LE(maxEntryDiff(*file.cube, *back.cube), c.tolerance) << c.format << " size " << n;
        // And the written table is not trivially the identity: the check above could fail.
        EXPECT_GT(back.cube->maxDeviationFromIdentity(), 0.05f);
    }
}

INSTANTIATE_TEST_SUITE_P(AllBakerFormats, OcioBake, ::testing::ValuesIn(kBakeCases),
                         [](const auto& info) { return std::string(info.param.format); });

TEST(OcioFormat, TinyThreeDlTablesAreUpsampledExactly) {
    // OCIO cannot read back a .3dl with fewer than 4 lattice points per axis; the writer
    // upsamples, which is exact for an affine table (any interpolation of it is itself).
    const std::string path = workDir() + "/tiny.3dl";
    lut::LutFile file;
    file.cube = lut::Lut3D::identity(2);
    for (auto& e : file.cube->entries())
        e = affine(e);
    const auto diags = lut::formats::writeLut(path, file);
    EXPECT_FALSE(diags.empty());
    const lut::LutFile back = lut::formats::readLut(path);
    ASSERT_EQ(back.cube->size(), 4);
    for (int b = 0; b < 4; ++b)
        for (int g = 0; g < 4; ++g)
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(back.cube->at(r, g, b)[c], affine(glm::vec3(r, g, b) / 3.0f)[c],
                                0.5 / 4095 + 1e-6);
}

TEST(OcioFormat, FlameStoresTwelveBitIntegers) {
    const std::string path = workDir() + "/g.3dl";
    lut::LutFile file;
    file.cube = gradeLut(9);
    lut::formats::writeLut(path, file);
    const lut::LutFile back = lut::formats::readLut(path);
    EXPECT_EQ(back.sourceBitDepth, 12);
    for (const auto& e : back.cube->entries())
        for (int c = 0; c < 3; ++c) {
            const double steps = e[c] * 4095.0;
            EXPECT_NEAR(steps, std::round(steps), 1e-3);
        }
}

lut::LutFile domainFile() {
    lut::LutFile file;
    lut::Lut3D l = lut::Lut3D::identity(5);
    l.setDomain(glm::vec3(0.0f), glm::vec3(2.0f));
    for (int b = 0; b < 5; ++b)
        for (int g = 0; g < 5; ++g)
            for (int r = 0; r < 5; ++r)
                l.at(r, g, b) = affine(l.latticeInput(r, g, b) * 0.5f);
    file.cube = l;
    return file;
}

TEST(OcioFormat, NonDefaultDomainIsResampledOverUnitInputsWithoutAShaper) {
    // .itx holds neither a shaper nor an input range.
    const std::string path = workDir() + "/domain.itx";
    const auto diags = lut::formats::writeLut(path, domainFile(), {}, "itx");
    EXPECT_TRUE(std::any_of(diags.begin(), diags.end(), [](const lut::Diagnostic& d) {
        return d.message.find("domain") != std::string::npos;
    }));
    const lut::LutFile back = lut::formats::readLut(path);
    ASSERT_TRUE(back.cube);
    EXPECT_TRUE(back.cube->hasDefaultDomain());
    // The file maps input x in [0,1] to affine(x / 2): the table over [0,2] evaluated there.
    for (int b = 0; b < 5; ++b)
        for (int g = 0; g < 5; ++g)
            for (int r = 0; r < 5; ++r) {
                const glm::vec3 want = affine(glm::vec3(r, g, b) / 4.0f * 0.5f);
                const glm::vec3 got = back.cube->at(r, g, b);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(got[c], want[c], 1e-5) << r << g << b;
            }
}

TEST(OcioFormat, FormatsWithAShaperKeepTheInputRange) {
    // .clf, .ctf (a range Matrix) and .csp (a straight prelut) keep the 0..2 input range: the
    // file read back has the same domain and entries, and OCIO's processor on the written file
    // gives affine(x / 2) at x = 2 (where a [0,1] file would have clamped to affine(1/2)).
    for (const char* ext : {".clf", ".ctf", ".csp"}) {
        SCOPED_TRACE(ext);
        const std::string path = workDir() + "/domain" + ext;
        const auto diags = lut::formats::writeLut(path, domainFile());
        EXPECT_FALSE(std::any_of(diags.begin(), diags.end(), [](const lut::Diagnostic& d) {
            return d.severity == lut::Diagnostic::Severity::Warning;
        }));
        const lut::LutFile back = lut::formats::readLut(path);
        ASSERT_TRUE(back.cube);
        EXPECT_EQ(back.cube->size(), 5);
        EXPECT_EQ(back.cube->domainMax(), glm::vec3(2.0f));
        EXPECT_LE(maxEntryDiff(*domainFile().cube, *back.cube), 2e-6);

        const auto cpu = lut::test::ocioFileProcessor(path);
        float rgb[3] = {2.0f, 1.0f, 0.5f};
        cpu->applyRGB(rgb);
        const glm::vec3 want = affine(glm::vec3(1.0f, 0.5f, 0.25f));
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(rgb[c], want[c], 1e-5);
    }
}

// lutkit's .spi3d reader against OpenColorIO's reading of the same files: a table written by
// lutkit (random values, sizes 2, 17, 33) and the hand-written one, each lattice point evaluated by
// OpenColorIO's processor (tetrahedral, exact at the points).
TEST(OcioFormat, Spi3dReadsAsOpenColorIOReadsIt) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-0.25f, 1.5f);
    for (const int n : {2, 17, 33}) {
        lut::LutFile src;
        src.cube = lut::Lut3D(n);
        for (auto& e : src.cube->entries())
            e = glm::vec3(u(rng), u(rng), u(rng));
        const std::string path = workDir() + "/random" + std::to_string(n) + ".spi3d";
        lut::formats::writeLut(path, src, {}, "spi3d");
        for (const std::string& file : {path, dataPath("ocio/affine.spi3d")}) {
            const lut::LutFile own = lut::formats::readLut(file);
            EXPECT_EQ(own.format, "spi3d");
            ASSERT_TRUE(own.cube);
            const auto p = lut::test::ocioFileProcessor(file);
            const int m = own.cube->size();
            for (int b = 0; b < m; ++b)
                for (int g = 0; g < m; ++g)
                    for (int r = 0; r < m; ++r) {
                        const glm::vec3 want =
                            lut::test::ocioEval(p, glm::vec3(r, g, b) / float(m - 1));
                        for (int ch = 0; ch < 3; ++ch)
                            ASSERT_NEAR(own.cube->at(r, g, b)[ch], want[ch], 2e-6)
                                << file << " at " << r << " " << g << " " << b;
                    }
        }
    }
}

TEST(OcioFormat, RefusesTablesLargerThanOcioHolds) {
    const std::string path = workDir() + "/big.csp";
    lut::LutFile file;
    file.cube = lut::Lut3D::identity(130);
    EXPECT_THROW(lut::formats::writeLut(path, file, {}, "csp"), lut::Error);
    EXPECT_FALSE(std::filesystem::exists(path));
}

// Hand-written files (tests/data/ocio/) of the affine map above: any interpolation of an affine
// map is exact, so sampling on any lattice must return affine() itself.
struct HandCase {
    const char* file;
    int ownSize;
    double tolerance; // .3dl: 12-bit integers
};

class OcioHandWritten : public ::testing::TestWithParam<HandCase> {};

TEST_P(OcioHandWritten, ReadsTheValuesComputedHere) {
    const HandCase c = GetParam();
    const std::string path = dataPath(std::string("ocio/") + c.file);
    const lut::LutFile own = lut::formats::readLut(path);
    ASSERT_TRUE(own.cube);
    EXPECT_EQ(own.cube->size(), c.ownSize);
    // OpenColorIO's formats are sampled on the lattice asked for; .spi3d is read by lutkit,
    // exactly.
    const bool sampled = std::string(c.file).find(".spi3d") == std::string::npos;
    for (const int n : {c.ownSize, sampled ? 9 : c.ownSize}) {
        lut::FormatOptions o;
        o.size = sampled ? n : 0;
        const lut::LutFile f = lut::formats::readLut(path, o);
        ASSERT_EQ(f.cube->size(), n);
        for (int b = 0; b < n; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r) {
                    const glm::vec3 want = affine(glm::vec3(r, g, b) / float(n - 1));
                    const glm::vec3 got = f.cube->at(r, g, b);
                    for (int ch = 0; ch < 3; ++ch)
                        ASSERT_NEAR(got[ch], want[ch], c.tolerance)
                            << c.file << " n=" << n << " at " << r << g << b;
                }
    }
}

INSTANTIATE_TEST_SUITE_P(Files, OcioHandWritten,
                         ::testing::Values(HandCase{"affine.spi3d", 2, 2e-6},
                                           HandCase{"affine.csp", 2, 2e-6},
                                           HandCase{"affine.3dl", 5, 0.5 / 4095 + 1e-6}),
                         [](const auto& info) {
                             std::string s = info.param.file;
                             std::replace(s.begin(), s.end(), '.', '_');
                             return s;
                         });

TEST(OcioFormat, ThreeDlIsTwelveBit) {
    EXPECT_EQ(lut::formats::readLut(dataPath("ocio/affine.3dl")).sourceBitDepth, 12);
    EXPECT_EQ(lut::formats::readLut(dataPath("ocio/affine.spi3d")).sourceBitDepth, 0);
}

TEST(OcioFormat, ErrorsNameTheFileOnOneLine) {
    const std::string dir = workDir();
    const std::string bad = dir + "/bad.spi3d";
    std::ofstream(bad) << "SPILUT 1.0\n3 3\n2 2 2\n0 0 0 0.1 0.2\n";
    try {
        lut::formats::readLut(bad);
        FAIL() << "no error";
    } catch (const lut::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find(bad), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
    EXPECT_THROW(lut::formats::readLut(dir + "/missing.csp"), lut::Error);
}

TEST(OcioFormat, SizeOptionOutOfRangeIsRefused) {
    lut::FormatOptions o;
    o.size = 257;
    EXPECT_THROW(lut::formats::readLut(dataPath("ocio/affine.3dl"), o), lut::Error);
}

TEST(OcioFormat, OneDimensionalFilesStayOneDimensional) {
    // curve.spi1d: 5 entries of (x^2, 0.5x + 0.1, 1 - x) at x = i/4.
    const auto curve = [](float x) { return glm::vec3(x * x, 0.5f * x + 0.1f, 1.0f - x); };
    const lut::LutFile f = lut::formats::readLut(dataPath("ocio/curve.spi1d"));
    ASSERT_TRUE(f.shaper);
    EXPECT_FALSE(f.cube);
    ASSERT_EQ(f.shaper->size(), 5);
    for (int i = 0; i < 5; ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR((*f.shaper)[i][c], curve(i / 4.0f)[c], 2e-6) << i;
    // Asked for a lattice, it is one: each channel follows its own curve.
    lut::FormatOptions o;
    o.size = 5;
    const lut::LutFile g = lut::formats::readLut(dataPath("ocio/curve.spi1d"), o);
    ASSERT_TRUE(g.cube);
    for (int b = 0; b < 5; ++b)
        for (int gg = 0; gg < 5; ++gg)
            for (int r = 0; r < 5; ++r) {
                const glm::vec3 v = g.cube->at(r, gg, b);
                EXPECT_NEAR(v.x, curve(r / 4.0f).x, 2e-6);
                EXPECT_NEAR(v.y, curve(gg / 4.0f).y, 2e-6);
                EXPECT_NEAR(v.z, curve(b / 4.0f).z, 2e-6);
            }
}
