// SPDX-License-Identifier: Apache-2.0
// --target smash: the extracted LUT, put through the game's grading on the original scene, must
// show the edited screenshot. The game is simulated here in float64 from smash-pipeline.md
// (bloom off), independently of the library's code.
#include "RoundtripTestUtil.h"
#include "TestSupport.h"

#include "lut/formats/ImageIO.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/QuantizeLut.h"
#include "lut/pipeline/Transfer.h"
#include "lut/roundtrip/Embed.h"
#include "lut/roundtrip/Extract.h"
#include "lut/smash/SmashGrading.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <memory>

using namespace lut;
using namespace lut::rt;

namespace {

// Display-encoded frame the game shows for a linear scene pixel with its LUT (nullptr = neutral).
glm::dvec3 gameDisplay(const float* px, const Sampler* lut) {
    glm::dvec3 lin(px[0], px[1], px[2]), s;
    for (int c = 0; c < 3; ++c)
        s[c] = std::pow(std::max(lin[c], 0.0), 0.454545);
    glm::dvec3 l = s;
    if (lut)
        l = glm::dvec3(lut->sample(glm::vec3(s)));
    const double a = clamp01(px[3]);
    glm::dvec3 out;
    for (int c = 0; c < 3; ++c) {
        const double r = ((l[c] - s[c]) * 0.99961 + s[c]) * 1.3703;
        const double graded = std::pow(std::max(r, 0.0), 2.2);
        out[c] = srgbEnc(clamp01(lin[c] * (1.0 - a) + graded * a));
    }
    return out;
}

Image screenshot(const Image& scene, const Sampler* lut) {
    Image shot(scene.width(), scene.height(), 1.0f);
    for (int y = 0; y < scene.height(); ++y)
        for (int x = 0; x < scene.width(); ++x) {
            const glm::dvec3 d = gameDisplay(scene.pixel(x, y), lut);
            float* p = shot.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = fromUnorm8(toUnorm8(static_cast<float>(d[c])));
        }
    return shot;
}

Image loadScene() {
    const std::string path = lut::test::samplePath("sample_scene.exr");
    if (std::filesystem::exists(path))
        return formats::readImage(path).image;
    // a synthetic HDR scene: gradients up to 1.5 in linear light, all alpha 1
    Image img(320, 180, 1.0f);
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 320; ++x) {
            float* p = img.pixel(x, y);
            p[0] = 1.5f * x / 320.0f * (0.5f + 0.5f * y / 180.0f);
            p[1] = 0.8f * y / 180.0f;
            p[2] = 0.3f + 0.2f * std::sin(x * 0.05f);
        }
    return img;
}

struct Compare {
    double maxSteps = 0.0;
    double meanSteps = 0.0;
    std::size_t pixels = 0;
    double maxExcess = 0.0; // largest (our error - the oracle LUT's error) on one pixel value
};

// The best LUT a 16^3 game LUT can be for an edit with no patch in between: the edit evaluated
// exactly at the colours the unedited game showed for each lattice input (float64, from the spec).
Lut3D oracleLut(const Edit& edit) {
    Lut3D L(16);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                const glm::dvec3 s = glm::dvec3(r, g, b) / 15.0;
                glm::dvec3 q;
                for (int c = 0; c < 3; ++c)
                    q[c] = srgbEnc(clamp01(std::pow(s[c] * 1.3703, 2.2)));
                const glm::dvec3 e = edit(q);
                for (int c = 0; c < 3; ++c) {
                    const double t = std::pow(srgbDec(clamp01(e[c])), 1 / 2.2);
                    double l = (t / 1.3703 - s[c]) / 0.99961 + s[c];
                    if (e[c] >= 1.0 - 1e-6) // white: the neutral entry when it shows white too
                        l = std::max(l, s[c]);
                    L.at(r, g, b)[c] = float(std::clamp(l, 0.0, 1.0));
                }
            }
    return L;
}

