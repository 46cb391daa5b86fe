// SPDX-License-Identifier: Apache-2.0
// LUT strength in lightness and chroma (lut/ops/Strength.h) against a float64 Oklab written from
// Björn Ottosson's definition (tests/support/OklabReference.h: his published matrices both ways)
// and the sRGB transfer curve of IEC 61966-2-1.
#include "OklabReference.h"
#include "OpsTestUtil.h"

#include "lut/Error.h"
#include "lut/ops/Strength.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

using namespace lut;
using namespace lut::opstest;

namespace {

using Vec = std::array<double, 3>;
using lut::test::oklab;

Vec reference(glm::vec3 input, glm::vec3 entry, double tl, double tc) {
    const glm::dvec3 v = lut::test::strengthBlend(glm::dvec3(input), glm::dvec3(entry), tl, tc);
    return {v.x, v.y, v.z};
}

// A grade that moves lightness, chroma and hue: a contrast curve, a warm shift and a saturation
// boost, the kind whose luma and chroma parts a user may want separately.
glm::vec3 strongGrade(glm::vec3 c) {
    glm::vec3 t;
    for (int i = 0; i < 3; ++i)
        t[i] = c[i] * c[i] * (3.0f - 2.0f * c[i]);
    const float y = 0.2126f * t.r + 0.7152f * t.g + 0.0722f * t.b;
    const glm::vec3 sat = glm::vec3(y) + 1.6f * (t - glm::vec3(y));
    return glm::clamp(sat * glm::vec3(1.08f, 1.0f, 0.85f) + glm::vec3(0.03f, 0.0f, -0.02f), 0.0f,
                      1.0f);
}

StrengthOptions amounts(double luma, double chroma) {
    StrengthOptions o;
    o.luma = luma;
    o.chroma = chroma;
    return o;
}

// Largest |a - b| over the entries of one component range [c0, c1) of Oklab.
double worstOklab(const Lut3D& out, const std::function<glm::vec3(int, int, int)>& want, int c0,
                  int c1) {
    double worst = 0;
    const int n = out.size();
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const Vec o = oklab(glm::dvec3(out.at(r, g, b))),
                          w = oklab(glm::dvec3(want(r, g, b)));
                for (int c = c0; c < c1; ++c)
                    worst = std::max(worst, std::fabs(o[static_cast<std::size_t>(c)] -
                                                      w[static_cast<std::size_t>(c)]));
            }
    return worst;
}

} // namespace

TEST(Strength, ZeroIsTheNeutralLutToTheBit) {
    const Lut3D graded = lutFrom(17, strongGrade);
    StrengthOptions o;
    o.strength = 0;
    EXPECT_TRUE(sameBits(applyStrength(graded, o), Lut3D::identity(17)));
    EXPECT_TRUE(sameBits(applyStrength(graded, amounts(0, 0)), Lut3D::identity(17)));
    // The neutral of the LUT's own domain, and NaN entries do not matter.
    Lut3D wide = withNonFinite(randomLut(5));
    wide.setDomain(glm::vec3(-0.25f, 0.0f, 0.0f), glm::vec3(2.0f, 1.0f, 4.0f));
    const Lut3D out = applyStrength(wide, o);
    for (int b = 0; b < 5; ++b)
        for (int g = 0; g < 5; ++g)
            for (int r = 0; r < 5; ++r) {
                const glm::vec3 x = wide.latticeInput(r, g, b);
                ASSERT_EQ(std::memcmp(&out.at(r, g, b), &x, sizeof x), 0) << r << g << b;
            }
    EXPECT_EQ(out.domainMin(), wide.domainMin());
    EXPECT_EQ(out.domainMax(), wide.domainMax());
}

TEST(Strength, OneIsTheLutToTheBit) {
    Lut3D graded = withNonFinite(lutFrom(9, strongGrade));
    graded.setTitle("warm");
    graded.comments().push_back("made by hand");
    const Lut3D out = applyStrength(graded, {});
    EXPECT_TRUE(sameBits(out, graded)); // NaN entries included: nothing is touched
    EXPECT_EQ(out.title(), "warm");
    EXPECT_EQ(out.comments(), graded.comments());
    EXPECT_TRUE(sameBits(applyStrength(graded, amounts(1, 1)), graded));
    StrengthOptions o;
    o.strength = 0.3;
    o.luma = 1;
    o.chroma = 1;
    EXPECT_TRUE(sameBits(applyStrength(graded, o), graded));
}

TEST(Strength, LumaOnlyKeepsTheInputsChroma) {
    // Acceptance: Oklab a, b of the result within 0.5% (0.005) of the neutral's; the blend keeps
    // them to float rounding of the stored entries, so the bound asserted is 20x tighter.
    const Lut3D graded = lutFrom(17, strongGrade);
    ASSERT_GT(worstOklab(
                  graded, [&](int r, int g, int b) { return graded.latticeInput(r, g, b); }, 1, 3),
              0.05); // the grade does move chroma, so keeping it is not trivially true
    const Lut3D out = applyStrength(graded, amounts(1, 0));
    EXPECT_LT(worstOklab(
                  out, [&](int r, int g, int b) { return graded.latticeInput(r, g, b); }, 1, 3),
              2.5e-4);
    // ... and its lightness is the LUT's.
    EXPECT_LT(worstOklab(
                  out, [&](int r, int g, int b) { return graded.at(r, g, b); }, 0, 1),
              2.5e-4);
}

