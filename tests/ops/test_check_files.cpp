// SPDX-License-Identifier: Apache-2.0
// The LUT check on files: the project's sample grade (its findings true by its own formula),
// every LUT fixture and OpenColorIO test file checked without a crash with finite figures,
// neutral fixtures without a finding; shapers and 1D files; a picture's colours; the thresholds
// file.
#include "CheckTestUtil.h"

#include "TestSupport.h"

#include "lut/formats/Registry.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace lut;
using namespace lut::opstest;
using namespace lut::checktest;

namespace {

// The sample grade as samples/tools/make_samples.cpp writes it, before its final clamp: warm
// highlights, teal shadows, +15% saturation, a contrast S-curve.
glm::dvec3 sampleGradeUnclamped(glm::dvec3 x) {
    const double luma = 0.2126 * x.r + 0.7152 * x.g + 0.0722 * x.b;
    const double warm[3] = {1.06, 1.0, 0.90}, teal[3] = {0.92, 1.02, 1.08};
    glm::dvec3 out;
    for (int i = 0; i < 3; ++i) {
        double v = x[i] * (luma * warm[i] + (1 - luma) * teal[i]);
        out[i] = luma + 1.15 * (v - luma); // clamped to [0, 1] next, then the S-curve
    }
    return out;
}

std::vector<std::string> lutFixtures() {
    std::vector<std::string> files;
    for (const char* dir : {"cube", "hald", "nutexb", "strip", "ocio", "ocio/corpus"})
        for (const auto& e : std::filesystem::directory_iterator(test::dataPath(dir)))
            if (e.is_regular_file())
                files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

bool finite(const CheckReport& r) {
    const CheckFigures& f = r.figures;
    for (double v : {f.worstFold, f.foldShare, f.worstFlat, f.worstStep, f.steepest,
                     f.worstHueShift, f.meanHueShift, f.skinDrift, f.gamutCoverage, f.worstRough,
                     f.totalVariationRatio, f.foldedShare, f.flatShare, f.neutralMaxDeltaE})
        if (!std::isfinite(v))
            return false;
    for (const CheckFinding& x : r.findings)
        if (!std::isfinite(x.size) || !std::isfinite(x.share) || !std::isfinite(x.input.x))
            return false;
    return true;
}

} // namespace

TEST(CheckFiles, SampleGradeOnlyClipsAndTheFormulaSaysSo) {
    formats::registerBuiltinFormats();
    const LutFile file = formats::readLut(test::samplePath("sample_grade.cube"), {});
    const CheckReport r = checkLut(file);
    SCOPED_TRACE(describe(r));
    EXPECT_NE(r.status(), CheckStatus::Fail);
    ASSERT_FALSE(r.findings.empty());
    const double cell = 1.0 / 32.0;
    for (const CheckFinding& f : r.findings) {
        ASSERT_EQ(f.kind, FindingKind::Clip) << f.text();
        // The formula clamps that channel within a cell of where the check says the clip is.
        bool clamped = false;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const glm::dvec3 x =
                        glm::clamp(glm::dvec3(f.input) + cell * glm::dvec3(dx, dy, dz), 0.0, 1.0);
                    const double v = sampleGradeUnclamped(x)[f.channel];
                    clamped = clamped || v > 1.0 + 0.5 / 255 || v < -0.5 / 255;
                }
        EXPECT_TRUE(clamped) << f.text();
    }
}

TEST(CheckFiles, EveryFixtureAndOcioTestFileWithoutACrash) {
    formats::registerBuiltinFormats();
    int checked = 0;
    for (const std::string& path : lutFixtures()) {
        LutFile file;
        try {
            file = formats::readLut(path, {});
        } catch (const Error&) {
            continue; // not a LUT lutkit reads (the formats' tests say why)
        }
        SCOPED_TRACE(path);
        CheckReport r;
        CheckOptions o;
        o.measureNeutral = checked % 8 == 0; // ΔE2000 over the lattice: the slowest part
        ASSERT_NO_THROW(r = checkLut(file, o));
        EXPECT_TRUE(finite(r)) << describe(r);
        ++checked;
        // The neutral fixtures have nothing to report.
        if (path.find("neutral") != std::string::npos) {
            EXPECT_TRUE(r.findings.empty()) << describe(r);
        }
    }
    EXPECT_GT(checked, 40);
}

