// SPDX-License-Identifier: Apache-2.0
// The screenshot/scene rule (lut/pipeline/SceneKind.h) that lutkit preview and the editor share.
#include "lut/pipeline/SceneKind.h"

#include <gtest/gtest.h>

using namespace lut;

TEST(SceneKindRule, IntegerFilesAreScreenshotsFloatAndLinearTaggedFilesScenes) {
    SceneEvidence png{false, 8, "sRGB", "png"};
    const SceneDecision a = decideSceneKind(png);
    EXPECT_EQ(a.kind, SceneKind::Screenshot);
    EXPECT_TRUE(a.undoGrading);
    EXPECT_FALSE(a.storedIsLinear);
    EXPECT_FALSE(a.forced);
    EXPECT_NE(a.reason.find("in-game screenshot"), std::string::npos) << a.reason;
    EXPECT_NE(a.reason.find("--scene"), std::string::npos) << a.reason;

    SceneEvidence jpeg16{false, 16, "", "tiff"};
    EXPECT_EQ(decideSceneKind(jpeg16).kind, SceneKind::Screenshot);

    SceneEvidence exr{true, 32, "Linear", "openexr"};
    const SceneDecision b = decideSceneKind(exr);
    EXPECT_EQ(b.kind, SceneKind::Scene);
    EXPECT_TRUE(b.storedIsLinear);
    EXPECT_FALSE(b.undoGrading);
    EXPECT_NE(b.reason.find("--from-screenshot"), std::string::npos) << b.reason;

    // a linear render stored as 16-bit TIFF says so in its metadata
    SceneEvidence render{false, 16, "Linear", "tiff"};
    const SceneDecision c = decideSceneKind(render);
    EXPECT_EQ(c.kind, SceneKind::Scene);
    EXPECT_TRUE(c.storedIsLinear);
    EXPECT_EQ(decideSceneKind(SceneEvidence{false, 16, "lin_rec709", "tiff"}).kind,
              SceneKind::Scene);
}

TEST(SceneKindRule, TheUserOverridesIt) {
    // a screenshot someone saved as EXR
    const SceneDecision a =
        decideSceneKind(SceneEvidence{true, 32, "Linear", "openexr"}, SceneKind::Screenshot);
    EXPECT_EQ(a.kind, SceneKind::Screenshot);
    EXPECT_TRUE(a.forced);
    EXPECT_FALSE(a.storedIsLinear);
    EXPECT_TRUE(a.undoGrading);
    // an 8-bit picture of a scene: sRGB-decoded, not ungraded
    const SceneDecision b =
        decideSceneKind(SceneEvidence{false, 8, "sRGB", "png"}, SceneKind::Scene);
    EXPECT_EQ(b.kind, SceneKind::Scene);
    EXPECT_FALSE(b.storedIsLinear);
    EXPECT_FALSE(b.undoGrading);
    EXPECT_NE(b.reason.find("sRGB-decoded"), std::string::npos) << b.reason;
    // the old rule stays
    EXPECT_EQ(detectSceneKind(false), SceneKind::Screenshot);
    EXPECT_EQ(detectSceneKind(true), SceneKind::Scene);
}