TEST(Strength, ChromaOnlyKeepsTheInputsLightness) {
    const Lut3D graded = lutFrom(17, strongGrade);
    ASSERT_GT(worstOklab(
                  graded, [&](int r, int g, int b) { return graded.latticeInput(r, g, b); }, 0, 1),
              0.05);
    const Lut3D out = applyStrength(graded, amounts(0, 1));
    EXPECT_LT(worstOklab(
                  out, [&](int r, int g, int b) { return graded.latticeInput(r, g, b); }, 0, 1),
              2.5e-4);
    EXPECT_LT(worstOklab(
                  out, [&](int r, int g, int b) { return graded.at(r, g, b); }, 1, 3),
              2.5e-4);
}

TEST(Strength, PartialAmountsMatchTheFloat64Blend) {
    const Lut3D lut = randomLut(9, 11);
    for (const auto& [tl, tc] : std::array<std::pair<double, double>, 4>{
             {{0.5, 0.5}, {0.25, 0.8}, {0.7, 0.0}, {1.5, 2.0}}}) {
        const Lut3D out = applyStrength(lut, amounts(tl, tc));
        double worst = 0;
        for (int b = 0; b < 9; ++b)
            for (int g = 0; g < 9; ++g)
                for (int r = 0; r < 9; ++r) {
                    const Vec w = reference(lut.latticeInput(r, g, b), lut.at(r, g, b), tl, tc);
                    for (int c = 0; c < 3; ++c)
                        worst = std::max(
                            worst, std::fabs(out.at(r, g, b)[c] - w[static_cast<std::size_t>(c)]));
                }
        EXPECT_LT(worst, 2e-6) << tl << " " << tc;
    }
    // strength alone sets both amounts; luma or chroma alone overrides its own.
    StrengthOptions o;
    o.strength = 0.4;
    o.chroma = 0.9;
    const Lut3D a = applyStrength(lut, o), b = applyStrength(lut, amounts(0.4, 0.9));
    EXPECT_TRUE(sameBits(a, b));
    o.chroma.reset();
    EXPECT_TRUE(sameBits(applyStrength(lut, o), applyStrength(lut, amounts(0.4, 0.4))));
}

TEST(Strength, HdrValuesAreKept) {
    // A LUT that brightens into HDR (x 4) and one with negative values: the partial blend lands
    // between input and entry, above 1 and below 0, never clipped.
    const Lut3D bright = lutFrom(5, [](glm::vec3 x) { return 4.0f * x + glm::vec3(0, 0, -0.2f); });
    const Lut3D out = applyStrength(bright, amounts(0.5, 0.5));
    const glm::vec3 white = out.at(4, 4, 4);
    const Vec want = reference(glm::vec3(1), bright.at(4, 4, 4), 0.5, 0.5);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(white[c], want[static_cast<std::size_t>(c)], 1e-5);
    EXPECT_GT(white.r, 1.5f);
    const glm::vec3 black = out.at(0, 0, 0);
    EXPECT_LT(black.b, 0.0f);
    EXPECT_NEAR(black.b, reference(glm::vec3(0), bright.at(0, 0, 0), 0.5, 0.5)[2], 1e-6);
}

TEST(Strength, NonFiniteEntriesGiveFiniteBlends) {
    const Lut3D bad = withNonFinite(randomLut(5));
    const Lut3D out = applyStrength(bad, amounts(0.5, 0.5));
    EXPECT_TRUE(allFinite(out));
    // NaN counts as 0 and -Inf as -65504: entry (0,0,0) is (NaN, 0.5, 0.5).
    const Vec want = reference(glm::vec3(0), glm::vec3(0.0f, 0.5f, 0.5f), 0.5, 0.5);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(out.at(0, 0, 0)[c], want[static_cast<std::size_t>(c)], 1e-6);
    for (const glm::vec3& e : out.entries())
        for (int c = 0; c < 3; ++c)
            EXPECT_LE(std::fabs(e[c]), 65504.0f);
}

TEST(Strength, LatticeSizesTwoAndSixtyFive) {
    for (const int n : {2, 65}) {
        const Lut3D lut = lutFrom(n, strongGrade);
        EXPECT_TRUE(sameBits(applyStrength(lut, amounts(0, 0)), Lut3D::identity(n)));
        const Lut3D out = applyStrength(lut, amounts(0.6, 0.3));
        ASSERT_EQ(out.size(), n);
        for (const int i : {0, n / 3, n - 1}) {
            const Vec w = reference(lut.latticeInput(i, n - 1 - i, i / 2),
                                    lut.at(i, n - 1 - i, i / 2), 0.6, 0.3);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(out.at(i, n - 1 - i, i / 2)[c], w[static_cast<std::size_t>(c)], 2e-6);
        }
    }
}

TEST(Strength, BadAmountsAreRefused) {
    const Lut3D lut = Lut3D::identity(2);
    StrengthOptions o;
    o.strength = std::nan("");
    EXPECT_THROW(applyStrength(lut, o), Error);
    EXPECT_THROW(applyStrength(lut, amounts(-0.1, 1)), Error);
    EXPECT_THROW(applyStrength(lut, amounts(1, 2.5)), Error);
    EXPECT_THROW(applyStrength(Lut3D(), {}), Error);
    try {
        applyStrength(lut, amounts(1, 3));
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("chroma"), std::string::npos) << e.what();
    }
}
