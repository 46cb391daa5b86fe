// SPDX-License-Identifier: Apache-2.0
// The LUT picture (lut/ops/Plot.h): assertions on pixels at places the layout documents. The
// pictures are also written under the build tree (build/test-tmp/...) to look at, never compared
// as files.
#include "OpsTestUtil.h"

#include "TestSupport.h"

#include "lut/formats/ImageIO.h"
#include "lut/ops/HeatMap.h"
#include "lut/ops/Plot.h"

#include <gtest/gtest.h>

using namespace lut;
using namespace lut::opstest;

namespace {

glm::vec3 pixelAt(const Image& img, int x, int y) {
    const float* p = img.pixel(x, y);
    return {p[0], p[1], p[2]};
}

// Writes into this test's folder under the build tree (emptied once per test).
void save(const Image& img, const std::string& name) {
    static std::string dir, forTest;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string current = std::string(info->test_suite_name()) + "." + info->name();
    if (forTest != current) {
        dir = test::tempDir();
        forTest = current;
    }
    formats::ImageWriteOptions o;
    o.alpha = false;
    formats::writeImage(dir + "/" + name, img, o);
}

// Separable curves along the neutral axis: R = t^2, G = t, B = sqrt(t) (so the three curves
// part), tetrahedral interpolation of which is 1D linear interpolation per channel.
glm::vec3 curvesGrade(glm::vec3 x) {
    return {x.r * x.r, x.g, std::sqrt(x.b)};
}

} // namespace

TEST(Plot, SlicesShowTheLutOutputWhereTheLayoutSays) {
    // An affine LUT interpolates exactly, so every slice pixel is the formula's value.
    auto f = [](glm::vec3 x) {
        return glm::vec3(0.8f * x.r + 0.1f, 0.5f * x.g + 0.4f * x.b, 1.0f - 0.9f * x.b);
    };
    const Plot p = plotLut(lutFrom(17, f));
    save(p.image, "affine_plot.png");
    for (int k = 0; k < 3; ++k) {
        const PlotRect r = p.layout.slices[static_cast<std::size_t>(k)];
        ASSERT_GT(r.width, 64);
        for (int y = 0; y < r.height; y += 13)
            for (int x = 0; x < r.width; x += 11) {
                const glm::vec3 in(static_cast<float>(x) / (r.width - 1),
                                   1.0f - static_cast<float>(y) / (r.height - 1),
                                   p.layout.sliceBlue[static_cast<std::size_t>(k)]);
                const glm::vec3 want = glm::clamp(f(in), 0.0f, 1.0f);
                const glm::vec3 got = pixelAt(p.image, r.x + x, r.y + y);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(got[c], want[c], 2e-6) << k << " " << x << "," << y;
            }
    }
}

TEST(Plot, NeutralAxisCurvesPassWhereTheFormulaSays) {
    const Plot p = plotLut(lutFrom(33, curvesGrade));
    save(p.image, "curves_plot.png");
    const PlotRect r = p.layout.curves;
    EXPECT_EQ(p.layout.curveMin, 0.0);
    EXPECT_EQ(p.layout.curveMax, 1.0);
    for (double t : {0.3, 0.5, 0.7}) {
        const int x = static_cast<int>(std::lround(r.x + t * (r.width - 1)));
        const double want[3] = {t * t, t, std::sqrt(t)};
        for (int c = 0; c < 3; ++c) {
            const double yf = r.y + (r.height - 1) * (1.0 - want[c]);
            const glm::vec3 px = pixelAt(p.image, x, static_cast<int>(std::lround(yf)));
            // The line's own colour dominates there: its channel is the brightest.
            const int other1 = (c + 1) % 3, other2 = (c + 2) % 3;
            EXPECT_GT(px[c], px[other1]) << "t " << t << " channel " << c;
            EXPECT_GT(px[c], px[other2]) << "t " << t << " channel " << c;
            EXPECT_GT(px[c], 0.8f);
        }
    }
    // A panel pixel far from every curve and grid line is the panel background.
    const glm::vec3 bg = pixelAt(p.image, r.x + 5 * r.width / 8, r.y + r.height - 12);
    EXPECT_LT(bg.r + bg.g + bg.b, 0.3f);
}

TEST(Plot, LatticeShowsBlackBelowWhiteAndTheRangeGrowsForHdr) {
    const Plot p = plotLut(Lut3D::identity(9));
    save(p.image, "identity_plot.png");
    const PlotRect r = p.layout.lattice;
    double whiteY = 0, blackY = 0;
    int whites = 0, blacks = 0, reds = 0;
    for (int y = r.y; y < r.y + r.height; ++y)
        for (int x = r.x; x < r.x + r.width; ++x) {
            const glm::vec3 c = pixelAt(p.image, x, y);
            if (c.r > 0.97f && c.g > 0.97f && c.b > 0.97f) {
                whiteY += y;
                ++whites;
            } else if (c.r > 0.97f && c.g < 0.03f && c.b < 0.03f) {
                ++reds;
            }
            // Black dots are drawn on a dark panel: find them as exact 0 with the panel being 0.07.
            if (c.r == 0.0f && c.g == 0.0f && c.b == 0.0f) {
                blackY += y;
                ++blacks;
            }
        }
    ASSERT_GT(whites, 5);
    ASSERT_GT(blacks, 5);
    EXPECT_GT(reds, 5);
    EXPECT_LT(whiteY / whites, blackY / blacks - 100); // white well above black
    // The title band has text.
    int ink = 0;
    for (int y = 10; y < 28; ++y)
        for (int x = 16; x < 200; ++x)
            ink += pixelAt(p.image, x, y).r > 0.5f;
    EXPECT_GT(ink, 50);

    Lut3D hdr = lutFrom(9, [](glm::vec3 x) { return 1.6f * x - 0.3f; });
    hdr.setTitle("HDR test");
    const Plot ph = plotLut(hdr);
    save(ph.image, "hdr_plot.png");
    EXPECT_EQ(ph.layout.curveMin, -0.5);
    EXPECT_EQ(ph.layout.curveMax, 1.5);
}

TEST(Plot, ExtremeLutsDrawFinitePictures) {
    for (const Lut3D& l : {withNonFinite(randomLut(9)), Lut3D::identity(2), randomLut(2)}) {
        const Plot p = plotLut(l);
        EXPECT_EQ(p.image.width(), 1356);
        for (float v : p.image.pixels())
            ASSERT_TRUE(std::isfinite(v) && v >= 0.0f && v <= 1.0f);
    }
    const Plot big = plotLut(lutFrom(65, smoothGrade), PlotOptions{17});
    save(big.image, "smooth_plot.png");
    // Heat map slices of two grades, to look at.
    std::vector<HeatMapSliceLayout> layout;
    save(diffHeatMapSlices(lutFrom(17, smoothGrade), lutFrom(17, curvesGrade), {}, 5, 128, &layout)
             .image,
         "heatmap_slices.png");
    EXPECT_EQ(layout.size(), 5u);
}
