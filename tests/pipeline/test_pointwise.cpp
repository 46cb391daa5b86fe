// SPDX-License-Identifier: Apache-2.0
// A pointwise pipeline on runs of pixels (Pipeline::runPixels, what a streamed preview runs) gives
// run()'s frame bit for bit, whatever the runs' lengths and wherever they start; the preview's
// preparation in one pass (decode and undo together, by table for 8-bit codes) gives what the
// decode and then smashUngrade give.
#include "PipelineTestUtil.h"

#include "lut/pipeline/Pipeline.h"
#include "lut/pipeline/PreviewPlan.h"
#include "lut/pipeline/PreviewPreparation.h"
#include "lut/pipeline/Transfer.h"
#include "lut/smash/SmashGrading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

using namespace lut;
using namespace lut::test;

namespace {

bool bitEqual(const Image& a, const Image& b, std::string* where = nullptr) {
    if (a.pixels().size() != b.pixels().size())
        return false;
    for (std::size_t i = 0; i < a.pixels().size(); ++i)
        if (std::memcmp(&a.pixels()[i], &b.pixels()[i], sizeof(float)) != 0) {
            if (where)
                *where = "value " + std::to_string(i) + ": " + std::to_string(a.pixels()[i]) +
                         " vs " + std::to_string(b.pixels()[i]);
            return false;
        }
    return true;
}

// A frame with what a stage may treat apart: HDR values, negatives, NaN and infinities (colour
// and alpha), alpha 0, partial and 1, and an odd width (SIMD tails inside every row).
Image hostileFrame() {
    Image f = makeScene(37, 11, 5, 8.0f);
    f.pixel(3, 2)[0] = std::numeric_limits<float>::quiet_NaN();
    f.pixel(4, 2)[1] = std::numeric_limits<float>::infinity();
    f.pixel(5, 2)[2] = -std::numeric_limits<float>::infinity();
    f.pixel(6, 2)[3] = std::numeric_limits<float>::quiet_NaN();
    f.pixel(7, 3)[0] = -0.25f;
    for (int x = 0; x < 37; ++x) {
        f.pixel(x, 5)[3] = 0.0f; // a row the grading leaves alone (fused display only)
        f.pixel(x, 6)[3] = x % 3 == 0 ? 0.0f : 1.0f;
    }
    return f;
}

// runPixels over the frame's pixels in runs of the given lengths, cycling (runs cross rows).
Image byRuns(const Pipeline& p, const Image& frame, const std::vector<std::size_t>& lengths) {
    Image out = frame;
    const std::size_t total = static_cast<std::size_t>(out.width()) * out.height();
    std::size_t at = 0, k = 0;
    while (at < total) {
        const std::size_t n = std::min(lengths[k++ % lengths.size()], total - at);
        p.runPixels(out.data() + 4 * at, n);
        at += n;
    }
    return out;
}

void expectRunsAreTheFrame(Pipeline p, const std::string& what) {
    ASSERT_TRUE(p.isPointwise()) << what;
    const Image frame = hostileFrame();
    Image want = frame;
    p.run(want.view());
    for (const auto& lengths : std::vector<std::vector<std::size_t>>{
             {1}, {7}, {64}, {37}, {100, 3, 65}, {static_cast<std::size_t>(37 * 11)}}) {
        std::string where;
        EXPECT_TRUE(bitEqual(byRuns(p, frame, lengths), want, &where))
            << what << ", runs of " << lengths[0] << ": " << where;
    }
}

} // namespace

TEST(Pointwise, RunsOfPixelsGiveTheFrameBitForBit) {
    const auto warm = std::make_shared<const Lut3D>(makeWarmLut(17));
    {
        PipelineSettings s; // the game's chain on a screenshot: no bloom (grading + fused sRGB)
        s.bloom = false;
        s.lut = warm;
        expectRunsAreTheFrame(Pipeline(s), "smash, no bloom");
    }
    {
        PipelineSettings s; // the lut stage between grading and display: no fusion
        s.bloom = false;
        s.lut = warm;
        s.enable = {"lut", "exposure"};
        s.assignments = {"exposure.stops=0.5"};
        expectRunsAreTheFrame(Pipeline(s), "smash + lut + exposure");
    }
    {
        PipelineSettings s; // display gamma (not fused), tone mapping
        s.preset = Preset::Pilot;
        s.bloom = false;
        s.lut = warm;
        s.interpolation = Interpolation::Tetrahedral;
        expectRunsAreTheFrame(Pipeline(s), "filmic, no bloom");
    }
    {
        PipelineSettings s; // the LUT on stored values, nothing after (apply-like)
        s.preset = Preset::None;
        s.enable = {"lut"};
        s.disable = {"display"};
        expectRunsAreTheFrame(Pipeline(s), "none + identity lut (clamps)");
        s.lut = warm;
        expectRunsAreTheFrame(Pipeline(s), "none + lut");
    }
}

