// SPDX-License-Identifier: Apache-2.0
// fit: recover known LUTs from synthetic before/after pairs, then degrade the pairs.
#include "RoundtripTestUtil.h"
#include "TestSupport.h"

#include "lut/formats/ImageIO.h"
#include "lut/interp/Sampler.h"
#include "lut/roundtrip/Fit.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

using namespace lut;
using namespace lut::rt;

namespace {

// A smooth global edit with channel crosstalk (a LUT, not three curves).
Edit smoothEdit() {
    const Edit curves = curvesEdit();
    return [curves](glm::dvec3 c) {
        const glm::dvec3 k = curves(c);
        const double l = luma(k);
        return glm::dvec3(clamp01(0.9 * k.x + 0.1 * l + 0.02), clamp01(k.y),
                          clamp01(0.85 * k.z + 0.15 * l));
    };
}

Image randomColours(int w, int h, unsigned seed) {
    Image img(w, h, 1.0f);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = fromUnorm8(toUnorm8(u(rng)));
        }
    return img;
}

Image edited(const Image& before, const Edit& f, int bitDepth) {
    Image after = before;
    applyEdit(after, f, bitDepth);
    return after;
}

// Largest difference (8-bit steps) between a fitted LUT and the edit at its lattice points.
double latticeError(const Lut3D& lut, const Edit& f) {
    double worst = 0.0;
    const int n = lut.size();
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::dvec3 want = f(glm::dvec3(r, g, b) / double(n - 1));
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::fabs(lut.at(r, g, b)[c] - want[c]) * 255.0);
            }
    return worst;
}

void expectSane(const Lut3D& lut) {
    for (const auto& e : lut.entries())
        for (int c = 0; c < 3; ++c) {
            ASSERT_TRUE(std::isfinite(e[c]));
            ASSERT_GE(e[c], 0.0f);
            ASSERT_LE(e[c], 1.0f);
        }
}

} // namespace

TEST(Fit, RecoversAKnownLutFromADensePair) {
    const Image before = randomColours(256, 256, 1);
    const Edit f = smoothEdit();
    FitOptions o;
    o.size = 17;
    for (int depth : {32, 8}) {
        const FitResult r = fitLut(before.view(), edited(before, f, depth).view(), o);
        EXPECT_TRUE(r.converged);
        const double err = latticeError(r.lut, f);
        std::printf("[ measured ] fit 17^3 from 65k random colours (%d-bit): lattice max %.3f "
                    "steps, pixel rms %.3f "
                    "max %.3f, extrapolated %.3f%%, %d CG iterations\n",
                    depth, err, r.rmsSteps8, r.maxSteps8, 100 * r.extrapolatedShare, r.iterations);
        EXPECT_LE(err, 1.0) << depth;
        EXPECT_LE(r.rmsSteps8, depth == 8 ? 0.6 : 0.3);
        EXPECT_LT(r.extrapolatedShare, 0.01);
        EXPECT_TRUE(r.warnings.empty());
    }
}

TEST(Fit, IdentityPairGivesTheIdentity) {
    const Image before = randomColours(128, 128, 2);
    FitOptions o;
    o.size = 9;
    const FitResult r = fitLut(before.view(), before.view(), o);
    EXPECT_LT(r.lut.maxDeviationFromIdentity(), 0.5f / 255.0f);
}

