// SPDX-License-Identifier: Apache-2.0
// The LUT check (lut/check/CheckLut.h) on LUTs with known defects built here from formulas
// (CheckTestUtil.h): each defect found, located within one lattice cell of where the formula puts
// it, sized within 10% of the formula's own figure (computed here in float64); and no finding on a
// smooth filmic grade or on neutral LUTs of every size from 2 to 65.
#include "CheckTestUtil.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace lut;
using namespace lut::opstest;
using namespace lut::checktest;

namespace {

constexpr int kN = 33;
constexpr double kCell = 1.0 / (kN - 1);

std::vector<const CheckFinding*> ofKind(const CheckReport& r, FindingKind kind) {
    std::vector<const CheckFinding*> out;
    for (const CheckFinding& f : r.findings)
        if (f.kind == kind)
            out.push_back(&f);
    return out;
}

const CheckFinding* largest(const std::vector<const CheckFinding*>& fs) {
    const CheckFinding* best = nullptr;
    for (const CheckFinding* f : fs)
        if (!best || f->size > best->size)
            best = f;
    return best;
}

double chebyshev(glm::dvec3 a, glm::dvec3 b) {
    const glm::dvec3 d = glm::abs(a - b);
    return std::max({d.x, d.y, d.z});
}

CheckReport check(const Lut3D& lut) {
    CheckOptions o;
    o.measureNeutral = false;
    return checkLut(lut, o);
}

} // namespace

TEST(CheckDefects, FoldOverOnTheRedAxisOnly) {
    const CheckReport r = check(lutFrom(kN, foldGrade));
    SCOPED_TRACE(describe(r));
    // The formula's fold, in float64: along red at g = b = 0 (w = 1, where it is deepest), from
    // the local peak before the falling part to the trough after it.
    double peak = -1.0, drop = 0.0, fallFrom = 0.0, fallTo = 0.0, at = 0.0;
    constexpr int kSteps = 200000;
    for (int i = 0; i <= kSteps; ++i) {
        const double x = double(i) / kSteps;
        const double v = foldRed(x, 0, 0);
        if (v > peak) {
            peak = v;
            at = x;
        }
        if (peak - v > drop) {
            drop = peak - v;
            fallFrom = at;
            fallTo = x;
        }
    }
    const double truthSteps = 255.0 * drop;
    ASSERT_GT(truthSteps, 15.0); // a real fold: the test means something
    const auto folds = ofKind(r, FindingKind::FoldOver);
    ASSERT_FALSE(folds.empty());
    for (const CheckFinding* f : folds)
        EXPECT_EQ(f->channel, 0) << "only red folds: " << f->text();
    const CheckFinding* worst = largest(folds);
    EXPECT_EQ(worst->severity, CheckStatus::Fail);
    EXPECT_NEAR(worst->size, truthSteps, 0.1 * truthSteps);
    EXPECT_EQ(worst->where, "along red");
    // Where: the middle of the falling part on the line g = b = 0, within one cell.
    EXPECT_LE(chebyshev(glm::dvec3(worst->input), {0.5 * (fallFrom + fallTo), 0, 0}), kCell);
    // The grey axis stays monotone (the formula: dR/dr = 1 - 0.25 (1 - t)^2 S'(t) > 0 there).
    EXPECT_EQ(r.figures.greyWorstFold, 0.0);
    for (const CheckFinding& f : r.findings)
        EXPECT_EQ(f.where.find("grey"), std::string::npos) << f.text();
    // The share: the volume where dR/dr < 0 in float64 (midpoint rule on a 100^3 grid) against
    // the share of lattice edges along red that fall; one lattice step of slack on either side
    // of the region along red.
    constexpr int kGrid = 100;
    double volume = 0.0, slack = 0.0;
    for (int bi = 0; bi < kGrid; ++bi)
        for (int gi = 0; gi < kGrid; ++gi) {
            const double g = (gi + 0.5) / kGrid, b = (bi + 0.5) / kGrid;
            int falling = 0;
            for (int ri = 0; ri < 4 * kGrid; ++ri) {
                const double x0 = double(ri) / (4 * kGrid), x1 = double(ri + 1) / (4 * kGrid);
                falling += foldRed(x1, g, b) < foldRed(x0, g, b) ? 1 : 0;
            }
            volume += falling / (4.0 * kGrid) / (kGrid * kGrid);
            slack += (falling ? 2.0 * kCell : 0.0) / (kGrid * kGrid);
        }
    double share = 0.0;
    for (const CheckFinding* f : folds)
        share += f->share;
    EXPECT_NEAR(share, volume, slack) << "volume " << volume;
    // Invertibility: folded cells, the worst one where the formula's red falls (within a cell).
    EXPECT_GT(r.figures.foldedShare, 0.0);
    const glm::vec3 folded = r.figures.worstFolded;
    bool falls = false;
    for (int d = -1; d <= 1; ++d) {
        const double x = folded.r + d * kCell;
        falls =
            falls || foldRed(x + 1e-4, folded.g, folded.b) < foldRed(x - 1e-4, folded.g, folded.b);
    }
    EXPECT_TRUE(falls) << folded.r << " " << folded.g << " " << folded.b;
}

