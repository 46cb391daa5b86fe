// SPDX-License-Identifier: Apache-2.0
// The patch describes itself: embed records the lattice, layout, scale, target and the stage
// LUT's digest, extract does by default what embed set up, and patches made before the target
// existed (tests/data/roundtrip/v1-*.png, made by lutkit embed before issue 14) still read.
#include "RoundtripTestUtil.h"
#include "TestSupport.h"

#include "lut/formats/ImageIO.h"
#include "lut/roundtrip/Embed.h"
#include "lut/roundtrip/Extract.h"
#include "lut/roundtrip/LutDigest.h"
#include "lut/roundtrip/PatchFinder.h"

#include <gtest/gtest.h>

using namespace lut;
using namespace lut::rt;

namespace {

Image fixture(const std::string& name) {
    return formats::readImage(lut::test::dataPath("roundtrip/" + name)).image;
}

Lut3D warmStageLut() {
    Lut3D warm = Lut3D::identity(16);
    for (auto& e : warm.entries())
        e = glm::vec3(std::min(1.0f, e.x * 1.05f + 0.02f), e.y, e.z * 0.92f);
    return warm;
}

} // namespace

TEST(SelfDescribing, OldPatchesStillRead) {
    {
        const Image img = fixture("v1-game-display-12-scale2.png");
        const FindResult f = findPatch(img.view());
        ASSERT_EQ(f.status, FindStatus::Found) << f.message;
        EXPECT_EQ(f.placement.headerVersion, 1);
        EXPECT_EQ(f.placement.lattice, PatchLattice::Smash);
        EXPECT_EQ(f.placement.size, 12);
        EXPECT_EQ(f.placement.layout, LutLayout::Pilot);
        EXPECT_EQ(f.placement.scale, 2);
        EXPECT_EQ(f.placement.bitDepth, 8);
        EXPECT_EQ(f.placement.frameX, 8);
        EXPECT_FALSE(f.placement.target.has_value());
        EXPECT_FALSE(f.placement.stageDigest.has_value());
        // no target recorded: the game-display lattice is made for the game
        const ExtractResult r = extractLut(img.view(), {});
        EXPECT_EQ(r.target, LutPurpose::Smash);
        EXPECT_EQ(r.targetSource, TargetSource::Lattice);
    }
    {
        // edited with oiiotool --powc 0.8 (rounded to 8 bits): the raw LUT is x^0.8
        const Image img = fixture("v1-game-display-12-scale2-pow0.8.png");
        ExtractOptions o;
        o.target = LutPurpose::Raw;
        const ExtractResult r = extractLut(img.view(), o);
        ASSERT_EQ(r.lut.size(), 16);
        for (int i = 0; i < 16; ++i) {
            const double x = i / 15.0;
            // between the 12 game-display values the edit is interpolated
            EXPECT_NEAR(r.lut.at(i, i, i).x, std::pow(x, 0.8), 3.0 / 255.0) << i;
        }
    }
    {
        const Image img = fixture("v1-uniform-16-hald-16bit.png");
        const FindResult f = findPatch(img.view());
        ASSERT_EQ(f.status, FindStatus::Found) << f.message;
        EXPECT_EQ(f.placement.headerVersion, 1);
        EXPECT_EQ(f.placement.lattice, PatchLattice::Uniform);
        EXPECT_EQ(f.placement.layout, LutLayout::Hald);
        EXPECT_EQ(f.placement.bitDepth, 16);
        const ExtractResult r = extractLut(img.view(), {});
        EXPECT_EQ(r.target, LutPurpose::Raw);
        EXPECT_LT(r.lut.maxDeviationFromIdentity(), 1e-4f);
    }
}