TEST(Pointwise, EveryStageThatSaysPointwiseIs) {
    // A stage that says pointwise() alone in a pipeline, with settings that make it work: runs
    // of pixels give the frame (a stage whose pixels depended on their position or neighbours
    // would differ between runs of 1 pixel and the frame).
    const auto warm = std::make_shared<const Lut3D>(makeWarmLut(9));
    int pointwise = 0;
    for (const auto& name : stageNames()) {
        PipelineSettings s;
        s.preset = Preset::None;
        s.lut = warm;
        s.enable = {name};
        s.assignments = {"exposure.stops=-0.7"};
        Pipeline p(s);
        if (!p.find(name)->pointwise())
            continue;
        ++pointwise;
        expectRunsAreTheFrame(std::move(p), name);
    }
    EXPECT_EQ(pointwise, 6); // sanitize, exposure, tonemap, smash-grade, lut, display
}

TEST(Pointwise, StagesThatNeedTheFrameAreNotPointwise) {
    EXPECT_FALSE(Pipeline(Preset::Smash).isPointwise()); // its bloom
    PipelineSettings s;
    s.bloom = false;
    EXPECT_TRUE(Pipeline(s).isPointwise());
    for (const char* stage : {"vignette", "grain", "chromatic-aberration", "soft-bloom"}) {
        s.enable = {stage};
        const Pipeline p(s);
        EXPECT_FALSE(p.isPointwise()) << stage;
        float px[4] = {0.5f, 0.5f, 0.5f, 1.0f};
        EXPECT_THROW(p.runPixels(px, 1), Error) << stage;
    }
}

TEST(Pointwise, PreparationIsTheDecodeThenTheUndo) {
    // 8-bit codes (the table path), values that are not codes, alpha below 1, NaN and values
    // beyond 1, with the neutral stage LUT and with another: the one-pass preparation gives what
    // the sRGB decode of every value and then smashUngrade give.
    Image frame(256, 4);
    Rng r(3);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 256; ++x) {
            float* p = frame.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = y < 2 ? static_cast<float>((x * (c + 3) + y * 7) % 256) / 255.0f
                             : static_cast<float>(1.4 * r.uniform() - 0.1);
            p[3] = y == 1 && x % 5 == 0 ? 0.5f : 1.0f;
        }
    frame.pixel(9, 3)[0] = std::numeric_limits<float>::quiet_NaN();
    frame.pixel(10, 0)[1] = 0.5f / 255.0f; // between codes
    PreviewRequest q;
    q.evidence = SceneEvidence{false, 8, "", "png"};
    const PreviewPlan plan = planPreview(q);
    ASSERT_TRUE(plan.decode && plan.undoGrading);
    const Lut3D warm = makeWarmLut(16);
    for (const Lut3D* stageLut : {static_cast<const Lut3D*>(nullptr), &warm}) {
        Image want = frame;
        srgbDecode(want.view(), 1);
        const UngradeResult u = smashUngrade(want.view(), stageLut, plan.settings.interpolation, 1);
        Image got = frame;
        preparePreviewFrame(plan, got.view(), stageLut, true, 2);
        std::string where;
        EXPECT_TRUE(bitEqual(got, want, &where))
            << (stageLut ? "warm" : "neutral") << ": " << where;
        Image streamed = frame;
        const PreviewPreparation prep(plan, stageLut, true);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 256; x += 51)
                prep.apply(streamed.pixel(x, y), static_cast<std::size_t>(std::min(51, 256 - x)));
        EXPECT_TRUE(bitEqual(streamed, want, &where)) << "runs: " << where;
        // The notes: bloom is left to the screenshot (said in the plan's reason, not again),
        // and the pixels the stage LUT cannot make are counted as smashUngrade counts them.
        std::size_t warned = 0;
        for (const auto& d : prep.notes()) {
            EXPECT_NE(d.message.rfind("bloom cannot be undone", 0), 0u) << d.message;
            if (d.severity == Diagnostic::Severity::Warning)
                warned = std::stoul(d.message);
        }
        EXPECT_EQ(warned, u.unconverged);
    }
}