TEST(Fit, FewColoursStayExactAndBounded) {
    // 12 flat colours: the system is singular without the ridge; the fit must hit the 12 colours,
    // stay finite and in range, and warn.
    Image before(120, 90, 1.0f);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.05f, 0.95f);
    std::vector<glm::vec3> palette(12);
    for (auto& p : palette)
        p = glm::vec3(u(rng), u(rng), u(rng));
    for (int y = 0; y < 90; ++y)
        for (int x = 0; x < 120; ++x) {
            const glm::vec3 c = palette[(x / 30) + 4 * (y / 30)];
            float* p = before.pixel(x, y);
            p[0] = c.x, p[1] = c.y, p[2] = c.z;
        }
    const Edit f = smoothEdit();
    const Image after = edited(before, f, 32);
    FitOptions o;
    o.size = 17;
    const FitResult r = fitLut(before.view(), after.view(), o);
    EXPECT_TRUE(r.has(RoundtripWarning::FewColours));
    EXPECT_TRUE(r.has(RoundtripWarning::LowCoverage));
    EXPECT_GT(r.extrapolatedShare, 0.99);
    EXPECT_TRUE(r.converged);
    EXPECT_LE(r.maxSteps8, 1.0);
    expectSane(r.lut);
    const auto s = makeSampler(r.lut, Interpolation::Trilinear);
    for (const auto& c : palette) {
        const glm::vec3 got = s->sample(c);
        const glm::dvec3 want = f(glm::dvec3(c));
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(got[ch], want[ch], 1.0 / 255.0);
    }
}

TEST(Fit, NoiseIsAveragedAway) {
    const Image before = randomColours(256, 256, 3);
    const Edit f = smoothEdit();
    Image after = edited(before, f, 32);
    std::mt19937 rng(9);
    std::normal_distribution<float> noise(0.0f, 3.0f / 255.0f);
    for (auto& v : after.pixels())
        v += noise(rng);
    for (int y = 0; y < after.height(); ++y)
        for (int x = 0; x < after.width(); ++x)
            after.pixel(x, y)[3] = 1.0f;
    quantize(after, 8);
    FitOptions o;
    o.size = 17;
    const FitResult r = fitLut(before.view(), after.view(), o);
    const double err = latticeError(r.lut, f);
    std::printf("[ measured ] fit with 3-step noise: lattice max %.3f steps, pixel rms %.3f\n", err,
                r.rmsSteps8);
    EXPECT_GT(r.rmsSteps8, 2.5); // the noise is in the data, not in the fit
    EXPECT_LT(r.rmsSteps8, 3.6);
    // single pixels are off by up to 12 steps; the lattice (about 16 pixels per cell, fewer at
    // the cube's corners) by a quarter of that
    EXPECT_LE(err, 4.0);
}

TEST(Fit, OutliersAreDownWeighted) {
    const Image before = randomColours(256, 256, 4);
    const Edit f = smoothEdit();
    Image after = edited(before, f, 8);
    // 5% of the pixels painted with unrelated colours (a brush stroke, a moved object)
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int y = 0; y < after.height(); ++y)
        for (int x = 0; x < after.width(); ++x)
            if (u(rng) < 0.05f)
                for (int c = 0; c < 3; ++c)
                    after.pixel(x, y)[c] = fromUnorm8(toUnorm8(u(rng)));
    FitOptions o;
    o.size = 17;
    const FitResult robust = fitLut(before.view(), after.view(), o);
    o.robust = false;
    const FitResult plain = fitLut(before.view(), after.view(), o);
    const double eRobust = latticeError(robust.lut, f), ePlain = latticeError(plain.lut, f);
    std::printf("[ measured ] fit with 5%% outliers: lattice max %.3f steps robust, %.3f plain\n",
                eRobust, ePlain);
    EXPECT_TRUE(robust.has(RoundtripWarning::Outliers));
    EXPECT_GT(robust.outlierPixels, 2000u);
    EXPECT_LE(eRobust, 3.0);
    EXPECT_LT(eRobust, 0.5 * ePlain);
}

