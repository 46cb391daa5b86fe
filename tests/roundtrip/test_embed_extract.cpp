// SPDX-License-Identifier: Apache-2.0
// Embed a patch, edit the image with known global functions, find and extract it again.
#include "OklabReference.h"
#include "RoundtripTestUtil.h"

#include "lut/interp/Sampler.h"
#include "lut/roundtrip/Embed.h"
#include "lut/roundtrip/Extract.h"
#include "lut/roundtrip/PatchFinder.h"
#include "lut/roundtrip/PatchReader.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace lut;
using namespace lut::rt;

namespace {

// Largest difference (8-bit steps) between a raw extracted LUT and the edit at its lattice points.
double latticeErrorSteps(const Lut3D& lut, const Edit& f) {
    double worst = 0.0;
    const int n = lut.size();
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::dvec3 want = f(glm::dvec3(r, g, b) / double(n - 1));
                const glm::vec3 got = lut.at(r, g, b);
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::fabs(got[c] - want[c]) * 255.0);
            }
    return worst;
}

struct Embedded {
    Image image;
    PatchPlacement placement;
};
EmbedOptions uniform16() {
    EmbedOptions o;
    o.target = LutPurpose::Raw; // implies the uniform 16^3 lattice
    o.scale = 2;
    return o;
}
Embedded embedded(int bitDepth = 8, EmbedOptions o = uniform16(), int width = 400,
                  int height = 260) {
    Embedded e{syntheticScreenshot(width, height, bitDepth), {}};
    o.bitDepth = bitDepth;
    e.placement = embedPatch(e.image.view(), o);
    return e;
}

} // namespace

TEST(Embed, FrameGeometryAndDefaults) {
    int w = 0, h = 0;
    patchFrameSize(LutLayout::Hald, 16, 2, w, h);
    EXPECT_EQ(w, 136);
    EXPECT_EQ(h, 136);
    patchFrameSize(LutLayout::Pilot, 16, 1, w, h);
    EXPECT_EQ(w, 260);
    EXPECT_EQ(h, 20);
    EXPECT_EQ(defaultPatchLayout(16), LutLayout::Hald);
    EXPECT_EQ(defaultPatchLayout(17), LutLayout::Pilot);
    EXPECT_THROW(patchFrameSize(LutLayout::Pilot, 4, 1, w, h), Error); // header does not fit
    EXPECT_THROW(patchFrameSize(LutLayout::Hald, 16, 0, w, h), Error);
    Image small(100, 100, 0.5f);
    EXPECT_THROW(embedPatch(small.view(), EmbedOptions{}), Error);
    // 16 is exact in 8 bits (255/15 = 17); 33 is not
    EXPECT_EQ(patchInputValue(5, 16, 8), 85.0f / 255.0f);
    EXPECT_NE(patchInputValue(5, 33, 8), 5.0f / 32.0f);
    EXPECT_EQ(patchInputValue(5, 33, 32), 5.0f / 32.0f);
}

TEST(Embed, NeutralPatchReadsBackAsIdentity) {
    for (int depth : {8, 16}) {
        auto e = embedded(depth);
        const FindResult f = findPatch(e.image.view());
        ASSERT_EQ(f.status, FindStatus::Found) << f.message;
        EXPECT_EQ(f.placement.frameX, e.placement.frameX);
        EXPECT_EQ(f.placement.frameY, e.placement.frameY);
        EXPECT_EQ(f.placement.size, 16);
        EXPECT_EQ(f.placement.scale, 2);
        EXPECT_EQ(f.placement.bitDepth, depth);
        const ExtractResult r = extractLut(e.image.view(), {});
        EXPECT_LT(r.lut.maxDeviationFromIdentity(), 1e-6f);
        EXPECT_TRUE(r.warnings.empty());
    }
}

