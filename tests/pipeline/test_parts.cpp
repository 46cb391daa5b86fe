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
    Pipeline p(Preset::Smash);
    const auto& names = stageNames();
    const std::size_t grade = std::find(names.begin(), names.end(), "smash-grade") - names.begin();
    EXPECT_EQ(p.firstLutStage(), grade);
    PipelineReport before, from;
    Image scene = makeScene(20, 12, 4);
    scene.pixel(1, 1)[2] = NAN; // something for sanitize to do
    const Image mid = inPart(p, scene, PipelinePart::BeforeLut, &before);
    inPart(p, mid, PipelinePart::FromLut, &from);
    for (std::size_t i = 0; i < names.size(); ++i) {
        const bool on = p.stages()[i]->enabled();
        EXPECT_EQ(before.stages[i].enabled, on && i < grade) << names[i];
        EXPECT_EQ(from.stages[i].enabled, on && i >= grade) << names[i];
        EXPECT_FALSE(before.stages[i].ran && i >= grade) << names[i];
        EXPECT_FALSE(from.stages[i].ran && i < grade) << names[i];
    }
    EXPECT_TRUE(before.stages[0].ran);              // sanitize
    EXPECT_TRUE(from.stages[grade].ran);            // smash-grade
    EXPECT_TRUE(from.stages[names.size() - 1].ran); // display
}

TEST(PipelineParts, SameBeforeLutFollowsTheStagesBeforeTheLut) {
    PipelineSettings a;
    a.preset = Preset::Smash;
    PipelineSettings b = a;
    // What only the LUT part sees: the LUT, its interpolation, display settings.
    b.lut = std::make_shared<const Lut3D>(makeWarmLut(16));
    b.interpolation = Interpolation::Tetrahedral;
    b.assignments = {"display.curve=gamma"};
    EXPECT_TRUE(Pipeline(a).sameBeforeLut(Pipeline(b)));
    // What the first part sees.
    PipelineSettings c = a;
    c.bloom = false;
    EXPECT_FALSE(Pipeline(a).sameBeforeLut(Pipeline(c)));
    PipelineSettings d = a;
    d.assignments = {"smash-bloom.strength=0.5"};
    EXPECT_FALSE(Pipeline(a).sameBeforeLut(Pipeline(d)));
    PipelineSettings e = a;
    e.enable = {"vignette"};
    EXPECT_FALSE(Pipeline(a).sameBeforeLut(Pipeline(e)));
    PipelineSettings f = a;
    f.preset = Preset::Pilot;
    EXPECT_FALSE(Pipeline(a).sameBeforeLut(Pipeline(f)));
    // A parameter of a stage that is switched off does not matter.
    PipelineSettings g = a, h = a;
    g.assignments = {"vignette.strength=0.1"};
    h.assignments = {"vignette.strength=0.9"};
    EXPECT_TRUE(Pipeline(g).sameBeforeLut(Pipeline(h)));
}
