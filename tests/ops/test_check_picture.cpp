// SPDX-License-Identifier: Apache-2.0
// The stress charts (lut/check/StressCharts.h) against the textbook HSV and HSL formulas, and the
// check's report picture (lut/check/CheckPicture.h): the AFTER charts are the LUT's output, and
// each finding is circled where its colour is. Pictures are written under the build tree to look
// at, never compared as files.
#include "CheckTestUtil.h"

#include "TestSupport.h"

#include "lut/check/CheckPicture.h"
#include "lut/check/StressCharts.h"
#include "lut/formats/ImageIO.h"

#include <gtest/gtest.h>

using namespace lut;
using namespace lut::opstest;
using namespace lut::checktest;

namespace {

glm::vec3 pixelAt(const Image& img, int x, int y) {
    const float* p = img.pixel(x, y);
    return {p[0], p[1], p[2]};
}

void save(const Image& img, const std::string& name) {
    formats::ImageWriteOptions o;
    o.alpha = false;
    o.bitDepth = 8;
    formats::writeImage(test::tempDir() + "/" + name, img, o);
}

// HSL -> RGB, the textbook sector form: chroma C = (1 - |2L - 1|) S, X = C (1 - |H/60 mod 2 - 1|).
glm::dvec3 hslToRgb(double h, double s, double l) {
    const double c = (1 - std::fabs(2 * l - 1)) * s;
    const double hp = std::fmod(h, 360.0) / 60.0;
    const double x = c * (1 - std::fabs(std::fmod(hp, 2.0) - 1));
    glm::dvec3 rgb = hp < 1   ? glm::dvec3(c, x, 0)
                     : hp < 2 ? glm::dvec3(x, c, 0)
                     : hp < 3 ? glm::dvec3(0, c, x)
                     : hp < 4 ? glm::dvec3(0, x, c)
                     : hp < 5 ? glm::dvec3(x, 0, c)
                              : glm::dvec3(c, 0, x);
    return rgb + (l - c / 2);
}

} // namespace

TEST(StressCharts, ColoursAreTheTextbookOnes) {
    const int w = 361, h = 101;
    for (int y = 0; y < h; y += 10)
        for (int x = 0; x < w; x += 12) {
            const double hue = 360.0 * x / (w - 1), v = double(y) / (h - 1);
            const glm::dvec3 hs = hsvToRgb(hue, 1.0 - v, 1.0);
            const glm::dvec3 hl = hslToRgb(hue, 1.0, 1.0 - v);
            const glm::vec3 a = stressChartColour(StressChart::HueSaturation, w, h, x, y);
            const glm::vec3 b = stressChartColour(StressChart::HueLightness, w, h, x, y);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(a[c], hs[c], 1e-5) << x << "," << y;
                EXPECT_NEAR(b[c], hl[c], 1e-5) << x << "," << y;
            }
            EXPECT_EQ(stressChartColour(StressChart::Grey, w, h, x, y),
                      glm::vec3(float(x) / (w - 1)));
        }
    // Slices: five squares at blue 0, 0.25, 0.5, 0.75, 1 with red right and green up.
    const Image s = stressChart(StressChart::Slices, 1064, 200);
    EXPECT_EQ(pixelAt(s, 0, 199), glm::vec3(0, 0, 0));
    EXPECT_EQ(pixelAt(s, 199, 0), glm::vec3(1, 1, 0));
    EXPECT_EQ(pixelAt(s, 4 * 213, 199), glm::vec3(0, 0, 1));
    EXPECT_EQ(pixelAt(s, 205, 100), glm::vec3(0)); // the gap
    // A colour is found where the chart shows it.
    const auto at = locateInChart(StressChart::HueLightness, w, h, {1.0f, 0.5f, 0.0f}, 0.02f);
    ASSERT_TRUE(at.has_value());
    const glm::vec3 there = stressChartColour(StressChart::HueLightness, w, h, at->x, at->y);
    EXPECT_LE(glm::length(there - glm::vec3(1.0f, 0.5f, 0.0f)), 0.03f);
    EXPECT_FALSE(locateInChart(StressChart::HueSaturation, w, h, {0.2f, 0.2f, 0.2f}, 0.02f));
    save(stressChartSheet(800), "sheet.png");
}

TEST(CheckPicture, AfterIsTheLutAndFindingsAreCircledWhereTheirColourIs) {
    // An affine LUT interpolates exactly: every AFTER pixel is the formula's value (clamped).
    auto affine = [](glm::vec3 x) {
        return glm::vec3(0.8f * x.r + 0.1f, 0.5f * x.g + 0.4f * x.b, 1.0f - 0.9f * x.b);
    };
    LutFile file;
    file.cube = lutFrom(17, affine);
    CheckReport report = checkLut(file);
    report.findings.clear(); // no circles over the charts
    const CheckPicture p = drawCheckReport(file, report, "affine.cube");
    save(p.image, "affine_check.png");
    for (int row = 0; row < 6; ++row) {
        const auto& before = p.layout.before[row];
        const auto& after = p.layout.after[row];
        ASSERT_GT(after.width, 100);
        ASSERT_EQ(before.width, after.width);
        for (int y = 0; y < after.height; y += 7)
            for (int x = 0; x < after.width; x += 29) {
                const glm::vec3 in = pixelAt(p.image, before.x + x, before.y + y);
                const float gain = row == 1 ? 4.0f : 1.0f; // the shadows are shown 4x brighter
                const glm::vec3 want = glm::clamp(affine(in / gain) * gain, 0.0f, 1.0f);
                const glm::vec3 got = pixelAt(p.image, after.x + x, after.y + y);
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(got[c], want[c], 2e-5) << row << " " << x << "," << y;
            }
    }
    // The folded LUT: its worst finding is circled, and the chart colour under each circle is
    // within the charts' tolerance of the finding's colour.
    LutFile fold;
    fold.cube = lutFrom(33, foldGrade);
    const CheckReport fr = checkLut(fold);
    const CheckPicture fp = drawCheckReport(fold, fr, "fold.cube");
    save(fp.image, "fold_check.png");
    int marks = 0;
    const StressChart charts[6] = {StressChart::Grey,          StressChart::Grey,
                                   StressChart::HueSaturation, StressChart::HueLightness,
                                   StressChart::Skin,          StressChart::Slices};
    for (const auto& m : fp.layout.marks) {
        const glm::vec3 want = fr.findings[static_cast<std::size_t>(m.finding - 1)].input;
        const auto& r = fp.layout.after[m.row];
        glm::vec3 chart = stressChartColour(charts[m.row], r.width, r.height, m.x - r.x, m.y - r.y);
        if (m.row == 1)
            chart *= 0.25f; // the shadows row: input 0..0.25
        const glm::vec3 d = glm::abs(chart - want);
        EXPECT_LE(std::max({d.x, d.y, d.z}), m.row == 5 ? 0.13f : 0.04f)
            << "finding " << m.finding << " row " << m.row;
        marks += m.finding == 1 ? 1 : 0;
    }
    EXPECT_GE(marks, 2); // the fold at (0.55, 0, 0): hue x lightness and the blue-0 slice
}