TEST(Embed, SmashLatticeIsTheDefault) {
    auto e = embedded(8, EmbedOptions{});
    EXPECT_EQ(e.placement.lattice, PatchLattice::Smash);
    EXPECT_EQ(e.placement.size, kSmashLatticeSize);
    EXPECT_EQ(e.placement.layout, LutLayout::Pilot);
    EXPECT_EQ(e.placement.frameWidth, 296);
    EXPECT_EQ(e.placement.frameHeight, 32);
    // the lattice values: what the game shows for i/15 through a neutral LUT
    for (int i = 0; i < kSmashLatticeSize; ++i) {
        const double want =
            i == 11 ? 1.0 : srgbEnc(std::min(1.0, std::pow(1.3703 * i / 15.0, 2.2)));
        EXPECT_NEAR(patchInputValue(PatchLattice::Smash, i, 12, 32), want, 1e-6) << i;
        EXPECT_EQ(patchInputValue(PatchLattice::Smash, i, 12, 8),
                  fromUnorm8(toUnorm8(float(want))));
    }
    const FindResult f = findPatch(e.image.view());
    ASSERT_EQ(f.status, FindStatus::Found);
    EXPECT_EQ(f.placement.lattice, PatchLattice::Smash);
    // raw from a non-uniform lattice: interpolated, and a neutral stays neutral
    ExtractOptions o;
    o.target = LutPurpose::Raw;
    o.outputSize = 16;
    const ExtractResult r = extractLut(e.image.view(), o);
    EXPECT_LT(r.lut.maxDeviationFromIdentity(), 1e-5f);
    applyEdit(e.image, curvesEdit(), 8);
    EXPECT_LE(latticeErrorSteps(extractLut(e.image.view(), o).lut, curvesEdit()), 2.0);
}

TEST(Embed, EveryLayoutCornerAndScaleIsFound) {
    struct Case {
        LutLayout layout;
        int size, scale;
        PatchCorner corner;
    };
    const Case cases[] = {{LutLayout::Pilot, 8, 1, PatchCorner::TopRight},
                          {LutLayout::Unity, 7, 2, PatchCorner::BottomLeft},
                          {LutLayout::Smush, 9, 1, PatchCorner::BottomRight},
                          {LutLayout::Hald, 9, 3, PatchCorner::TopLeft},
                          {LutLayout::Hald, 16, 1, PatchCorner::BottomRight},
                          {LutLayout::Pilot, 17, 1, PatchCorner::TopLeft}};
    for (const auto& c : cases) {
        EmbedOptions o = uniform16();
        o.layout = c.layout;
        o.size = c.size;
        o.scale = c.scale;
        o.corner = c.corner;
        auto e = embedded(8, o);
        const FindResult f = findPatch(e.image.view());
        ASSERT_EQ(f.status, FindStatus::Found)
            << toString(c.layout) << " " << c.size << ": " << f.message;
        EXPECT_EQ(f.placement.layout, c.layout);
        EXPECT_EQ(f.placement.size, c.size);
        EXPECT_EQ(f.placement.frameX, e.placement.frameX);
        EXPECT_EQ(f.placement.frameY, e.placement.frameY);
        const auto edit = curvesEdit();
        applyEdit(e.image, edit, 8);
        const ExtractResult r = extractLut(e.image.view(), {});
        // 8-bit inputs j/(N-1) are rounded when N-1 does not divide 255: the output at the exact
        // lattice point is interpolated from the neighbours, so allow a little more than 1 step.
        EXPECT_LE(latticeErrorSteps(r.lut, edit), c.size == 16 ? 0.51 : 1.5) << toString(c.layout);
    }
}

TEST(Extract, KnownGlobalEditsAreRecoveredAtTheLattice8Bit) {
    const std::pair<const char*, Edit> edits[] = {
        {"curves", curvesEdit()},
        {"levels", levelsEdit()},
        {"saturation", saturationEdit()},
        {"gradient map", warmGradientMap()},
        {"inverting gradient map", invertingGradientMap()}};
    for (const auto& [name, edit] : edits) {
        auto e = embedded(8);
        applyEdit(e.image, edit, 8);
        const ExtractResult r = extractLut(e.image.view(), {});
        EXPECT_LE(latticeErrorSteps(r.lut, edit), 0.51) << name; // the 8-bit rounding of the edit
        EXPECT_FALSE(r.has(RoundtripWarning::NonGlobalEdit)) << name;
        EXPECT_FALSE(r.has(RoundtripWarning::ProfileChange)) << name;
        std::printf("[ measured ] %-24s expected error %.3f max / %.3f mean 8-bit steps\n", name,
                    r.expected.overall.maxSteps, r.expected.overall.meanSteps);
    }
}