// Game output with `lut` vs the edited screenshot, on alpha-1 pixels outside the patch frame.
Compare compareWithGame(const Image& scene, const Image& edited, const Lut3D& lut,
                        const PatchPlacement& p, const Lut3D* oracle = nullptr) {
    Lut3D shipped = lut;
    quantize8(shipped); // what the nutexb holds
    const auto sampler = makeSampler(shipped, Interpolation::Trilinear);
    std::unique_ptr<Sampler> best;
    if (oracle) {
        Lut3D o = *oracle;
        quantize8(o);
        best = makeSampler(o, Interpolation::Trilinear);
    }
    Compare c;
    double sum = 0.0;
    for (int y = 0; y < scene.height(); ++y)
        for (int x = 0; x < scene.width(); ++x) {
            if (scene.pixel(x, y)[3] < 1.0f)
                continue;
            if (x >= p.frameX && x < p.frameX + p.frameWidth && y >= p.frameY &&
                y < p.frameY + p.frameHeight)
                continue;
            const glm::dvec3 g = gameDisplay(scene.pixel(x, y), sampler.get());
            glm::dvec3 gb(0.0);
            if (best)
                gb = gameDisplay(scene.pixel(x, y), best.get());
            for (int ch = 0; ch < 3; ++ch) {
                // the game's frame is 8-bit too
                const double shown = fromUnorm8(toUnorm8(static_cast<float>(g[ch])));
                const double d = std::fabs(shown - edited.pixel(x, y)[ch]) * 255.0;
                c.maxSteps = std::max(c.maxSteps, d);
                sum += d;
                if (best) {
                    const double sb = fromUnorm8(toUnorm8(static_cast<float>(gb[ch])));
                    c.maxExcess =
                        std::max(c.maxExcess, d - std::fabs(sb - edited.pixel(x, y)[ch]) * 255.0);
                }
            }
            ++c.pixels;
        }
    c.meanSteps = c.pixels ? sum / (3.0 * c.pixels) : 0.0;
    return c;
}

} // namespace

TEST(SmashTarget, NoEditGivesTheNeutralLut) {
    const Image scene = loadScene();
    Image shot = screenshot(scene, nullptr);
    embedPatch(shot.view(), EmbedOptions{});
    ExtractOptions o;
    o.target = LutPurpose::Smash;
    const ExtractResult r = extractLut(shot.view(), o);
    ASSERT_EQ(r.lut.size(), 16);
    // Below the brighten step's clip point (s < 1/1.3703) the neutral LUT is the answer; above it
    // the screenshot only says "white", every entry from the one that shows white up shows it, and
    // the LUT keeps the neutral stage's own (the rule above white): the neutral LUT everywhere.
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int rr = 0; rr < 16; ++rr) {
                const int idx[3] = {rr, g, b};
                for (int c = 0; c < 3; ++c) {
                    const double s = idx[c] / 15.0;
                    EXPECT_NEAR(r.lut.at(rr, g, b)[c], s, 1e-4) << rr << " " << g << " " << b;
                }
            }
    EXPECT_FALSE(r.has(RoundtripWarning::OutOfRange));
}

TEST(SmashTarget, GameShowsTheEditedScreenshot) {
    const Image scene = loadScene();
    const std::pair<const char*, Edit> edits[] = {
        {"curves", curvesEdit()}, {"saturation", saturationEdit(1.3)}, {"levels", levelsEdit()}};
    for (const auto& [name, edit] : edits) {
        Image shot = screenshot(scene, nullptr);
        const PatchPlacement p = embedPatch(shot.view(), EmbedOptions{});
        applyEdit(shot, edit, 8);
        ExtractOptions o;
        o.target = LutPurpose::Smash;
        const ExtractResult r = extractLut(shot.view(), o);
        const Lut3D best = oracleLut(edit);
        const Compare c = compareWithGame(scene, shot, r.lut, p, &best);
        const Compare ob = compareWithGame(scene, shot, best, p);
        ASSERT_GT(c.pixels, 1000u);
        std::printf(
            "[ measured ] smash %-10s game vs edited: max %.2f mean %.3f 8-bit steps (%zu px); "
            "best 16^3 "
            "LUT: max %.2f mean %.3f; worst excess %.2f; predicted in-game %.2f max %.3f mean\n",
            name, c.maxSteps, c.meanSteps, c.pixels, ob.maxSteps, ob.meanSteps, c.maxExcess,
            r.expected.overall.maxSteps, r.expected.overall.meanSteps);
        // On every pixel within 2 steps of what the best possible 16^3 game LUT shows (the game's
        // own lattice cannot follow a clamped saturation between its points: 8 steps there)...
        EXPECT_LE(c.maxExcess, 2.0 + 1e-3) << name;
        EXPECT_LE(c.meanSteps, ob.meanSteps + 0.35) << name;
        // ...and within 2 steps outright for the edit the game lattice can follow.
        if (std::string(name) == "curves") {
            EXPECT_LE(c.maxSteps, 2.0 + 1e-3);
        }
        // The report is an honest bound for what the scene showed, up to the screenshot's own
        // 8-bit rounding (which a steep edit such as levels near its black point magnifies: the
        // best LUT shows the same there).
        EXPECT_LE(c.maxSteps, std::max(r.expected.overall.maxSteps, ob.maxSteps) + 2.0) << name;
    }
}

