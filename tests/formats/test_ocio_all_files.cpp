// SPDX-License-Identifier: Apache-2.0
// Every file of OpenColorIO's test data (tests/data/ocio/corpus: all of OpenColorIO's
// tests/data/files but its configs) through lutkit's two ways of sampling a foreign file --
// convert's reader (lut::formats::readLut, the table written as .clf) and bake (--lut FILE) --
// against OpenColorIO's unoptimised processor of the source built here (OPTIMIZATION_NONE, what
// OCIO_OPTIMIZATION_FLAGS=0 gives ociochecklut). OCIO 2.1's optimiser simplifies some chains
// wrongly (a Gamma pair of opposite styles, CDL nodes in a CTF, inverse LUT pairs); both paths
// must follow the faithful processor. Each written file is read back by OCIO (an independent
// reader) and compared with the source where the written table is exact: its lattice points or
// its 1D entries. A file OCIO refuses is refused by lutkit too. The .ccc/.cdl files are read with
// the CCC id "0" (the first correction), as convert --cccid 0 reads them.
#include "OcioTestUtil.h"

#include "lut/Error.h"
#include "lut/formats/Bake.h"
#include "lut/formats/OcioFiles.h"
#include "lut/formats/Registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <ostream>

namespace fs = std::filesystem;
using namespace lut::test;

namespace {

struct Case {
    std::string name; // path under the corpus folder
    std::string cccid;
};

// How gtest and ctest name a case: its path (not the bytes of the struct).
[[maybe_unused]] void PrintTo(const Case& c, std::ostream* os) {
    *os << c.name << (c.cccid.empty() ? "" : " --cccid " + c.cccid);
}

std::vector<Case> allFiles() {
    std::vector<Case> out;
    const fs::path root = dataPath("ocio/corpus");
    for (const auto& e : fs::recursive_directory_iterator(root)) {
        if (!e.is_regular_file())
            continue;
        const std::string rel = fs::relative(e.path(), root).string();
        if (rel == "LICENSE" || rel == "README.md")
            continue;
        const std::string ext = e.path().extension().string();
        out.push_back({rel, ext == ".ccc" || ext == ".cdl" ? "0" : ""});
    }
    std::sort(out.begin(), out.end(), [](const Case& a, const Case& b) { return a.name < b.name; });
    return out;
}

std::string workDir() {
    const std::string d = tempDir() + "-all";
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

double tolerance(double reference) {
    return 1e-5 * std::max(1.0, std::fabs(reference));
}

// The inputs where a table read or written by lutkit holds the source exactly: its lattice
// points (3D), its entries on the grey axis and along each channel (1D), a grid over the shaper's
// domain (shaper + table, both read exactly).
std::vector<glm::vec3> exactPoints(const lut::LutFile& f) {
    std::vector<glm::vec3> pts;
    if (f.cube && !f.shaper) {
        const lut::Lut3D& c = *f.cube;
        const int n = c.size(), step = std::max(1, (n - 1) / 16);
        for (int b = 0; b < n; b += step)
            for (int g = 0; g < n; g += step)
                for (int r = 0; r < n; r += step)
                    pts.push_back(c.latticeInput(r, g, b));
        return pts;
    }
    if (f.shaper && !f.cube) {
        const lut::Lut1D& s = *f.shaper;
        const int n = s.size(), step = std::max(1, (n - 1) / 256);
        for (int i = 0; i < n; i += step) {
            const glm::vec3 x = s.domainMin() + (s.domainMax() - s.domainMin()) *
                                                    (static_cast<float>(i) / float(n - 1));
            pts.push_back(x);
        }
        return pts;
    }
    const glm::vec3 lo = f.inputDomainMin(), hi = f.inputDomainMax();
    for (int b = 0; b < 9; ++b)
        for (int g = 0; g < 9; ++g)
            for (int r = 0; r < 9; ++r)
                pts.push_back(lo + (hi - lo) * glm::vec3(r, g, b) / 8.0f);
    return pts;
}

// Largest |written - source| over pts in units of tolerance(); non-finite references skipped.
double worstOver(const OCIO::ConstCPUProcessorRcPtr& source,
                 const OCIO::ConstCPUProcessorRcPtr& written, const std::vector<glm::vec3>& pts) {
    double worst = 0.0;
    for (const glm::vec3& x : pts) {
        const glm::vec3 want = ocioEval(source, x), got = ocioEval(written, x);
        for (int c = 0; c < 3; ++c)
            if (std::isfinite(want[c]))
                worst = std::max(worst, std::fabs(double(got[c]) - want[c]) / tolerance(want[c]));
    }
    return worst;
}

class OcioAllFiles : public ::testing::TestWithParam<Case> {};

} // namespace

TEST_P(OcioAllFiles, ConvertAndBakeFollowTheUnoptimisedProcessor) {
    const Case f = GetParam();
    const std::string src = corpusPath(f.name);
    OCIO::ConstCPUProcessorRcPtr source;
    std::string refusal;
    try {
        source = ocioFileProcessor(src, f.cccid);
    } catch (const std::exception& e) {
        refusal = e.what();
    }
    lut::FormatOptions ro;
    ro.size = 9; // a chain sampled at 9^3: the test compares at its lattice points
    if (!f.cccid.empty())
        ro.setAttribute(lut::formats::kOcioCccIdAttribute, f.cccid);
    if (!source) {
        // OpenColorIO refuses it: so does lutkit, with one line naming the file.
        try {
            (void)lut::formats::readLut(src, ro, "ocio");
            ADD_FAILURE() << "read a file OpenColorIO refuses (" << refusal << ")";
        } catch (const lut::Error& e) {
            EXPECT_NE(std::string(e.what()).find(src), std::string::npos) << e.what();
        }
        return;
    }
    const std::string dir = workDir();
    // convert: the reader's table, written as .clf (keeps a shaper and an input range).
    {
        SCOPED_TRACE("convert");
        const lut::LutFile read = lut::formats::readLut(src, ro, "ocio");
        const std::string out = dir + "/converted.clf";
        (void)lut::formats::writeLut(out, read, {});
        const lut::LutFile written = lut::formats::readLut(out);
        EXPECT_LE(worstOver(source, ocioFileProcessor(out), exactPoints(written)), 1.0)
            << "largest difference, in units of 1e-5 (relative above 1)";
    }
    // bake --lut FILE, 9^3 (or a 1D table), written as .clf.
    {
        SCOPED_TRACE("bake");
        const std::string out = dir + "/baked.clf";
        lut::formats::BakeOptions o;
        o.files = {{src, f.cccid, false}};
        o.cubeSize = 9;
        const lut::formats::BakeReport r = lut::formats::bake(out, o);
        const lut::LutFile written = lut::formats::readLut(out);
        EXPECT_LE(worstOver(source, ocioFileProcessor(out), exactPoints(written)), 1.0)
            << "largest difference, in units of 1e-5 (relative above 1)";
        EXPECT_TRUE(r.measuredFile) << r.readBackError;
    }
}

INSTANTIATE_TEST_SUITE_P(Files, OcioAllFiles, ::testing::ValuesIn(allFiles()),
                         [](const auto& info) {
                             std::string s = info.param.name;
                             for (auto& c : s)
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             return s;
                         });