TEST(Extract, SixteenBitIsTighter) {
    for (const auto& edit : {curvesEdit(), saturationEdit(), levelsEdit()}) {
        auto e = embedded(16);
        applyEdit(e.image, edit, 16);
        const ExtractResult r = extractLut(e.image.view(), {});
        EXPECT_LE(latticeErrorSteps(r.lut, edit), 0.01);
    }
}

TEST(Extract, OutputSizeResamplesTheEditExactly) {
    // A 33^3 output from the 16^3 patch of a per-channel curve: tetrahedral interpolation of a
    // separable function is exact along each axis, so the error is the curve's own between the
    // 16-lattice (bounded by the sub-lattice estimate).
    auto e = embedded(16);
    const auto edit = curvesEdit();
    applyEdit(e.image, edit, 16);
    ExtractOptions o;
    o.outputSize = 33;
    const ExtractResult r = extractLut(e.image.view(), o);
    ASSERT_EQ(r.lut.size(), 33);
    const double err = latticeErrorSteps(r.lut, edit);
    EXPECT_GT(err, 0.0);
    EXPECT_LE(err, r.expected.atLattice.maxSteps);
    std::printf("[ measured ] curves at 33^3 from a 16^3 patch: %.3f steps (sub-lattice %.3f, "
                "expected at the lattice %.3f)\n",
                err, r.subLattice.maxSteps, r.expected.atLattice.maxSteps);
}

TEST(Find, SurvivesCropAndMoveByWholePixels) {
    auto e = embedded(8);
    applyEdit(e.image, saturationEdit(), 8);
    const int moves[][2] = {{5, 3}, {-40, -17}, {7, -60}, {0, 0}};
    for (const auto& m : moves) {
        // crop (positive offsets cut the left/top) or move into a bigger canvas (negative)
        const Image moved = cropOrPad(e.image, m[0], m[1], 380 - m[0] / 2, 250 - m[1] / 3, 0.0f);
        const FindResult f = findPatch(moved.view());
        ASSERT_EQ(f.status, FindStatus::Found) << m[0] << "," << m[1];
        EXPECT_EQ(f.placement.frameX, e.placement.frameX - m[0]);
        EXPECT_EQ(f.placement.frameY, e.placement.frameY - m[1]);
        const ExtractResult r = extractLut(moved.view(), {});
        EXPECT_LE(latticeErrorSteps(r.lut, saturationEdit()), 0.51);
    }
}

TEST(Find, BackgroundOfTheMarkerColourDoesNotHideTheFrame) {
    // The first outer cell merges with a white (or black) background into one long run.
    for (float bg : {1.0f, 0.0f}) {
        Image img(300, 200, bg);
        for (int y = 0; y < 200; ++y)
            for (int x = 0; x < 300; ++x)
                img.pixel(x, y)[3] = 1.0f;
        EmbedOptions o;
        o.margin = 0;
        const auto p = embedPatch(img.view(), o);
        const Image moved = cropOrPad(img, -3, -2, 310, 210, bg);
        const FindResult f = findPatch(moved.view());
        ASSERT_EQ(f.status, FindStatus::Found);
        EXPECT_EQ(f.placement.frameX, p.frameX + 3);
        EXPECT_EQ(f.placement.frameY, p.frameY + 2);
    }
}

TEST(Find, NotFoundIsAnError) {
    Image plain = syntheticScreenshot();
    const FindResult f = findPatch(plain.view());
    EXPECT_EQ(f.status, FindStatus::NotFound);
    EXPECT_THROW(extractLut(plain.view(), {}), Error);
    // a frame whose header was painted over is not trusted
    auto e = embedded(8);
    for (int y = e.placement.frameY + 2; y < e.placement.frameY + 4; ++y)
        for (int x = e.placement.frameX + 2; x < e.placement.frameX + 40; ++x)
            e.image.pixel(x, y)[0] = 0.5f;
    EXPECT_EQ(findPatch(e.image.view()).status, FindStatus::NotFound);
    try {
        extractLut(e.image.view(), {});
        FAIL() << "expected an error";
    } catch (const Error& err) {
        EXPECT_NE(std::string(err.what()).find("no LUT patch found"), std::string::npos);
    }
}

