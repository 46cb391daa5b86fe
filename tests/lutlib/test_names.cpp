// SPDX-License-Identifier: Apache-2.0
// The names users see and type (issue 18's vocabulary, written here plainly as the oracle): the
// primary names toString gives, and the old names every parser keeps accepting as aliases.
#include "lut/Error.h"
#include "lut/io/Layout.h"
#include "lut/pipeline/Pipeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

using namespace lut;

TEST(Names, LayoutsByTheEngineOrToolThatUsesThem) {
    EXPECT_STREQ(toString(LutLayout::Pilot), "unreal");
    EXPECT_STREQ(toString(LutLayout::Unity), "unity");
    EXPECT_STREQ(toString(LutLayout::Smush), "smush");
    EXPECT_STREQ(toString(LutLayout::Hald), "hald");
    EXPECT_STREQ(toString(LutLayout::Reshade), "reshade");
    EXPECT_STREQ(toString(LutLayout::Unity32), "unity-32");
    const std::vector<std::pair<const char*, LutLayout>> accepted = {
        {"unreal", LutLayout::Pilot},      {"pilot", LutLayout::Pilot},
        {"godot", LutLayout::Pilot},       {"unity", LutLayout::Unity},
        {"smush", LutLayout::Smush},       {"lattice", LutLayout::Smush},
        {"hald", LutLayout::Hald},         {"reshade", LutLayout::Reshade},
        {"unreal-32", LutLayout::Reshade}, {"unity-32", LutLayout::Unity32},
    };
    for (const auto& [name, layout] : accepted)
        EXPECT_EQ(parseLayout(name), layout) << name;
    const std::vector<std::string> pilotAliases = layoutAliases(LutLayout::Pilot);
    EXPECT_EQ(pilotAliases, (std::vector<std::string>{"pilot", "godot"}));
    try {
        (void)parseLayout("Unreal");
        FAIL() << "names are case-sensitive";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "unknown layout 'Unreal' (expected unreal, unity, smush, hald, reshade, "
                  "unity-32; also pilot, godot, lattice, unreal-32)");
    }
}

TEST(Names, PresetsSayWhatTheyLookLike) {
    EXPECT_STREQ(toString(Preset::Smash), "smash");
    EXPECT_STREQ(toString(Preset::Pilot), "filmic");
    EXPECT_STREQ(toString(Preset::Lecture), "cinematic");
    EXPECT_STREQ(toString(Preset::None), "none");
    EXPECT_EQ(parsePreset("filmic"), Preset::Pilot);
    EXPECT_EQ(parsePreset("pilot"), Preset::Pilot);
    EXPECT_EQ(parsePreset("cinematic"), Preset::Lecture);
    EXPECT_EQ(parsePreset("lecture"), Preset::Lecture);
    EXPECT_THROW(parsePreset("sugar"), Error);
    for (const Preset p : allPresets())
        EXPECT_EQ(parsePreset(toString(p)), p);
    EXPECT_EQ(allPresets().size(), 4u);
}

TEST(Names, RenamedStagesAnswerToTheirOldNamesEverywhere) {
    const auto& names = stageNames();
    for (const char* n : {"soft-bloom", "glow-bloom"})
        EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
    for (const char* old : {"filter-bloom", "sugar-bloom"})
        EXPECT_EQ(std::find(names.begin(), names.end(), old), names.end()) << old;
    EXPECT_STREQ(makeStage("filter-bloom")->name(), "soft-bloom");
    EXPECT_STREQ(makeStage("sugar-bloom")->name(), "glow-bloom");
    EXPECT_EQ(canonicalStageName("sugar-bloom"), "glow-bloom");
    EXPECT_EQ(canonicalStageName("vignette"), "vignette");

    // In a pipeline: find, enable, and "stage.param=value" by the old name.
    PipelineSettings s;
    s.preset = Preset::Pilot;
    s.enable = {"sugar-bloom"};
    s.assignments = {"sugar-bloom.f0=0.5", "filter-bloom.strength=2"};
    Pipeline p(s);
    EXPECT_TRUE(p.stage("glow-bloom").enabled());
    EXPECT_FLOAT_EQ(p.stage("glow-bloom").param("f0"), 0.5f);
    EXPECT_FLOAT_EQ(p.stage("soft-bloom").param("strength"), 2.0f);
    EXPECT_EQ(p.find("filter-bloom"), p.find("soft-bloom"));
    // The filmic preset's own bloom is the soft bloom.
    EXPECT_EQ(p.find("bloom"), p.find("soft-bloom"));
}
