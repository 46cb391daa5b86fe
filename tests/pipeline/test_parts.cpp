// SPDX-License-Identifier: Apache-2.0
// The pipeline in two parts around its LUT (PipelinePart): BeforeLut then FromLut is the whole
// run bit for bit, and sameBeforeLut says when a cached BeforeLut frame still applies.
#include "PipelineTestUtil.h"

#include "lut/pipeline/Pipeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

using namespace lut;
using namespace lut::test;

namespace {

bool bitEqual(const Image& a, const Image& b) {
    return a.pixels().size() == b.pixels().size() &&
           std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(float)) ==
               0;
}

Image inPart(Pipeline& p, const Image& frame, PipelinePart part, PipelineReport* report = nullptr) {
    RunOptions o;
    o.part = part;
    o.frameIndex = 2;
    return p.run(frame, o, report);
}

} // namespace

TEST(PipelineParts, BeforeThenFromLutIsTheWholeRunBitForBit) {
    Image scene = makeScene(57, 31, 9);
    scene.pixel(3, 4)[0] = NAN; // sanitize runs in the first part only
    scene.pixel(8, 2)[1] = INFINITY;
    const auto lut = std::make_shared<const Lut3D>(makeWarmLut(17));
    for (Preset preset : {Preset::Smash, Preset::Pilot, Preset::Lecture, Preset::None})
        for (bool bloom : {true, false})
            for (Interpolation m : {Interpolation::Trilinear, Interpolation::Tetrahedral}) {
                PipelineSettings s;
                s.preset = preset;
                s.bloom = bloom;
                s.lut = lut;
                s.interpolation = m;
                Pipeline p(s);
                const Image whole = inPart(p, scene, PipelinePart::Whole);
                const Image before = inPart(p, scene, PipelinePart::BeforeLut);
                const Image split = inPart(p, before, PipelinePart::FromLut);
                EXPECT_TRUE(bitEqual(whole, split))
                    << toString(preset) << " bloom " << bloom << " " << toString(m);
                // The first part alone is not the whole (the LUT and display stages remain).
                EXPECT_FALSE(bitEqual(whole, before)) << toString(preset);
            }
}

TEST(PipelineParts, ThePartsSplitAtTheFirstLutStage) {
    // No stage names here: the split is found by the pipeline, not by a list of names.
    Image scene = makeScene(20, 12, 4);
    scene.pixel(1, 1)[2] = NAN; // something for sanitize to do
    PipelineSettings warm, cool;
    warm.lut = std::make_shared<const Lut3D>(makeWarmLut(16, 1.0));
    cool.lut = std::make_shared<const Lut3D>(makeWarmLut(16, -1.0));
    Pipeline a(warm), b(cool);
    const std::size_t split = a.firstLutStage();
    ASSERT_LT(split, a.stages().size());
    // Before the LUT nothing depends on the LUT; from it on, everything after does.
    PipelineReport before, from;
    const Image midA = inPart(a, scene, PipelinePart::BeforeLut, &before);
    const Image midB = inPart(b, scene, PipelinePart::BeforeLut);
    EXPECT_TRUE(bitEqual(midA, midB));
    EXPECT_FALSE(bitEqual(midA, scene));
    EXPECT_FALSE(bitEqual(inPart(a, midA, PipelinePart::FromLut, &from),
                          inPart(b, midA, PipelinePart::FromLut)));
    for (std::size_t i = 0; i < a.stages().size(); ++i) {
        const bool on = a.stages()[i]->enabled();
        EXPECT_EQ(before.stages[i].enabled, on && i < split) << i;
        EXPECT_EQ(from.stages[i].enabled, on && i >= split) << i;
        EXPECT_FALSE(before.stages[i].ran && i >= split) << i;
        EXPECT_FALSE(from.stages[i].ran && i < split) << i;
    }
    EXPECT_TRUE(before.stages[0].ran); // sanitize
    EXPECT_TRUE(from.stages[split].ran);
}

TEST(PipelineParts, SameBeforeLutFollowsTheStagesBeforeTheLut) {
    PipelineSettings base;
    base.preset = Preset::Smash;
    const Pipeline a(base);
    const std::size_t split = a.firstLutStage();
    // What only the LUT part sees: the LUT, its interpolation, settings of the last stage.
    PipelineSettings lutOnly = base;
    lutOnly.lut = std::make_shared<const Lut3D>(makeWarmLut(16));
    lutOnly.interpolation = Interpolation::Tetrahedral;
    Pipeline b(lutOnly);
    Stage& last = *b.stages().back();
    ASSERT_FALSE(last.params().empty());
    const StageParam& p = last.params().front();
    last.setParam(p.name, p.value == p.min ? p.max : p.min);
    EXPECT_TRUE(a.sameBeforeLut(b));
    // What the first part sees: bloom on/off, a bloom setting, another stage, another preset.
    PipelineSettings noBloom = base;
    noBloom.bloom = false;
    EXPECT_FALSE(a.sameBeforeLut(Pipeline(noBloom)));
    PipelineSettings weakBloom = base;
    weakBloom.assignments = {"bloom.strength=0.5"};
    EXPECT_FALSE(a.sameBeforeLut(Pipeline(weakBloom)));
    PipelineSettings pilot = base;
    pilot.preset = Preset::Pilot;
    EXPECT_FALSE(a.sameBeforeLut(Pipeline(pilot)));
    // A stage before the LUT that the preset leaves off: switching it on matters, its
    // parameters while it is off do not.
    std::size_t off = 0;
    while (off < split && a.stages()[off]->enabled())
        ++off;
    ASSERT_LT(off, split);
    const std::string name = a.stages()[off]->name();
    Pipeline tuned(base);
    Stage& s = *tuned.stages()[off];
    if (!s.params().empty()) {
        const StageParam& q = s.params().front();
        s.setParam(q.name, q.value == q.min ? q.max : q.min);
    }
    EXPECT_TRUE(a.sameBeforeLut(tuned)) << name;
    PipelineSettings extra = base;
    extra.enable = {name};
    EXPECT_FALSE(a.sameBeforeLut(Pipeline(extra))) << name;
}
