// SPDX-License-Identifier: Apache-2.0
// OpenColorIO's own test files (tests/data/ocio/corpus) through lutkit: every bake equals OCIO's
// processor on the source file, evaluated directly, at every lattice point of a 33^3 grid (the
// written file itself read by OCIO, an independent reader); chains are read through the whole
// processor at the size asked for, never on an inner table's lattice; files of one known shape are
// read exactly.
#include "OcioTestUtil.h"

#include "lut/Error.h"
#include "lut/formats/Bake.h"
#include "lut/formats/OcioFiles.h"
#include "lut/formats/Registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

using namespace lut::test;

namespace {

std::string workDir() {
    const std::string d = tempDir() + "-corpus";
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

double tolerance(double reference) {
    return 1e-5 * std::max(1.0, std::fabs(reference));
}

// Compares OCIO's processor on `written` with the one on the source at the n^3 lattice points of
// [lo, hi]; points where the source is not finite are skipped (the bake writes 0 there and warns).
// Returns the largest difference in units of tolerance().
double worstOnLattice(const OCIO::ConstCPUProcessorRcPtr& source,
                      const OCIO::ConstCPUProcessorRcPtr& written, glm::vec3 lo, glm::vec3 hi,
                      int n, int& skipped) {
    double worst = 0.0;
    skipped = 0;
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 x = lo + (hi - lo) * glm::vec3(r, g, b) / float(n - 1);
                const glm::vec3 want = ocioEval(source, x);
                const glm::vec3 got = ocioEval(written, x);
                for (int c = 0; c < 3; ++c) {
                    if (!std::isfinite(want[c])) {
                        ++skipped;
                        continue;
                    }
                    worst =
                        std::max(worst, std::fabs(double(got[c]) - want[c]) / tolerance(want[c]));
                }
            }
    return worst;
}

class OcioCorpus : public ::testing::TestWithParam<CorpusFile> {};

TEST_P(OcioCorpus, BakeEqualsOcioProcessorAtEveryLatticePoint) {
    const CorpusFile f = GetParam();
    const std::string src = corpusPath(f.name);
    const auto source = ocioFileProcessor(src, f.cccid);
    const std::string dir = workDir();
    // .cube (Resolve dialect: an input range is kept) and .clf, both read back by OCIO.
    for (const char* ext : {".cube", ".clf"}) {
        SCOPED_TRACE(std::string(f.name) + " -> " + ext);
        const std::string out = dir + "/baked" + ext;
        lut::formats::BakeOptions o;
        o.files = {{src, f.cccid, false}};
        o.cubeSize = 33;
        const lut::formats::BakeReport r = lut::formats::bake(out, o);
        ASSERT_EQ(r.cubeSize, 33);
        EXPECT_TRUE(r.measuredFile) << r.readBackError;
        int skipped = 0;
        const double worst =
            worstOnLattice(source, ocioFileProcessor(out), r.domainMin, r.domainMax, 33, skipped);
        EXPECT_LE(worst, 1.0) << "largest difference, in units of 1e-5 (relative above 1)";
        if (skipped) {
            EXPECT_TRUE(std::any_of(r.diagnostics.begin(), r.diagnostics.end(),
                                    [](const lut::Diagnostic& d) {
                                        return d.message.find("NaN/Inf") != std::string::npos;
                                    }));
        }
        // The reported error is the file against the processor between lattice points: finite,
        // and for a file that is exactly one table over its own range, zero.
        EXPECT_TRUE(std::isfinite(r.error.maxAbs) || skipped);
    }
}

INSTANTIATE_TEST_SUITE_P(Files, OcioCorpus, ::testing::ValuesIn(ocioCorpus()),
                         [](const auto& info) {
                             std::string s = info.param.name;
                             for (auto& c : s)
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             return s;
                         });

TEST(OcioCorpusRead, ChainsAreSampledThroughTheWholeProcessor) {
    // Each of these holds a small table inside a chain: reading used to sample on that table's
    // 2^3 or 3^3 lattice ("size 2^3") and resampling to 33 differed from OCIO by up to 1.0.
    for (const char* name : {"clf/multiple_ops.clf", "clf/lut1d_lut3d_lut1d.clf",
                             "clf/illegal/unknown_elements.clf"}) {
        SCOPED_TRACE(name);
        const std::string path = corpusPath(name);
        const auto source = ocioFileProcessor(path);
        const lut::LutFile own = lut::formats::readLut(path);
        ASSERT_TRUE(own.cube);
        EXPECT_EQ(own.cube->size(), 33);
        EXPECT_TRUE(std::any_of(own.diagnostics.begin(), own.diagnostics.end(),
                                [](const lut::Diagnostic& d) {
                                    return d.message.find("differs from OpenColorIO's processor "
                                                          "by max") != std::string::npos;
                                }));
        lut::FormatOptions o;
        o.size = 17;
        const lut::LutFile f = lut::formats::readLut(path, o);
        ASSERT_EQ(f.cube->size(), 17);
        double worst = 0.0;
        for (int b = 0; b < 17; ++b)
            for (int g = 0; g < 17; ++g)
                for (int r = 0; r < 17; ++r) {
                    const glm::vec3 want = ocioEval(source, glm::vec3(r, g, b) / 16.0f);
                    for (int c = 0; c < 3; ++c)
                        worst =
                            std::max(worst, std::fabs(double(f.cube->at(r, g, b)[c]) - want[c]) /
                                                tolerance(want[c]));
                }
        EXPECT_LE(worst, 1.0);
    }
}

TEST(OcioCorpusRead, FilesOfOneShapeAreReadExactly) {
    // A 17^3 table: read at its own size, no sampling note.
    const lut::LutFile t = lut::formats::readLut(corpusPath("clf/lut3d_17x17x17_10i_12i.clf"));
    ASSERT_TRUE(t.cube);
    EXPECT_EQ(t.cube->size(), 17);
    for (const auto& d : t.diagnostics)
        EXPECT_EQ(d.message.find("sampled"), std::string::npos) << d.str();
    // nuke_3d.vf: a 2^3 table behind a range over 0..0.5.
    const lut::LutFile vf = lut::formats::readLut(corpusPath("nuke_3d.vf"));
    ASSERT_TRUE(vf.cube);
    EXPECT_EQ(vf.cube->size(), 2);
    EXPECT_EQ(vf.cube->domainMax(), glm::vec3(0.5f));
    // resolve_1d3d.cube through OCIO: the same function as lutkit's own .cube reader reads,
    // shaper and input ranges kept (checked as functions on a grid reaching past the domain).
    const lut::LutFile viaOcio = lut::formats::readLut(corpusPath("resolve_1d3d.cube"), {}, "ocio");
    const lut::LutFile ours = lut::formats::readLut(corpusPath("resolve_1d3d.cube"));
    ASSERT_TRUE(viaOcio.shaper && viaOcio.cube);
    EXPECT_EQ(viaOcio.shaper->size(), ours.shaper->size());
    EXPECT_EQ(viaOcio.shaper->domainMin(), ours.shaper->domainMin());
    EXPECT_EQ(viaOcio.shaper->domainMax(), ours.shaper->domainMax());
    const auto source = ocioFileProcessor(corpusPath("resolve_1d3d.cube"));
    const lut::Lut3D a = viaOcio.toLut3D(9), b = ours.toLut3D(9);
    for (std::size_t i = 0; i < a.entryCount(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(a.entries()[i][c], b.entries()[i][c], 1e-5);
}

TEST(OcioCorpusRead, CccIdPicksTheCorrection) {
    const std::string path = corpusPath("cdl_test1.ccc");
    try {
        (void)lut::formats::readLut(path);
        FAIL() << "read without a CCC id";
    } catch (const lut::Error& e) {
        EXPECT_NE(std::string(e.what()).find("--cccid"), std::string::npos) << e.what();
    }
    for (const char* id : {"cc0001", "cc0003", "1"}) {
        SCOPED_TRACE(id);
        lut::FormatOptions o;
        o.size = 5;
        o.setAttribute(lut::formats::kOcioCccIdAttribute, id);
        const lut::LutFile f = lut::formats::readLut(path, o);
        const auto source = ocioFileProcessor(path, id);
        for (int b = 0; b < 5; ++b)
            for (int g = 0; g < 5; ++g)
                for (int r = 0; r < 5; ++r) {
                    const glm::vec3 want = ocioEval(source, glm::vec3(r, g, b) / 4.0f);
                    for (int c = 0; c < 3; ++c)
                        EXPECT_NEAR(f.cube->at(r, g, b)[c], want[c], 1e-6);
                }
    }
}

TEST(OcioCorpusBake, PerChannelConversionsBecomeOneDimensionalTables) {
    // A 1D table holds a conversion without crosstalk exactly at its entries: each coordinate of
    // the grid below is an entry of the 4096-entry table (4095 = 5 * 819).
    const std::string dir = workDir();
    for (const char* name : {"lut1d_1.spi1d", "clf/log_all_styles.clf", "cdl_test_ASC_SAT.cc"}) {
        SCOPED_TRACE(name);
        const std::string src = corpusPath(name), out = dir + "/curves.cube";
        lut::formats::BakeOptions o;
        o.files = {{src, "", false}};
        const lut::formats::BakeReport r = lut::formats::bake(out, o);
        EXPECT_EQ(r.cubeSize, 0);
        EXPECT_EQ(r.shaperSize, lut::formats::kDefaultShaperSize);
        const lut::LutFile back = lut::formats::readLut(out);
        EXPECT_TRUE(back.shaper && !back.cube);
        const auto source = ocioFileProcessor(src);
        const auto written = ocioFileProcessor(out);
        int skipped = 0;
        EXPECT_LE(worstOnLattice(source, written, r.domainMin, r.domainMax, 6, skipped), 1.0);
    }
}

} // namespace