TEST(Find, NonIntegerScaleIsReported) {
    auto e = embedded(8);
    applyEdit(e.image, curvesEdit(), 8);
    // 1.75x: cells of 3.5 pixels cannot be read
    const Image scaled = resizeBilinear(e.image, 1.75);
    const FindResult f = findPatch(scaled.view());
    EXPECT_EQ(f.status, FindStatus::Scaled);
    EXPECT_NEAR(f.observedPeriod, 3.5, 0.1);
    try {
        extractLut(scaled.view(), {});
        FAIL() << "expected an error";
    } catch (const Error& err) {
        EXPECT_NE(std::string(err.what()).find("resized"), std::string::npos);
    }
    // 1.5x: cells of exactly 3 pixels whose centres are unblended: read, with a warning
    const Image s15 = resizeBilinear(e.image, 1.5);
    const ExtractResult r = extractLut(s15.view(), {});
    EXPECT_TRUE(r.has(RoundtripWarning::Rescaled));
    EXPECT_EQ(r.placement.cell, 3);
    EXPECT_LE(latticeErrorSteps(r.lut, curvesEdit()), 0.51);
}

TEST(Find, WholeNumberUpscaleIsReadWithAWarning) {
    auto e = embedded(8);
    applyEdit(e.image, levelsEdit(), 8);
    const Image big = resizeNearest(e.image, 2);
    const ExtractResult r = extractLut(big.view(), {});
    EXPECT_TRUE(r.has(RoundtripWarning::Rescaled));
    EXPECT_EQ(r.placement.cell, 4);
    EXPECT_LE(latticeErrorSteps(r.lut, levelsEdit()), 0.51);
}

TEST(Checks, NoiseInsideBlocksIsANonGlobalEdit) {
    auto e = embedded(8);
    std::mt19937 rng(3);
    std::normal_distribution<float> noise(0.0f, 3.0f / 255.0f);
    for (int y = 0; y < e.image.height(); ++y)
        for (int x = 0; x < e.image.width(); ++x)
            for (int c = 0; c < 3; ++c)
                e.image.pixel(x, y)[c] =
                    std::clamp(e.image.pixel(x, y)[c] + noise(rng), 0.0f, 1.0f);
    quantize(e.image, 8);
    const ExtractResult r = extractLut(e.image.view(), {});
    EXPECT_TRUE(r.has(RoundtripWarning::NonGlobalEdit));
    // still close: the block average takes the noise down by 2
    EXPECT_LE(latticeErrorSteps(r.lut, [](glm::dvec3 c) { return c; }), 6.0);
}

TEST(Checks, BrushStrokeOnAScaleOnePatchIsANonGlobalEdit) {
    EmbedOptions o = uniform16();
    o.scale = 1;
    auto e = embedded(8, o);
    applyEdit(e.image, curvesEdit(), 8);
    // a soft brush stroke across the patch
    const int cx = e.placement.patchX() + 30, cy = e.placement.patchY() + 20;
    for (int y = cy - 6; y <= cy + 6; ++y)
        for (int x = cx - 6; x <= cx + 6; ++x) {
            const double d = std::hypot(x - cx, y - cy) / 6.0;
            if (d > 1.0)
                continue;
            float* p = e.image.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = float(p[c] * d + 0.8 * (1 - d));
        }
    quantize(e.image, 8);
    const ExtractResult r = extractLut(e.image.view(), {});
    EXPECT_TRUE(r.has(RoundtripWarning::NonGlobalEdit));
    EXPECT_GT(r.suspiciousEntries, 10u);
}

TEST(Checks, BlurIsANonGlobalEdit) {
    // A 3x3 blur leaves the centres of 4x4 cells intact (the frame is still found) but not the
    // block edges; at scales 1 and 2 it leaves no pure cell and the frame is not found at all.
    for (int scale : {1, 2, 4}) {
        EmbedOptions o = uniform16();
        o.scale = scale;
        auto e = embedded(8, o, 400, 300);
        Image blurred = e.image;
        for (int y = 1; y + 1 < e.image.height(); ++y)
            for (int x = 1; x + 1 < e.image.width(); ++x)
                for (int c = 0; c < 3; ++c) {
                    double acc = 0;
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx)
                            acc += e.image.pixel(x + dx, y + dy)[c];
                    blurred.pixel(x, y)[c] = float(acc / 9.0);
                }
        quantize(blurred, 8);
        const FindResult f = findPatch(blurred.view());
        if (scale < 4) {
            EXPECT_NE(f.status, FindStatus::Found) << scale;
            continue;
        }
        ASSERT_EQ(f.status, FindStatus::Found);
        const ExtractResult r = extractLut(blurred.view(), {});
        EXPECT_TRUE(r.has(RoundtripWarning::NonGlobalEdit)) << scale;
    }
}