TEST(CheckDefects, PosterisedBandInTheBlues) {
    const CheckReport r = check(lutFrom(kN, posteriseGrade));
    SCOPED_TRACE(describe(r));
    const auto steps = ofKind(r, FindingKind::Step);
    ASSERT_FALSE(steps.empty());
    const CheckFinding* worst = largest(steps);
    // The formula's levels are 0.1 apart where blueness is 1: 25.5 8-bit steps.
    EXPECT_NEAR(worst->size, 25.5, 2.55);
    EXPECT_EQ(worst->severity, CheckStatus::Fail);
    EXPECT_EQ(worst->channel, 2);
    // Inside the band (blue in [0.5, 0.9), red and green under 0.4), give or take one cell.
    const glm::vec3 x = worst->input;
    EXPECT_GE(x.b, 0.5 - kCell);
    EXPECT_LE(x.b, 0.9 + kCell);
    EXPECT_LE(std::max(x.r, x.g), 0.4 + kCell);
    // The colours it concerns: deep blues in the band, not the rest of the cube.
    EXPECT_TRUE(worst->region.contains({0.05f, 0.05f, 0.7f}));
    EXPECT_FALSE(worst->region.contains({0.8f, 0.8f, 0.7f}));
    EXPECT_FALSE(worst->region.contains({0.05f, 0.05f, 0.2f}));
    // Its blue never falls: no fold-over is reported.
    EXPECT_TRUE(ofKind(r, FindingKind::FoldOver).empty());
}

TEST(CheckDefects, TwentyDegreeHueTwistInTheYellows) {
    const CheckReport r = check(lutFrom(kN, twistGrade));
    SCOPED_TRACE(describe(r));
    const auto hues = ofKind(r, FindingKind::HueShift);
    ASSERT_EQ(hues.size(), 1u);
    const CheckFinding& f = *hues.front();
    EXPECT_NE(f.where.find("yellows"), std::string::npos);
    EXPECT_NEAR(f.size, kTwistDegrees, 0.1 * kTwistDegrees);
    EXPECT_NEAR(r.figures.worstHueShift, kTwistDegrees, 0.1 * kTwistDegrees);
    // Where: on the twist's ridge (Oklab hue 110) within one cell: the location moved round to
    // hue 110 at its own lightness and chroma is at most one lattice step away.
    const glm::dvec3 lab = oklab(glm::dvec3(f.input));
    const double chroma = std::hypot(lab.y, lab.z), h = kTwistCentre * std::numbers::pi / 180.0;
    const glm::dvec3 ridge = oklabToLinear({lab.x, chroma * std::cos(h), chroma * std::sin(h)});
    const glm::dvec3 ridgeSrgb(encode(ridge.x), encode(ridge.y), encode(ridge.z));
    EXPECT_LE(chebyshev(glm::dvec3(f.input), ridgeSrgb), kCell);
    EXPECT_TRUE(f.region.contains({0.9f, 0.85f, 0.1f})); // a yellow
    EXPECT_FALSE(f.region.contains({0.1f, 0.2f, 0.9f})); // a blue
    EXPECT_LT(std::fabs(r.figures.skinDrift), 2.0);      // skin (hue ~55) is outside the twist
}

TEST(CheckDefects, ClipOfFivePercentOfTheCube) {
    const CheckReport r = check(lutFrom(kN, clipGrade));
    SCOPED_TRACE(describe(r));
    const auto clips = ofKind(r, FindingKind::Clip);
    ASSERT_EQ(clips.size(), 1u);
    const CheckFinding& f = *clips.front();
    EXPECT_EQ(f.channel, 0);
    EXPECT_NEAR(f.share, 0.05, 0.005); // r above 0.95: 5% of the cube
    EXPECT_NEAR(r.figures.clippedShare[0], 0.05, 0.005);
    const double cut = 255.0 * (1.0 / 0.95 - 1.0); // what the clip cuts off at r = 1
    EXPECT_NEAR(f.size, cut, 0.1 * cut);
    EXPECT_NEAR(f.input.r, 0.95, kCell);         // where it starts
    EXPECT_NEAR(f.output.r, 1.0f, 1.06 * kCell); // within a cell of where the table reaches 1
    EXPECT_NE(f.severity, CheckStatus::Pass);
    EXPECT_EQ(r.figures.clippedShare[1], 0.0);
    EXPECT_EQ(r.figures.clippedShare[2], 0.0);
}

