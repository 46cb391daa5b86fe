// SPDX-License-Identifier: Apache-2.0
// Skipping a stage never changes the output: every preset, with every stage enabled in turn,
// run normally and with forceAll give bit-identical frames on several scenes.
#include "PipelineTestUtil.h"

#include "lut/pipeline/Pipeline.h"

#include <gtest/gtest.h>

#include <cstring>

using namespace lut;
using namespace lut::test;

namespace {

std::vector<std::pair<std::string, Image>> scenes() {
    std::vector<std::pair<std::string, Image>> v;
    v.emplace_back("hdr", makeScene(41, 29, 1));
    Image dark = makeScene(40, 30, 2, 1.0f);
    for (auto& p : dark.pixels())
        p *= 0.3f; // nothing above any bloom threshold, alpha scaled
    v.emplace_back("dark", dark);
    Image bg = makeScene(33, 17, 3);
    for (int i = 3; i < static_cast<int>(bg.pixels().size()); i += 4)
        bg.pixels()[i] = 0.0f;
    v.emplace_back("alpha0", bg);
    Image bad = makeScene(36, 20, 4);
    bad.pixel(5, 5)[0] = NAN;
    bad.pixel(9, 3)[1] = INFINITY;
    bad.pixel(20, 10)[2] = -INFINITY;
    bad.pixel(1, 1)[3] = NAN;
    v.emplace_back("nonfinite", bad);
    Image grey(16, 16, 0.18f);
    v.emplace_back("grey", grey);
    Image neg = makeScene(21, 13, 6);
    for (int i = 0; i < static_cast<int>(neg.pixels().size()); i += 7)
        neg.pixels()[i] = -neg.pixels()[i];
    v.emplace_back("negative", neg);
    return v;
}

bool bitEqual(const Image& a, const Image& b) {
    return a.pixels().size() == b.pixels().size() &&
           std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(float)) ==
               0;
}

void expectSkipExact(Pipeline& p, const std::string& what) {
    for (const auto& [name, scene] : scenes()) {
        Image a = scene, b = scene;
        RunOptions normal, forced;
        forced.forceAll = true;
        normal.frameIndex = forced.frameIndex = 3;
        p.run(a.view(), normal);
        p.run(b.view(), forced);
        EXPECT_TRUE(bitEqual(a, b)) << what << " on scene " << name;
    }
}

} // namespace

TEST(PipelineSkip, PresetsAreBitIdenticalWithAndWithoutSkipping) {
    for (Preset pr : {Preset::Smash, Preset::Pilot, Preset::Lecture, Preset::None}) {
        Pipeline p(pr);
        expectSkipExact(p, toString(pr));
    }
}

TEST(PipelineSkip, EveryStageAloneAndWithNeutralSettings) {
    for (const auto& n : stageNames()) {
        Pipeline p(Preset::None);
        p.setEnabled(n, true);
        expectSkipExact(p, n);
    }
    // Settings that make stages no-ops.
    Pipeline p(Preset::Lecture);
    for (const char* s : {"grain", "vignette", "chromatic-aberration", "exposure", "sugar-bloom",
                          "filter-bloom", "smash-bloom", "tonemap", "smash-grade"})
        p.setEnabled(s, true);
    for (const char* a :
         {"grain.strength=0", "vignette.strength=0", "chromatic-aberration.strength=0",
          "exposure.stops=0", "hdr-bloom.strength=0", "filter-bloom.threshold=50",
          "sugar-bloom.threshold=100", "smash-bloom.threshold=1"})
        p.assign(a);
    expectSkipExact(p, "neutral settings");
}

TEST(PipelineSkip, SkippedStagesAreReported) {
    Pipeline p(Preset::Smash);
    Image dark(32, 32, 0.1f);
    const PipelineReport r = p.run(dark.view());
    auto ran = [&](const std::string& n) {
        for (const auto& s : r.stages)
            if (s.name == n)
                return s.ran;
        ADD_FAILURE() << n;
        return false;
    };
    EXPECT_FALSE(ran("smash-bloom")); // nothing above the threshold
    EXPECT_TRUE(ran("smash-grade"));
    EXPECT_TRUE(ran("display"));
    EXPECT_FALSE(ran("sanitize"));
    Image bg(32, 32, 0.0f); // alpha 0: no grading
    const PipelineReport r2 = p.run(bg.view());
    for (const auto& s : r2.stages)
        if (s.name == "smash-grade") {
            EXPECT_FALSE(s.ran);
        }
    EXPECT_NE(r.str().find("smash-bloom"), std::string::npos);
}
