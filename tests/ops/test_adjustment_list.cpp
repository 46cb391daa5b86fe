// SPDX-License-Identifier: Apache-2.0
// The adjustment list text (lut/ops/AdjustmentList.h): exact round trips, the documented syntax
// and errors that name the line and column.
#include "OpsTestUtil.h"

#include "lut/Error.h"
#include "lut/ops/AdjustmentList.h"

#include <gtest/gtest.h>

using namespace lut;
using namespace lut::opstest;

namespace {

Adjustments everything() {
    Adjustments a;
    a.exposure = 0.1; // not exact in binary: the text must still bring back the same double
    a.contrast = 1.0 / 3.0;
    a.saturation = 1.2345678901234567;
    a.temperature = -0.0;
    a.tint = 1e-300;
    a.liftMaster = 0.02;
    a.gammaMaster = 1.1;
    a.gainMaster = 0.95;
    a.lift = {0.01, 0.0, -0.01};
    a.gamma = {1.0, 1.05, 0.97};
    a.gain = {1.02, 1.0, 0.99};
    a.curveMaster = Curve(CurveKind::Tone, {{0, 0}, {0.25, 0.2}, {1, 1}});
    a.curveRed = Curve(CurveKind::Tone, {{0, 0.01}, {0.6, 0.62}, {1, 0.98}});
    a.curveBlue = Curve(CurveKind::Tone, {{0, 0}, {1, 0.9}});
    a.hueVsHue = Curve(CurveKind::Hue, {{0, 5}, {120, -7.5}});
    a.hueVsSat = Curve(CurveKind::Hue, {{30, 0.2}, {210, -0.3}, {300, 0}});
    a.hueVsLum = Curve(CurveKind::Hue, {{60, 0.1}});
    a.strength = 0.8;
    return a;
}

} // namespace

TEST(AdjustmentList, RoundTripIsExactAndAppliesBitForBit) {
    const Adjustments a = everything();
    const std::string text = formatAdjustmentList(a);
    const Adjustments back = parseAdjustmentList(text);
    EXPECT_EQ(back, a) << text;
    EXPECT_TRUE(std::signbit(back.temperature)); // -0 survives
    const Lut3D base = lutFrom(17, smoothGrade);
    EXPECT_TRUE(sameBits(applyAdjustments(base, back), applyAdjustments(base, a)));
    // Formatting what was parsed gives the same text again.
    EXPECT_EQ(formatAdjustmentList(back), text);
}

TEST(AdjustmentList, WritesOnlyWhatDiffersInReadableForm) {
    EXPECT_EQ(formatAdjustmentList(Adjustments{}), "# lutkit adjustment list 1\n");
    EXPECT_EQ(parseAdjustmentList(""), Adjustments{});
    Adjustments a;
    a.exposure = 0.5;
    a.lift = {0.01, 0, -0.01};
    a.curveMaster = Curve(CurveKind::Tone, {{0, 0}, {0.25, 0.2}, {1, 1}});
    EXPECT_EQ(formatAdjustmentList(a), "# lutkit adjustment list 1\n"
                                       "exposure 0.5\n"
                                       "lift 0.01 0 -0.01\n"
                                       "curve.master 0,0 0.25,0.2 1,1\n");
}

TEST(AdjustmentList, ParsesTheDocumentedSyntax) {
    const Adjustments a = parseAdjustmentList("# a grade\n"
                                              "\n"
                                              "strength 0.75   # trailing comment\n"
                                              "hue.sat 0,0.2 120,-0.5\n"
                                              "\tgain.master +1.5e0\r\n"
                                              "lift 0.01 0 -0.01\n"
                                              "curve.green 0,0 1,0.8");
    EXPECT_EQ(a.strength, 0.75);
    EXPECT_EQ(a.gainMaster, 1.5);
    EXPECT_EQ(a.lift, glm::dvec3(0.01, 0, -0.01));
    EXPECT_EQ(a.hueVsSat, Curve(CurveKind::Hue, {{0, 0.2}, {120, -0.5}}));
    EXPECT_EQ(a.curveGreen, Curve(CurveKind::Tone, {{0, 0}, {1, 0.8}}));
    EXPECT_EQ(a.exposure, 0.0);
}

TEST(AdjustmentList, ErrorsNameLineAndColumn) {
    auto expectError = [](const std::string& text, int line, int column, const std::string& what) {
        try {
            parseAdjustmentList(text, "grade.txt");
            ADD_FAILURE() << "no error for: " << text;
        } catch (const ParseError& e) {
            EXPECT_EQ(e.path(), "grade.txt");
            EXPECT_EQ(e.line(), line) << e.what();
            EXPECT_EQ(e.column(), column) << e.what();
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };
    expectError("exposure 1\nbrightness 2\n", 2, 1, "unknown adjustment 'brightness'");
    expectError("exposure 1\n  contrast 0.x\n", 2, 12, "expected a number");
    expectError("exposure 1\nexposure 2\n", 2, 1, "already given");
    expectError("lift 0.1 0.2\n", 1, 1, "three numbers");
    expectError("saturation\n", 1, 1, "one number");
    expectError("curve.red 0,0 0.5;0.5 1,1\n", 1, 15, "x,y");
    expectError("curve.red 0,0 0.5,nan 1,1\n", 1, 19, "finite");
    expectError("curve.red 0,0 0,1\n", 1, 1, "share x");
    expectError("curve.blue 0.5,0.5\n", 1, 1, "at least 2 points");
    expectError("hue.hue 10,0 370,1\n", 1, 1, "share x");
    expectError("strength inf\n", 1, 10, "finite");
}