TEST(CheckFiles, ShaperAndTableLocatedInTheFilesInput) {
    // A log2 shaper over [0, 16] into a table that folds red (as foldGrade) in its own
    // coordinates: the fold is reported at the input the shaper sends there.
    LutFile file;
    Lut1D shaper(1024);
    shaper.setDomain(glm::vec3(0.0f), glm::vec3(16.0f));
    for (int i = 0; i < shaper.size(); ++i) {
        const float x = 16.0f * i / (shaper.size() - 1);
        shaper[i] = glm::vec3(std::log2(1.0f + x) / std::log2(17.0f));
    }
    file.shaper = shaper;
    file.cube = lutFrom(33, foldGrade);
    CheckOptions o;
    o.measureNeutral = false;
    const CheckReport r = checkLut(file, o);
    SCOPED_TRACE(describe(r));
    const CheckFinding* fold = nullptr;
    for (const CheckFinding& f : r.findings)
        if (f.kind == FindingKind::FoldOver && (!fold || f.size > fold->size))
            fold = &f;
    ASSERT_NE(fold, nullptr);
    // In table coordinates the fold is at red 0.55 (CheckDefects); in the file's input it is
    // where the shaper reaches 0.55: 17^0.55 - 1.
    const double want = std::pow(17.0, 0.55) - 1.0;
    EXPECT_NEAR(fold->input.r, want, std::pow(17.0, 0.55 + 1.0 / 32) - 1.0 - want);
    EXPECT_TRUE(fold->region.contains(fold->input));
    EXPECT_FALSE(fold->region.contains({12.0f, 12.0f, 12.0f}));
}

TEST(CheckFiles, OneDimensionalCurves) {
    LutFile file;
    Lut1D curve(256);
    for (int i = 0; i < 256; ++i) {
        const float x = i / 255.0f;
        // Green folds back by 0.05 (12.75 steps) around 0.5; red and blue are the identity.
        const float g = x - 0.1f * static_cast<float>(smoothstep(0.45, 0.55, x));
        curve[i] = glm::vec3(x, g, x);
    }
    file.shaper = curve;
    const CheckReport r = checkLut(file);
    SCOPED_TRACE(describe(r));
    ASSERT_FALSE(r.findings.empty());
    const CheckFinding& f = r.findings.front();
    EXPECT_EQ(f.kind, FindingKind::FoldOver);
    EXPECT_EQ(f.channel, 1);
    // The formula's drop: peak to trough of x - 0.1 smoothstep(0.45, 0.55, x), in float64.
    double peak = -1, drop = 0;
    for (int i = 0; i <= 100000; ++i) {
        const double x = i / 100000.0, v = x - 0.1 * smoothstep(0.45, 0.55, x);
        peak = std::max(peak, v);
        drop = std::max(drop, peak - v);
    }
    EXPECT_NEAR(f.size, 255 * drop, 0.1 * 255 * drop);
    EXPECT_NEAR(f.input.g, 0.5, 1.0 / 255 * 4);
    EXPECT_TRUE(f.region.contains({0.0f, 0.5f, 0.0f}));
    EXPECT_FALSE(f.region.contains({0.5f, 0.1f, 0.5f}));
}

