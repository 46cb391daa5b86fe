// SPDX-License-Identifier: Apache-2.0
// --layout reshade (and unity-32) through the commands: neutral writes 1024x32, convert resamples
// to 32^3 and says so, apply and preview read a ReShade strip with --lut-layout, a size the name
// does not hold is bad usage.
#include "CliTestSupport.h"
#include "ShaderSamplers.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace lut;
using namespace lut::test;

namespace {} // namespace

TEST(CliReshade, NeutralIs1024x32AndSampledByLutFxAsTheIdentity) {
    const std::string dir = workDir();
    const RunResult r = runCli("neutral '" + dir + "/n.png' --layout reshade");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("neutral 32^3, layout reshade"), std::string::npos) << r.out;
    const Texture tex = load(dir + "/n.png");
    ASSERT_EQ(tex.w, 1024);
    ASSERT_EQ(tex.h, 32);
    // LUT.fx on the neutral strip gives back every colour within half an 8-bit step.
    double worst = 0;
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 40; ++j) {
            const glm::dvec3 c(i / 40.0, j / 40.0, ((i * 7 + j * 3) % 41) / 40.0);
            const auto got = reshadeSample(tex, c);
            for (int ch = 0; ch < 3; ++ch)
                worst = std::max(worst, std::fabs(got[ch] - c[ch]) * 255.0);
        }
    EXPECT_LE(worst, 0.5 + 1e-4);
    const RunResult info = runCli("info '" + dir + "/n.png'");
    EXPECT_NE(info.out.find("strip (reshade)"), std::string::npos) << info.out;
}

TEST(CliReshade, ConvertResamplesTo32AndSizesTheNameDoesNotHoldAreBadUsage) {
    const std::string dir = workDir();
    const std::string cube = samplePath("sample_grade.cube"); // 33^3
    RunResult r = runCli("convert '" + cube + "' '" + dir + "/g.png' --layout reshade");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("resample 33^3 -> 32^3"), std::string::npos) << r.out;
    EXPECT_EQ(formats::readImageInfo(dir + "/g.png").width, 1024);
    r = runCli("convert '" + cube + "' '" + dir + "/u.png' --layout unity-32");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(formats::readLut(dir + "/u.png").dialect, "unity-32");
    r = runCli("convert '" + cube + "' '" + dir + "/x.png' --layout reshade --size 16");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("the reshade layout is 1024x32 (32^3), not 16^3"), std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/x.png"));
    r = runCli("neutral '" + dir + "/y.png' --layout unity-32 --size 64");
    EXPECT_EQ(r.exitCode, 2) << r.err;
}

TEST(CliReshade, ApplyAndPreviewReadAReshadeStrip) {
    // The strip of the sample grade applied to a picture gives what the .cube resampled to 32^3
    // gives (the same table), read by --lut-layout reshade and by detection alike.
    const std::string dir = workDir();
    const std::string cube = samplePath("sample_grade.cube");
    ASSERT_EQ(runCli("convert '" + cube + "' '" + dir + "/g.png' --layout reshade").exitCode, 0);
    ASSERT_EQ(runCli("convert '" + dir + "/g.png' '" + dir + "/g.cube'").exitCode, 0);
    const std::string shot = samplePath("sample_scene.png");
    for (const std::string& how : {std::string(" --lut-layout reshade"), std::string()}) {
        ASSERT_EQ(runCli("apply --lut '" + dir + "/g.png'" + how + " '" + shot + "' -o '" + dir +
                         "/a.png' -y")
                      .exitCode,
                  0);
        ASSERT_EQ(
            runCli("apply --lut '" + dir + "/g.cube' '" + shot + "' -o '" + dir + "/b.png' -y")
                .exitCode,
            0);
        EXPECT_EQ(formats::readImage(dir + "/a.png").image.pixels(),
                  formats::readImage(dir + "/b.png").image.pixels());
        ASSERT_EQ(runCli("preview '" + shot + "' -o '" + dir + "/p.png' -y --lut '" + dir +
                         "/g.png'" + how)
                      .exitCode,
                  0);
        ASSERT_EQ(
            runCli("preview '" + shot + "' -o '" + dir + "/q.png' -y --lut '" + dir + "/g.cube'")
                .exitCode,
            0);
        EXPECT_EQ(formats::readImage(dir + "/p.png").image.pixels(),
                  formats::readImage(dir + "/q.png").image.pixels());
    }
}