TEST(Fit, NaturalImageWarnsAboutCoverage) {
    const std::string path = lut::test::samplePath("sample_scene.png");
    const Image before =
        std::filesystem::exists(path) ? formats::readImage(path).image : syntheticScreenshot();
    const Edit f = curvesEdit();
    const FitResult r = fitLut(before.view(), edited(before, f, 8).view());
    EXPECT_TRUE(r.has(RoundtripWarning::LowCoverage));
    EXPECT_LE(r.rmsSteps8, 0.7);
    EXPECT_LE(r.maxSteps8, 2.5);
    expectSane(r.lut);
    std::printf("[ measured ] fit 33^3 to the sample scene: rms %.3f max %.3f steps, %.2f%% "
                "extrapolated, %d CG "
                "iterations%s\n",
                r.rmsSteps8, r.maxSteps8, 100 * r.extrapolatedShare, r.iterations,
                r.converged ? "" : " (not converged)");
}

TEST(Fit, RejectsMismatchedAndDegenerateInput) {
    Image a(10, 10, 0.5f), b(11, 10, 0.5f);
    EXPECT_THROW(fitLut(a.view(), b.view()), Error);
    EXPECT_THROW(fitLut(Image().view(), Image().view()), Error);
    FitOptions o;
    o.size = 1;
    EXPECT_THROW(fitLut(a.view(), a.view(), o), Error);
    // NaN and infinities in the input are defined: treated as 0 / clamped, never spread
    Image n(8, 8, 0.5f), m(8, 8, 0.5f);
    n.pixel(1, 1)[0] = NAN;
    m.pixel(2, 2)[1] = INFINITY;
    m.pixel(3, 3)[2] = -1e30f;
    o.size = 5;
    const FitResult r = fitLut(n.view(), m.view(), o);
    expectSane(r.lut);
    EXPECT_TRUE(std::isfinite(r.rmsSteps8));
}

TEST(Fit, HeldOutErrorBoundsWhatOtherPixelsOfThePictureShow) {
    // The figure fit prints for colours it was not fitted to (a fit on 7/8 of the colours,
    // measured on the other 1/8) against the truth: the written LUT (fitted on all of them) on
    // another picture of the same kind (the synthetic screenshot at another size: other pixels,
    // the same colours' neighbourhood), in float64 against the exact edit stored 8-bit, as the
    // after image holds it. The residual over the fitted pixels is below that truth.
    const Image before = syntheticScreenshot(400, 260, 8);
    const Edit f = smoothEdit();
    FitOptions o;
    o.size = 17;
    const FitResult r = fitLut(before.view(), edited(before, f, 8).view(), o);
    ASSERT_GT(r.heldOutColours, 100u);
    const Image other = syntheticScreenshot(397, 263, 8);
    const auto sampler = makeSampler(r.lut, Interpolation::Trilinear);
    double truth = 0.0;
    for (int y = 0; y < other.height(); ++y)
        for (int x = 0; x < other.width(); ++x) {
            const float* p = other.pixel(x, y);
            const glm::vec3 got = sampler->sample(glm::vec3(p[0], p[1], p[2]));
            const glm::dvec3 want = f(glm::dvec3(p[0], p[1], p[2]));
            for (int c = 0; c < 3; ++c)
                truth = std::max(truth,
                                 std::fabs(got[c] - fromUnorm8(toUnorm8(float(want[c])))) * 255.0);
        }
    std::printf("[ measured ] fit 17^3: fitted pixels max %.3f rms %.3f; held out max %.3f rms "
                "%.3f (%zu colours); another picture's pixels max %.3f 8-bit steps\n",
                r.maxSteps8, r.rmsSteps8, r.heldOutMaxSteps8, r.heldOutRmsSteps8, r.heldOutColours,
                truth);
    EXPECT_GE(r.heldOutMaxSteps8, truth);
    EXPECT_GE(r.heldOutRmsSteps8, r.rmsSteps8);
}

