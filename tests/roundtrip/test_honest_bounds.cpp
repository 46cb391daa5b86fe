// The expected error extract prints is an upper bound of the truth in practice: for every
// synthetic edit x file type x target, the truth (the exact edit in float64 and, for smash, the
// game written out from docs/specs/smash-pipeline.md) against what extract reports.
#include "RoundtripTestUtil.h"
#include "SavedAs.h"
#include "TruthOracle.h"

#include "lut/roundtrip/Embed.h"
#include "lut/roundtrip/Extract.h"
#include "lut/roundtrip/PatchFinder.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace lut;
using namespace lut::rt;

namespace {

std::vector<std::pair<const char*, Edit>> testEdits() {
    return {{"curves", curvesEdit()},
            {"levels", levelsEdit()},
            {"saturation", saturationEdit(1.3)},
            {"gradient map", warmGradientMap()},
            {"hue shift", hueShiftEdit(40.0)}};
}

} // namespace

// One test per target and file type (each runs the five edits), so each stays short.
class HonestBounds : public ::testing::TestWithParam<std::tuple<LutPurpose, Storage>> {};

TEST_P(HonestBounds, PrintedExpectedErrorHolds) {
    const LutPurpose target = std::get<0>(GetParam());
    const Storage storage = std::get<1>(GetParam());
    const std::string dir = rtDir();
    for (const auto& [name, edit] : testEdits()) {
        const int bits = storageBits(storage);
        Image shot = syntheticScreenshot(kShotWidth, kShotHeight, bits);
        EmbedOptions eo;
        eo.target = target;
        eo.bitDepth = bits;
        embedPatch(shot.view(), eo);
        applyEdit(shot, edit, bits);
        const Image saved = savedAs(shot, storage, dir, "shot");
        const ExtractResult r = extractLut(saved.view(), {});
        ASSERT_EQ(r.target, target);
        const Truth t =
            target == LutPurpose::Smash ? smashTruth(r.lut, edit) : rawTruth(r.lut, edit);
        const ExpectedError& e = r.expected;
        std::printf("[ measured ] %-5s %-12s %-12s lattice true %5.2f/%5.3f printed "
                    "%5.2f/%5.3f | all true %5.2f/%5.3f/%5.2f printed %5.2f/%5.3f/%5.2f "
                    "(max/mean/p99)\n",
                    toString(target), name, storageName(storage), t.lattice.max, t.lattice.mean,
                    e.atLattice.maxSteps, e.atLattice.meanSteps, t.overall.max, t.overall.mean,
                    t.overall.p99, e.overall.maxSteps, e.overall.meanSteps, e.overall.p99Steps);
        const std::string what =
            std::string(toString(target)) + " " + name + " " + storageName(storage);
        EXPECT_LE(t.lattice.max, e.atLattice.maxSteps) << what << ": lattice max";
        EXPECT_LE(t.lattice.mean, e.atLattice.meanSteps) << what << ": lattice mean";
        EXPECT_LE(t.overall.max, e.overall.maxSteps) << what << ": max";
        EXPECT_LE(t.overall.mean, e.overall.meanSteps) << what << ": mean";
        EXPECT_LE(t.overall.p99, e.overall.p99Steps) << what << ": p99";
    }
}

INSTANTIATE_TEST_SUITE_P(EveryEditFileAndTarget, HonestBounds,
                         ::testing::Combine(::testing::Values(LutPurpose::Smash, LutPurpose::Raw),
                                            ::testing::Values(Storage::Png8, Storage::Tiff16,
                                                              Storage::Jpeg420, Storage::Jpeg444)),
                         [](const ::testing::TestParamInfo<std::tuple<LutPurpose, Storage>>& info) {
                             std::string name = std::string(toString(std::get<0>(info.param))) +
                                                "_" + storageName(std::get<1>(info.param));
                             for (char& ch : name)
                                 if (ch == '-')
                                     ch = '_';
                             return name;
                         });