TEST(SmashTarget, ThePreviewPipelineShowsTheEditedScreenshotToo) {
    // The same check through the library's Smash grading (the preview pipeline's), not the
    // test's float64 model: the two agree, and the extracted LUT passes through both.
    const Image scene = loadScene();
    Image shot = screenshot(scene, nullptr);
    const PatchPlacement p = embedPatch(shot.view(), EmbedOptions{});
    const Edit edit = curvesEdit();
    applyEdit(shot, edit, 8);
    ExtractOptions o;
    o.target = LutPurpose::Smash;
    Lut3D shipped = extractLut(shot.view(), o).lut;
    quantize8(shipped);
    const auto sampler = makeSampler(shipped, Interpolation::Trilinear);
    double worst = 0.0, worstModel = 0.0;
    for (int y = 0; y < scene.height(); ++y)
        for (int x = 0; x < scene.width(); ++x) {
            const float* px = scene.pixel(x, y);
            if (px[3] < 1.0f)
                continue;
            if (x >= p.frameX && x < p.frameX + p.frameWidth && y >= p.frameY &&
                y < p.frameY + p.frameHeight)
                continue;
            const glm::vec3 lin = smashGradeMix(glm::vec3(px[0], px[1], px[2]), px[3], *sampler);
            const glm::dvec3 model = gameDisplay(px, sampler.get());
            for (int c = 0; c < 3; ++c) {
                const float shown =
                    fromUnorm8(toUnorm8(srgbEncode(std::clamp(lin[c], 0.0f, 1.0f))));
                worst = std::max(worst, std::fabs(shown - shot.pixel(x, y)[c]) * 255.0);
                worstModel = std::max(
                    worstModel,
                    std::fabs(srgbEncode(std::clamp(lin[c], 0.0f, 1.0f)) - model[c]) * 255.0);
            }
        }
    EXPECT_LE(worstModel, 0.05);
    EXPECT_LE(worst, 2.0 + 1e-3);
}

TEST(SmashTarget, OriginalLutIsCompensated) {
    // The stage already had a warm LUT; the modder only brightens the shadows a little.
    Lut3D warm = Lut3D::identity(16);
    for (auto& e : warm.entries())
        e = glm::vec3(std::min(1.0f, e.x * 1.05f + 0.02f), e.y, e.z * 0.92f);
    const auto warmSampler = makeSampler(warm, Interpolation::Trilinear);
    const Image scene = loadScene();
    Image shot = screenshot(scene, warmSampler.get());
    const PatchPlacement p = embedPatch(shot.view(), EmbedOptions{});
    const Edit lift = levelsEdit(0.0, 1.0, 1.15, 0.0, 1.0);
    applyEdit(shot, lift, 8);
    ExtractOptions o;
    o.target = LutPurpose::Smash;
    o.originalLut = &warm;
    const ExtractResult r = extractLut(shot.view(), o);
    const Compare c = compareWithGame(scene, shot, r.lut, p);
    EXPECT_LE(c.maxSteps, 2.0 + 1e-3);
    // ignoring the original LUT gets it wrong by far more
    o.originalLut = nullptr;
    const Compare wrong = compareWithGame(scene, shot, extractLut(shot.view(), o).lut, p);
    EXPECT_GT(wrong.maxSteps, 5.0);
}

TEST(SmashTarget, UnreachableColoursAreClampedAndReported) {
    // An inverting gradient map wants (almost) black for the brightest inputs: the brighten step
    // keeps 0.039% of s, so black there needs L slightly below 0. Clamped and counted; under half
    // an 8-bit step the clamp cannot change a stored entry, so it is no warning (it was one).
    const Image scene = loadScene();
    Image shot = screenshot(scene, nullptr);
    embedPatch(shot.view(), EmbedOptions{});
    applyEdit(shot, invertingGradientMap(), 8);
    ExtractOptions o;
    o.target = LutPurpose::Smash;
    const ExtractResult r = extractLut(shot.view(), o);
    EXPECT_FALSE(r.has(RoundtripWarning::OutOfRange));
    EXPECT_GT(r.clampedEntries, 0u);
    EXPECT_GT(r.clampedMax, 0.0);
    EXPECT_LT(r.clampedMax, 0.5 / 255.0);
    for (const auto& e : r.lut.entries())
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(e[c], 0.0f);
            EXPECT_LE(e[c], 1.0f);
        }
}