TEST(SelfDescribing, TheHeaderRecordsWhatEmbedWasAskedFor) {
    const Lut3D warm = warmStageLut();
    struct Case {
        LutPurpose target;
        const Lut3D* original;
        PatchLattice lattice;
        int size;
        LutLayout layout;
    };
    const Case cases[] = {
        {LutPurpose::Smash, nullptr, PatchLattice::Smash, 12, LutLayout::Pilot},
        {LutPurpose::Raw, nullptr, PatchLattice::Uniform, 16, LutLayout::Hald},
        {LutPurpose::Smash, &warm, PatchLattice::SmashStage, 16, LutLayout::Hald},
    };
    for (const auto& c : cases) {
        Image shot = syntheticScreenshot(kShotWidth, kShotHeight, 8);
        EmbedOptions eo;
        eo.target = c.target;
        eo.originalLut = c.original;
        const PatchPlacement p = embedPatch(shot.view(), eo);
        EXPECT_EQ(p.scale, kDefaultPatchScale);
        const FindResult f = findPatch(shot.view());
        ASSERT_EQ(f.status, FindStatus::Found) << f.message;
        EXPECT_EQ(f.placement.headerVersion, 2);
        EXPECT_EQ(f.placement.lattice, c.lattice);
        EXPECT_EQ(f.placement.size, c.size);
        EXPECT_EQ(f.placement.layout, c.layout);
        EXPECT_EQ(f.placement.scale, kDefaultPatchScale);
        ASSERT_TRUE(f.placement.target.has_value());
        EXPECT_EQ(*f.placement.target, c.target);
        EXPECT_EQ(f.placement.stageDigest.has_value(), c.original != nullptr);
        if (c.original) {
            EXPECT_EQ(*f.placement.stageDigest, lutDigest(warm));
        }
        // the first entry sits on the 16-pixel JPEG grid
        EXPECT_EQ(f.placement.patchX() % kJpegGrid, 0);
        EXPECT_EQ(f.placement.patchY() % kJpegGrid, 0);
        // extract does what embed set up; an explicit target wins
        const ExtractResult r = extractLut(shot.view(), {});
        EXPECT_EQ(r.target, c.target);
        EXPECT_EQ(r.targetSource, TargetSource::Patch);
        if (!c.original) {
            ExtractOptions o;
            o.target = c.target == LutPurpose::Raw ? LutPurpose::Smash : LutPurpose::Raw;
            const ExtractResult other = extractLut(shot.view(), o);
            EXPECT_EQ(other.target, *o.target);
            EXPECT_EQ(other.targetSource, TargetSource::Option);
        }
    }
}

TEST(SelfDescribing, TheDigestTellsStageLutsApart) {
    const Lut3D warm = warmStageLut();
    Lut3D other = warm;
    other.at(3, 4, 5).x += 2.0f / 255.0f;
    EXPECT_NE(lutDigest(warm), lutDigest(other));
    EXPECT_EQ(lutDigest(warm), lutDigest(warm));
    EXPECT_NE(lutDigest(Lut3D::identity(16)), lutDigest(Lut3D::identity(17)));
    EXPECT_EQ(digestText(0x3fa2), "3fa2");
    // extract warns when the original LUT given is not the one the patch was made for
    Image shot = syntheticScreenshot(kShotWidth, kShotHeight, 8);
    EmbedOptions eo;
    eo.originalLut = &warm;
    embedPatch(shot.view(), eo);
    ExtractOptions o;
    o.originalLut = &other;
    EXPECT_TRUE(extractLut(shot.view(), o).has(RoundtripWarning::StageMismatch));
    o.originalLut = &warm;
    EXPECT_FALSE(extractLut(shot.view(), o).has(RoundtripWarning::StageMismatch));
    // a stage patch cannot give a raw LUT, and an original LUT is refused for a raw patch
    ExtractOptions raw;
    raw.target = LutPurpose::Raw;
    EXPECT_THROW(extractLut(shot.view(), raw), Error);
    EmbedOptions bad;
    bad.target = LutPurpose::Raw;
    bad.originalLut = &warm;
    Image again = syntheticScreenshot(kShotWidth, kShotHeight, 8);
    EXPECT_THROW(embedPatch(again.view(), bad), Error);
}

TEST(SelfDescribing, SmallScreenshotsGetTheLargestScaleThatFits) {
    Image shot = syntheticScreenshot(400, 260, 8);
    const PatchPlacement p = embedPatch(shot.view(), EmbedOptions{});
    EXPECT_EQ(p.scale, 2); // 12^3 pilot: 148 cells wide, 3 px would need 452 pixels
    EmbedOptions fixed;
    fixed.scale = 3;
    Image again = syntheticScreenshot(400, 260, 8);
    EXPECT_THROW(embedPatch(again.view(), fixed), Error);
}
