// SPDX-License-Identifier: Apache-2.0
// Clear diagnoses: blur, sharpen, noise, brush strokes, a colour-profile conversion, a resize and
// a lossy save over the patch are each named as the likely cause, with the fix.
#include "RoundtripTestUtil.h"
#include "SavedAs.h"
#include "TruthOracle.h"

#include "lut/roundtrip/Embed.h"
#include "lut/roundtrip/Extract.h"
#include "lut/roundtrip/PatchFinder.h"
#include "lut/roundtrip/PatchReader.h"

#include <gtest/gtest.h>

#include <random>

using namespace lut;
using namespace lut::rt;

namespace {

// What an editor's filters do, written plainly.
Image boxBlur(const Image& src, int radius) {
    Image tmp = src, out = src;
    const int w = src.width(), h = src.height();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                double acc = 0.0;
                for (int k = -radius; k <= radius; ++k)
                    acc += src.pixel(std::clamp(x + k, 0, w - 1), y)[c];
                tmp.pixel(x, y)[c] = static_cast<float>(acc / (2 * radius + 1));
            }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                double acc = 0.0;
                for (int k = -radius; k <= radius; ++k)
                    acc += tmp.pixel(x, std::clamp(y + k, 0, h - 1))[c];
                out.pixel(x, y)[c] = static_cast<float>(acc / (2 * radius + 1));
            }
    return out;
}
Image sharpen(const Image& src, double amount) {
    const Image soft = boxBlur(src, 1);
    Image out = src;
    for (int y = 0; y < src.height(); ++y)
        for (int x = 0; x < src.width(); ++x)
            for (int c = 0; c < 3; ++c)
                out.pixel(x, y)[c] = static_cast<float>(clamp01(
                    src.pixel(x, y)[c] + amount * (src.pixel(x, y)[c] - soft.pixel(x, y)[c])));
    return out;
}
void addNoise(Image& img, double steps) {
    std::mt19937 rng(11);
    std::normal_distribution<double> n(0.0, steps / 255.0);
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            for (int c = 0; c < 3; ++c)
                img.pixel(x, y)[c] = static_cast<float>(clamp01(img.pixel(x, y)[c] + n(rng)));
}
// A soft round brush stroke of `colour` (opacity falling off over its last third).
void brush(Image& img, int cx, int cy, int radius, glm::dvec3 colour, double opacity) {
    for (int y = cy - radius; y <= cy + radius; ++y)
        for (int x = cx - radius; x <= cx + radius; ++x) {
            if (x < 0 || y < 0 || x >= img.width() || y >= img.height())
                continue;
            const double d = std::hypot(x - cx, y - cy) / radius;
            if (d >= 1.0)
                continue;
            const double a = opacity * std::clamp((1.0 - d) * 3.0, 0.0, 1.0);
            float* p = img.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = static_cast<float>(p[c] * (1.0 - a) + colour[c] * a);
        }
}

struct Edited {
    Image image;
    PatchPlacement placement;
};
Edited embeddedAndEdited(int scale = 0) {
    Edited e{syntheticScreenshot(kShotWidth, kShotHeight, 8), {}};
    EmbedOptions o;
    o.scale = scale;
    e.placement = embedPatch(e.image.view(), o);
    applyEdit(e.image, curvesEdit(), 8);
    return e;
}
std::string messages(const ExtractResult& r) {
    std::string all;
    for (const auto& d : r.diagnostics)
        all += d.message + "\n";
    return all;
}
bool mentions(const std::string& text, const char* word) {
    return text.find(word) != std::string::npos;
}

} // namespace

TEST(Diagnoses, ACleanEditHasNoCause) {
    const Edited e = embeddedAndEdited();
    const ExtractResult r = extractLut(e.image.view(), {});
    EXPECT_EQ(r.cause, EditCause::None);
    EXPECT_FALSE(r.has(RoundtripWarning::NonGlobalEdit));
}

TEST(Diagnoses, BlurIsNamedAndTheMiddlesStillRead) {
    Edited e = embeddedAndEdited();
    const Image blurred = boxBlur(e.image, 1);
    const ExtractResult r = extractLut(blurred.view(), {});
    EXPECT_EQ(r.cause, EditCause::Blur) << messages(r);
    EXPECT_TRUE(r.has(RoundtripWarning::NonGlobalEdit));
    EXPECT_TRUE(mentions(messages(r), "blur")) << messages(r);
    // the blocks' middles are clean at scale 8: the LUT is as good as without the blur
    const Truth t = smashTruth(r.lut, curvesEdit());
    EXPECT_LE(t.lattice.max, 1.5);
}

TEST(Diagnoses, ABlurredSmallPatchIsNotFoundAndTheBlurIsNamed) {
    Edited e = embeddedAndEdited(2);
    const Image blurred = boxBlur(e.image, 1);
    const FindResult f = findPatch(blurred.view());
    ASSERT_NE(f.status, FindStatus::Found);
    EXPECT_EQ(f.cause, EditCause::Blur) << f.message;
    EXPECT_TRUE(mentions(f.message, "blur")) << f.message;
    EXPECT_TRUE(mentions(f.message, "--scale 8")) << f.message;
}