TEST(Checks, ProfileConversionIsRecognised) {
    // sRGB -> gamma 2.2 profile conversion of the stored values, and a pure gamma change
    const Edit toGamma22 = [](glm::dvec3 c) {
        return glm::dvec3(std::pow(srgbDec(c.x), 1 / 2.2), std::pow(srgbDec(c.y), 1 / 2.2),
                          std::pow(srgbDec(c.z), 1 / 2.2));
    };
    const Edit gamma18 = [](glm::dvec3 c) {
        return glm::dvec3(std::pow(c.x, 2.2 / 1.8), std::pow(c.y, 2.2 / 1.8),
                          std::pow(c.z, 2.2 / 1.8));
    };
    for (const auto& edit : {toGamma22, gamma18}) {
        auto e = embedded(8);
        applyEdit(e.image, edit, 8);
        const ExtractResult r = extractLut(e.image.view(), {});
        EXPECT_TRUE(r.has(RoundtripWarning::ProfileChange));
        EXPECT_FALSE(r.has(RoundtripWarning::NonGlobalEdit));
    }
    auto e = embedded(8);
    applyEdit(e.image, gamma18, 8);
    EXPECT_NEAR(extractLut(e.image.view(), {}).gamma, 2.2 / 1.8, 0.01);
}

TEST(Checks, ClippingIsReported) {
    auto e = embedded(8);
    applyEdit(e.image, levelsEdit(0.3, 0.6, 1.0, 0.0, 1.0), 8);
    const ExtractResult r = extractLut(e.image.view(), {});
    EXPECT_TRUE(r.has(RoundtripWarning::Clipping));
    EXPECT_GT(r.clippedValues, 1000u);
    // a mild edit does not clip
    auto m = embedded(8);
    applyEdit(m.image, curvesEdit(), 8);
    EXPECT_FALSE(extractLut(m.image.view(), {}).has(RoundtripWarning::Clipping));
}

TEST(Extract, ExpectedErrorBoundsTheErrorBetweenLatticePoints) {
    // Truth: the edit at the centres of the patch cells, against the 16^3 patch interpolated.
    for (const auto& edit : {curvesEdit(), saturationEdit(), levelsEdit()}) {
        auto e = embedded(16);
        applyEdit(e.image, edit, 16);
        const FindResult f = findPatch(e.image.view());
        const PatchReading patch = readPatch(e.image.view(), f.placement);
        const ExtractResult r = extractLut(patch, {});
        const PatchFunction fn(patch.values, patch.axis);
        double worst = 0.0;
        for (int b = 0; b < 15; ++b)
            for (int g = 0; g < 15; ++g)
                for (int rr = 0; rr < 15; ++rr) {
                    const glm::dvec3 in = (glm::dvec3(rr, g, b) + 0.5) / 15.0;
                    const glm::vec3 got = fn(glm::vec3(in));
                    const glm::dvec3 want = edit(in);
                    for (int c = 0; c < 3; ++c)
                        worst = std::max(worst, std::fabs(got[c] - want[c]) * 255.0);
                }
        // an upper estimate, and not a wild one
        EXPECT_LE(worst, r.expected.overall.maxSteps);
        EXPECT_GE(worst, 0.1 * r.expected.overall.maxSteps);
        std::printf(
            "[ measured ] 16^3 patch between lattice points: true max %.3f steps, predicted %.3f\n",
            worst, r.expected.overall.maxSteps);
    }
}