TEST(CheckFiles, OverAPicturesColours) {
    // A picture of greys and deep blues: the posterised blues show, the folded reds do not.
    Image shot(64, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) {
            float* p = shot.pixel(x, y);
            const bool blue = x >= 48;
            p[0] = blue ? 0.05f : x / 63.0f;
            p[1] = blue ? 0.05f : x / 63.0f;
            p[2] = blue ? 0.55f + 0.3f * y / 31.0f : x / 63.0f;
            p[3] = 1.0f;
        }
    const Lut3D lut = lutFrom(33, [](glm::vec3 x) { return posteriseGrade(foldGrade(x)); });
    CheckOptions o;
    o.measureNeutral = false;
    const CheckReport cube = checkLut(lut, o);
    const ImageView view = shot.view();
    o.image = &view;
    const CheckReport picture = checkLut(lut, o);
    SCOPED_TRACE(describe(picture));
    auto has = [](const CheckReport& r, FindingKind k) {
        return std::any_of(r.findings.begin(), r.findings.end(),
                           [k](const CheckFinding& f) { return f.kind == k; });
    };
    EXPECT_TRUE(has(cube, FindingKind::FoldOver));
    EXPECT_TRUE(has(cube, FindingKind::Step));
    EXPECT_FALSE(has(picture, FindingKind::FoldOver)); // no red in the picture
    ASSERT_TRUE(has(picture, FindingKind::Step));
    EXPECT_TRUE(picture.image);
    for (const CheckFinding& f : picture.findings) {
        if (f.kind != FindingKind::Step)
            continue;
        // Its share is of the picture's pixels: the blue quarter, at most.
        EXPECT_GT(f.share, 0.0);
        EXPECT_LE(f.share, 0.25 + 1e-6);
        // Its mask marks blue pixels only.
        const std::vector<std::uint8_t> mask = regionMask(f.region, view);
        int marked = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 64; ++x)
                if (mask[static_cast<std::size_t>(y * 64 + x)]) {
                    ++marked;
                    EXPECT_GE(x, 48);
                }
        EXPECT_GT(marked, 0);
    }
    EXPECT_EQ(picture.figures.imageOutsideDomain, 0.0);
}

TEST(CheckThresholdsFile, ReadsBothFormsAndNamesTheMistake) {
    const CheckThresholds t = parseCheckThresholds("# mine\n"
                                                   "fold-over = 1 3   # steps\n"
                                                   "\n"
                                                   "clip.warn = 5\n"
                                                   "HUE-SHIFT.fail=40\n",
                                                   "t.txt");
    EXPECT_EQ(t.foldOver.warn, 1.0);
    EXPECT_EQ(t.foldOver.fail, 3.0);
    EXPECT_EQ(t.clip.warn, 5.0);
    EXPECT_EQ(t.clip.fail, CheckThresholds{}.clip.fail);
    EXPECT_EQ(t.hueShift.fail, 40.0);
    auto error = [](const std::string& text) {
        try {
            parseCheckThresholds(text, "t.txt");
        } catch (const ParseError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error("fold-over = 1 3\nfoldover = 1 2\n"),
              "t.txt:2:1: unknown threshold 'foldover'; did you mean 'fold-over'? (found "
              "'foldover')");
    EXPECT_EQ(error("clip 1 2\n"), "t.txt:1:6: expected '=' after 'clip'");
    EXPECT_EQ(error("clip = 1\n"), "t.txt:1:9: expected a second number: the fail value");
    EXPECT_EQ(error("clip = x\n"), "t.txt:1:7: expected two numbers: the warn and the fail value");
    EXPECT_EQ(error("clip = 5 1\n"), "t.txt:1:1: 'clip': the fail value is below the warn value");
    EXPECT_EQ(error("clip = 1 2 3\n"), "t.txt:1:12: unexpected text (found '3')");
    // A stricter threshold turns a pass into a warning.
    CheckOptions o;
    o.measureNeutral = false;
    o.thresholds = parseCheckThresholds("steep = 0.9 0.95", "t.txt");
    const CheckReport r = checkLut(lutFrom(17, [](glm::vec3 x) { return x; }), o);
    EXPECT_EQ(r.check(CheckKind::Banding).status, CheckStatus::Fail) << describe(r);
}