TEST(Diagnoses, SharpenIsNamed) {
    Edited e = embeddedAndEdited();
    const Image sharp = sharpen(e.image, 0.8);
    const FindResult f = findPatch(sharp.view());
    ASSERT_EQ(f.status, FindStatus::Found);
    const PatchReading patch = readPatch(sharp.view(), f.placement);
    const BlockEvidence& ev = patch.blocks;
    const ExtractResult r = extractLut(patch, {});
    EXPECT_EQ(r.cause, EditCause::Sharpen)
        << messages(r) << "towards " << ev.towards << " border " << ev.borderSteps << " interior "
        << ev.interiorSteps << " chroma " << ev.chromaShare;
    EXPECT_TRUE(mentions(messages(r), "sharpen")) << messages(r);
}

TEST(Diagnoses, NoiseIsNamed) {
    Edited e = embeddedAndEdited();
    addNoise(e.image, 4.0);
    const ExtractResult r = extractLut(e.image.view(), {});
    EXPECT_EQ(r.cause, EditCause::Noise) << messages(r);
    EXPECT_TRUE(mentions(messages(r), "noise")) << messages(r);
    // heavy noise on small cells: not found, and named
    Edited small = embeddedAndEdited(2);
    addNoise(small.image, 14.0);
    const FindResult f = findPatch(small.image.view());
    if (f.status != FindStatus::Found) {
        EXPECT_EQ(f.cause, EditCause::Noise) << f.message;
    }
}

TEST(Diagnoses, BrushStrokesAreNamedWithWhereTheyAre) {
    {
        // a soft stroke: blocks along its rim are not uniform, all in one part of the patch
        Edited e = embeddedAndEdited();
        const PatchPlacement& p = e.placement;
        brush(e.image, p.patchX() + 300, p.patchY() + 48, 40, {0.9, 0.2, 0.2}, 0.8);
        const ExtractResult r = extractLut(e.image.view(), {});
        EXPECT_EQ(r.cause, EditCause::LocalEdit) << messages(r);
        EXPECT_TRUE(mentions(messages(r), "brush stroke")) << messages(r);
        EXPECT_TRUE(mentions(messages(r), "pixels (")) << messages(r);
    }
    {
        // opaque paint over whole blocks: each block uniform, but wrong for its neighbours
        Edited e = embeddedAndEdited();
        const PatchPlacement& p = e.placement;
        for (int y = p.patchY() + 3 * p.cell; y < p.patchY() + 6 * p.cell; ++y)
            for (int x = p.patchX() + 40 * p.cell; x < p.patchX() + 44 * p.cell; ++x) {
                float* px = e.image.pixel(x, y);
                px[0] = 0.95f;
                px[1] = 0.1f;
                px[2] = 0.6f;
            }
        const ExtractResult r = extractLut(e.image.view(), {});
        EXPECT_EQ(r.cause, EditCause::LocalEdit) << messages(r);
        EXPECT_TRUE(mentions(messages(r), "brush stroke")) << messages(r);
    }
}

TEST(Diagnoses, AProfileConversionIsNamed) {
    Edited e{syntheticScreenshot(kShotWidth, kShotHeight, 8), {}};
    embedPatch(e.image.view(), EmbedOptions{});
    // what converting from sRGB to a gamma 2.2 profile does to the stored values
    applyEdit(
        e.image,
        [](glm::dvec3 c) {
            return glm::dvec3(std::pow(srgbDec(c.x), 1 / 2.2), std::pow(srgbDec(c.y), 1 / 2.2),
                              std::pow(srgbDec(c.z), 1 / 2.2));
        },
        8);
    const ExtractResult r = extractLut(e.image.view(), {});
    EXPECT_TRUE(r.has(RoundtripWarning::ProfileChange)) << messages(r);
    EXPECT_TRUE(mentions(messages(r), "colour profile")) << messages(r);
}

TEST(Diagnoses, AResizeIsNamed) {
    const Edited e = embeddedAndEdited();
    const Image resized = resizeBilinear(e.image, 1.37);
    const FindResult f = findPatch(resized.view());
    ASSERT_NE(f.status, FindStatus::Found);
    EXPECT_TRUE(mentions(f.message, "resized")) << f.message;
    EXPECT_TRUE(mentions(f.message, "Undo the resize")) << f.message;
}

TEST(Diagnoses, ALossySaveIsNotALocalEdit) {
    const std::string dir = rtDir();
    const Edited e = embeddedAndEdited();
    const Image saved = savedAs(e.image, Storage::Jpeg420, dir, "shot");
    ExtractOptions o;
    o.fileChromaSubsampling = "4:2:0";
    const ExtractResult r = extractLut(saved.view(), o);
    EXPECT_FALSE(r.has(RoundtripWarning::NonGlobalEdit)) << messages(r);
    EXPECT_TRUE(r.cause == EditCause::None || r.cause == EditCause::Lossy) << toString(r.cause);
}