TEST(PatchFunction, ExactOnTheLatticeAndDefinedEverywhere) {
    Lut3D v = Lut3D::identity(5);
    std::vector<float> axis = {0.0f, 0.2f, 0.5f, 0.7f, 1.0f}; // rectilinear
    for (int b = 0; b < 5; ++b)
        for (int g = 0; g < 5; ++g)
            for (int r = 0; r < 5; ++r)
                v.at(r, g, b) = glm::vec3(axis[r], axis[g], axis[b]) * 2.0f;
    const PatchFunction f(v, axis);
    EXPECT_EQ(f(glm::vec3(0.5f, 0.2f, 0.7f)), glm::vec3(1.0f, 0.4f, 1.4f));
    // a linear function on a rectilinear grid is reproduced between points too
    const glm::vec3 mid = f(glm::vec3(0.35f, 0.6f, 0.1f));
    EXPECT_NEAR(mid.x, 0.7f, 1e-6f);
    EXPECT_NEAR(mid.y, 1.2f, 1e-6f);
    EXPECT_NEAR(mid.z, 0.2f, 1e-6f);
    const glm::vec3 odd = f(glm::vec3(NAN, INFINITY, -1e30f));
    EXPECT_EQ(odd, glm::vec3(0.0f, 2.0f, 0.0f));
}

TEST(Find, NonFiniteAndExtremePixelsAreHarmless) {
    // NaN, infinities and huge values in the screenshot (a float EXR) neither hide the patch nor
    // leak into the LUT; an image made only of them has no patch.
    auto e = embedded(32);
    for (int y = 0; y < e.image.height(); y += 3)
        for (int x = 0; x < e.image.width(); x += 5) {
            if (x >= e.placement.frameX - 1 && x <= e.placement.frameX + e.placement.frameWidth &&
                y >= e.placement.frameY - 1 && y <= e.placement.frameY + e.placement.frameHeight)
                continue;
            float* p = e.image.pixel(x, y);
            p[0] = NAN;
            p[1] = (x / 5) % 2 ? INFINITY : -INFINITY;
            p[2] = 1e30f;
        }
    const ExtractResult r = extractLut(e.image.view(), {});
    EXPECT_LT(r.lut.maxDeviationFromIdentity(), 1e-6f);
    Image bad(200, 100, NAN);
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 200; ++x)
            if ((x + y) % 2)
                bad.pixel(x, y)[0] = INFINITY;
    EXPECT_EQ(findPatch(bad.view()).status, FindStatus::NotFound);
    EXPECT_EQ(findPatch(Image().view()).status, FindStatus::NotFound);
}

TEST(Extract, StrengthBlendsTheEditWithWhatWasThereBefore) {
    // --luma-strength 0.5 --chroma-strength 0.25 on a saturation edit: the LUT gives the float64
    // Oklab blend (tests/support/OklabReference.h) of each input with its edited colour, at the
    // lattice points and, within the printed expected error, between them.
    auto e = embedded(16);
    const auto edit = saturationEdit();
    applyEdit(e.image, edit, 16);
    ExtractOptions o;
    o.strength.luma = 0.5;
    o.strength.chroma = 0.25;
    const ExtractResult r = extractLut(e.image.view(), o);
    const auto want = [&](glm::dvec3 in) {
        return lut::test::strengthBlend(in, edit(in), 0.5, 0.25);
    };
    EXPECT_LE(latticeErrorSteps(r.lut, want), 0.05);
    EXPECT_GT(latticeErrorSteps(r.lut, edit), 5.0); // not the full edit
    const auto sampler = makeSampler(r.lut, Interpolation::Tetrahedral);
    double worst = 0.0;
    for (int b = 0; b < 15; ++b)
        for (int g = 0; g < 15; ++g)
            for (int rr = 0; rr < 15; ++rr) {
                const glm::dvec3 in = (glm::dvec3(rr, g, b) + 0.5) / 15.0;
                const glm::vec3 got = sampler->sample(glm::vec3(in));
                const glm::dvec3 w = want(in);
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::fabs(got[c] - w[c]) * 255.0);
            }
    EXPECT_LE(worst, r.expected.overall.maxSteps);
    std::printf("[ measured ] half-strength saturation between lattice points: true max %.3f "
                "steps, predicted %.3f\n",
                worst, r.expected.overall.maxSteps);
    bool noted = false;
    for (const auto& d : r.diagnostics)
        noted = noted || d.message.find("strength") != std::string::npos;
    EXPECT_TRUE(noted);
}