TEST(CheckDefects, NanInOneEntry) {
    for (int n : {2, 17}) {
        Lut3D lut = Lut3D::identity(n);
        const glm::ivec3 p = n == 2 ? glm::ivec3(1, 0, 1) : glm::ivec3(3, 4, 5);
        lut.at(p.x, p.y, p.z).g = std::nanf("");
        const CheckReport r = check(lut);
        SCOPED_TRACE(describe(r));
        const auto nans = ofKind(r, FindingKind::NonFinite);
        ASSERT_EQ(nans.size(), 1u);
        EXPECT_EQ(nans.front()->size, 1.0);
        EXPECT_EQ(nans.front()->severity, CheckStatus::Fail);
        const glm::vec3 want = lut.latticeInput(p.x, p.y, p.z);
        EXPECT_EQ(nans.front()->input, want);
        EXPECT_EQ(r.figures.nonFinite, 1u);
        EXPECT_EQ(r.status(), CheckStatus::Fail);
        EXPECT_TRUE(nans.front()->region.contains(want));
        for (const CheckFinding& f : r.findings) // every figure finite
            EXPECT_TRUE(std::isfinite(f.size) && std::isfinite(f.share)) << f.text();
    }
}

TEST(CheckDefects, SteepButSmoothGamma) {
    const CheckReport r = check(lutFrom(kN, gammaGrade));
    SCOPED_TRACE(describe(r));
    const auto steep = ofKind(r, FindingKind::Steep);
    ASSERT_FALSE(steep.empty());
    const CheckFinding* worst = largest(steep);
    // The table's slope across its first cell: (h^(1/2.4) - 0) / h output per input.
    const double slope = std::pow(kCell, 1 / 2.4) / kCell;
    EXPECT_NEAR(worst->size, slope, 0.1 * slope);
    EXPECT_NEAR(r.figures.steepest, slope, 0.1 * slope);
    EXPECT_EQ(worst->severity, CheckStatus::Warn); // smooth: steep, not broken
    // Where the formula is steeper than the warn threshold (d/dx x^(1/2.4) >= 4 below
    // x = (1 / 9.6)^(1 / (1 - 1 / 2.4))), within a cell.
    const double edge = std::pow(1.0 / 9.6, 1.0 / (1.0 - 1.0 / 2.4));
    const glm::vec3 x = worst->input;
    EXPECT_LE(std::min({x.r, x.g, x.b}), edge + kCell);
    // Smooth and monotone: no fold, step or flat run.
    EXPECT_TRUE(ofKind(r, FindingKind::FoldOver).empty());
    EXPECT_TRUE(ofKind(r, FindingKind::Step).empty());
    EXPECT_TRUE(ofKind(r, FindingKind::Flat).empty());
    EXPECT_NE(r.status(), CheckStatus::Fail);
}

TEST(CheckDefects, SmoothFilmicGradeHasNoFinding) {
    for (int n : {17, 33, 65}) {
        const CheckReport r = checkLut(lutFrom(n, filmicGrade));
        SCOPED_TRACE(describe(r));
        EXPECT_TRUE(r.findings.empty()) << n;
        EXPECT_EQ(r.status(), CheckStatus::Pass) << n;
    }
}

TEST(CheckDefects, NeutralOfEverySizeHasNoFinding) {
    for (int n = 2; n <= 65; ++n) {
        const CheckReport r = check(Lut3D::identity(n));
        EXPECT_TRUE(r.findings.empty()) << n << "\n" << describe(r);
        EXPECT_EQ(r.status(), CheckStatus::Pass) << n;
        EXPECT_EQ(r.figures.worstFold, 0.0) << n;
        EXPECT_NEAR(r.figures.steepest, 1.0, 1e-5) << n;
        EXPECT_EQ(r.figures.clippedShare[0] + r.figures.clippedShare[1] + r.figures.clippedShare[2],
                  0.0)
            << n;
        EXPECT_EQ(r.figures.foldedShare + r.figures.flatShare, 0.0) << n;
        EXPECT_LT(std::fabs(r.figures.worstHueShift), 0.5) << n;
    }
}

// Issue 40: a highlight clip followed by a colour matrix (min(1.4 x, 1), then a mixing matrix
// whose rows sum to 1) holds the colour constant past the clip, away from the output's bounds:
// the black-to-cyan ray was a "flat run" and banding failed. It is a clip of the input, reported
// as one (range), and banding passes.
TEST(CheckDefects, HighlightClipThenAMatrixIsAClipNotBanding) {
    const CheckReport r = check(lutFrom(kN, [](glm::vec3 x) {
        const glm::dvec3 y(std::min(1.4 * x.r, 1.0), std::min(1.4 * x.g, 1.0),
                           std::min(1.4 * x.b, 1.0));
        return glm::vec3(0.85 * y.r + 0.10 * y.g + 0.05 * y.b, 0.05 * y.r + 0.90 * y.g + 0.05 * y.b,
                         0.05 * y.r + 0.10 * y.g + 0.85 * y.b);
    }));
    SCOPED_TRACE(describe(r));
    EXPECT_EQ(r.check(CheckKind::Banding).status, CheckStatus::Pass);
    EXPECT_TRUE(ofKind(r, FindingKind::Flat).empty());
    EXPECT_FALSE(ofKind(r, FindingKind::Clip).empty());
    // A posterised band still fails banding (its flats are inside the lines).
    const CheckReport p = check(lutFrom(kN, posteriseGrade));
    EXPECT_NE(p.check(CheckKind::Banding).status, CheckStatus::Pass);
}