// The numbers behind the default patch (docs/roundtrip.md): how far the smash-target LUT from
// each patch lies from the best 16^3 LUT (the exact edit at the exact points), at the lattice.
TEST(SmashTarget, DefaultPatchIsTheMostAccurate) {
    struct Config {
        const char* name;
        PatchLattice lattice;
        int size;
        LutLayout layout;
        int scale;
    };
    const Config configs[] = {{"smash 12^3", PatchLattice::Smash, 12, LutLayout::Pilot, 2},
                              {"uniform 16^3", PatchLattice::Uniform, 16, LutLayout::Hald, 2},
                              {"uniform 25^3", PatchLattice::Uniform, 25, LutLayout::Hald, 1},
                              {"uniform 33^3", PatchLattice::Uniform, 33, LutLayout::Pilot, 1}};
    const std::pair<const char*, Edit> edits[] = {{"curves", curvesEdit()},
                                                  {"levels", levelsEdit()},
                                                  {"saturation", saturationEdit(1.3)},
                                                  {"gradient map", warmGradientMap()}};
    for (const auto& [ename, edit] : edits) {
        const Lut3D best = oracleLut(edit);
        double smashMax = 0.0, uniform16Max = 0.0;
        for (const auto& c : configs) {
            Image shot = syntheticScreenshot(1200, 260, 8);
            EmbedOptions eo;
            eo.lattice = c.lattice;
            eo.size = c.size;
            eo.layout = c.layout;
            eo.scale = c.scale;
            embedPatch(shot.view(), eo);
            applyEdit(shot, edit, 8);
            ExtractOptions o;
            o.target = LutPurpose::Smash;
            const ExtractResult r = extractLut(shot.view(), o);
            // compared where it matters: what the game displays at each lattice input (a LUT
            // step near black is worth far less than a display step there)
            ErrorAccumulator acc;
            for (int b = 0; b < 16; ++b)
                for (int g = 0; g < 16; ++g)
                    for (int rr = 0; rr < 16; ++rr)
                        for (int ch = 0; ch < 3; ++ch) {
                            const double s = (ch == 0 ? rr : ch == 1 ? g : b) / 15.0;
                            auto shown = [s](double l) {
                                return srgbEnc(clamp01(std::pow(
                                    std::max(((l - s) * 0.99961 + s) * 1.3703, 0.0), 2.2)));
                            };
                            acc.add(shown(r.lut.at(rr, g, b)[ch]), shown(best.at(rr, g, b)[ch]));
                        }
            const ErrorStats e = acc.result();
            std::printf("[ measured ] %-12s %-13s game display vs best LUT at the lattice: max "
                        "%.2f mean %.3f 8-bit "
                        "steps\n",
                        ename, c.name, e.maxSteps8(), e.meanSteps8());
            if (c.lattice == PatchLattice::Smash)
                smashMax = e.maxSteps8();
            if (c.size == 16)
                uniform16Max = e.maxSteps8();
        }
        EXPECT_LE(smashMax, uniform16Max + 0.05) << ename;
        EXPECT_LE(smashMax, 1.0) << ename; // the 8-bit rounding of the patch and of the edit
    }
}

TEST(SmashTarget, TheRefinementLowersTheMeanAndKeepsTheWhites) {
    // A per-channel gamma: the white region (inputs above the brighten step's clip) wants white
    // in every channel; an unguarded step once pushed entries there to 0.52 (67 steps dark).
    const Image scene = loadScene();
    Image shot = screenshot(scene, nullptr);
    const PatchPlacement p = embedPatch(shot.view(), EmbedOptions{});
    const Edit gamma = [](glm::dvec3 c) {
        return glm::dvec3(std::pow(c.x, 0.8), std::pow(c.y, 0.9), std::pow(c.z, 1.1));
    };
    applyEdit(shot, gamma, 8);
    ExtractOptions o;
    o.refine = true;
    const ExtractResult refined = extractLut(shot.view(), o);
    ASSERT_TRUE(refined.refined);
    o.refine = false;
    const ExtractResult exact = extractLut(shot.view(), o);
    const Compare cr = compareWithGame(scene, shot, refined.lut, p);
    const Compare ce = compareWithGame(scene, shot, exact.lut, p);
    std::printf("[ measured ] gamma edit, game vs edited screenshot: exact max %.2f mean %.3f, "
                "refined max %.2f mean %.3f 8-bit steps\n",
                ce.maxSteps, ce.meanSteps, cr.maxSteps, cr.meanSteps);
    EXPECT_LE(cr.meanSteps, ce.meanSteps + 0.02);
    EXPECT_LE(cr.maxSteps, ce.maxSteps + 1.0);
    EXPECT_LE(refined.modelError.meanSteps, refined.exactModelError.meanSteps);
    EXPECT_LE(refined.modelError.maxSteps, refined.exactModelError.maxSteps + 1.0);
}