TEST(Fit, TheSamePicturesGiveTheSameLutWhateverTheThreads) {
    // Issue 40: fit gave another LUT on every run (up to 2.8 steps apart): the normal equations
    // were summed in the order the threads finished. Now in one order: the same bytes with 1, 3
    // and all threads, and from two runs of the program.
    const Image before = randomColours(300, 200, 11);
    const Image after = edited(before, smoothEdit(), 8);
    FitOptions o;
    o.size = 17;
    o.nthreads = 1;
    const Lut3D one = fitLut(before.view(), after.view(), o).lut;
    for (int threads : {3, 0}) {
        o.nthreads = threads;
        const Lut3D many = fitLut(before.view(), after.view(), o).lut;
        ASSERT_EQ(many.entries(), one.entries()) << threads << " threads";
    }
    const std::string dir = rtDir();
    formats::ImageWriteOptions w;
    w.alpha = false;
    formats::writeImage(dir + "/before.png", syntheticScreenshot(640, 400, 8), w);
    Image shot = formats::readImage(dir + "/before.png").image;
    applyEdit(shot, smoothEdit(), 8);
    formats::writeImage(dir + "/after.png", shot, w);
    std::string bytes[2];
    for (int run = 0; run < 2; ++run) {
        const std::string out = dir + "/fit" + std::to_string(run) + ".cube";
        const auto r = lut::test::runCli("fit " + lut::test::shellQuoted(dir + "/before.png") +
                                         " " + lut::test::shellQuoted(dir + "/after.png") + " " +
                                         lut::test::shellQuoted(out));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        bytes[run] = lut::test::fileBytes(out);
    }
    EXPECT_FALSE(bytes[0].empty());
    EXPECT_EQ(bytes[0], bytes[1]);
}

// Issue 40: fit's printed maxima came from the pixels it sampled (every other row and column of a
// picture over 8 megapixels) read trilinearly: on the full-resolution screenshot it was fitted on
// the LUT was 13.72 steps off where it printed 6.22. Here a picture just over 8 megapixels whose
// after image has a local stroke on odd rows and columns only, on colours fit does not hold out
// (the hash of Fit.cpp, copied): the sampling and the held-out eighth both missed it. Both maxima
// now bound the truth over every pixel of the picture, read trilinearly and tetrahedrally.
TEST(Fit, PrintedMaximaBoundEveryPixelOfTheFittedPicture) {
    const int w = 2830, h = 2830; // 8.01 megapixels: fit samples every other row and column
    const Image before = randomColours(w, h, 40);
    Image after = edited(before, smoothEdit(), 8);
    auto heldOut = [](const float* a) {
        std::uint32_t key = 0;
        for (int c = 0; c < 3; ++c)
            key = (key << 8) | static_cast<std::uint32_t>(std::lround(a[c] * 255.0f));
        std::uint64_t k =
            (static_cast<std::uint64_t>(key) + 0x9E3779B97F4A7C15ull) * 0xBF58476D1CE4E5B9ull;
        k ^= k >> 31;
        return (k & 7u) == 0u;
    };
    for (int y = 1; y < 400; y += 2)
        for (int x = 1; x < 400; x += 2)
            if (!heldOut(before.pixel(x, y))) {
                float* p = after.pixel(x, y);
                for (int c = 0; c < 3; ++c)
                    p[c] = 1.0f - p[c];
            }
    FitOptions o;
    o.size = 17;
    const FitResult r = fitLut(before.view(), after.view(), o);
    double truth = 0.0;
    for (Interpolation m : {Interpolation::Trilinear, Interpolation::Tetrahedral}) {
        const auto s = makeSampler(r.lut, m);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const float* a = before.pixel(x, y);
                const float* b = after.pixel(x, y);
                const glm::vec3 got = s->sample(glm::vec3(a[0], a[1], a[2]));
                for (int c = 0; c < 3; ++c)
                    truth = std::max(truth, std::fabs(double(got[c]) - b[c]) * 255.0);
            }
    }
    std::printf("[ measured ] fit of an 8-megapixel picture with a stroke: truth %.2f, printed "
                "pixels max %.2f, held out max %.2f 8-bit steps\n",
                truth, r.maxSteps8, r.heldOutMaxSteps8);
    EXPECT_GE(r.maxSteps8, truth);
    EXPECT_GE(r.heldOutMaxSteps8, truth);
}
