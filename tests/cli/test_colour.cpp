// SPDX-License-Identifier: Apache-2.0
// Colour management in apply, preview and convert: the LUT runs in the space it was made for,
// with OpenColorIO converting on either side; checked against OCIO's own processors doing the
// whole chain (the LUT included, as a FileTransform); values outside the LUT's domain are
// reported, never clamped silently; Hald sizes named as ImageMagick names them.
#include "CliTestSupport.h"
#include "OcioTestUtil.h"
#include "TestPaths.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

namespace fs = std::filesystem;
using namespace lut::test;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {

using lut::test::shellQuoted;

std::string testConfig() {
    return dataPath("ocio/test_config.ocio");
}

std::string shippedConfig() {
    return std::string(LUTKIT_BINARY_DIR) + "/share/lutkit/ocio/config.ocio";
}

// A 17^3 grade over [0,1] that mixes channels.
std::string writeGrade(const std::string& path) {
    std::ofstream o(path);
    o.precision(9);
    o << "LUT_3D_SIZE 17\n";
    for (int b = 0; b < 17; ++b)
        for (int g = 0; g < 17; ++g)
            for (int r = 0; r < 17; ++r) {
                const float x = r / 16.0f, y = g / 16.0f, z = b / 16.0f;
                o << 0.85f * x + 0.1f * y * y << " " << std::pow(y, 1.3f) << " "
                  << 0.7f * z + 0.2f * x * z + 0.05f << "\n";
            }
    return path;
}

// A float image with values from 0 to `top` (linear scene light), alpha 0.5.
lut::Image hdrImage(float top) {
    lut::Image img(32, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x) {
            float* p = img.pixel(x, y);
            p[0] = top * x / 31.0f;
            p[1] = top * 0.5f * y / 15.0f;
            p[2] = 0.18f * (1 + (x + y) % 5);
            p[3] = 0.5f;
        }
    return img;
}

void writeExr(const std::string& path, const lut::Image& img) {
    lut::formats::ImageWriteOptions w;
    w.bitDepth = 32;
    lut::formats::writeImage(path, img, w);
}

// OCIO runs the whole chain on the image: the conversions and the LUT (a FileTransform).
lut::Image ocioChain(const lut::Image& in, const OCIO::ConstTransformRcPtr& t,
                     const std::string& config) {
    auto cfg = OCIO::Config::CreateFromFile(config.c_str());
    const auto p = cfg->getProcessor(t)->getDefaultCPUProcessor();
    lut::Image out = in;
    OCIO::PackedImageDesc desc(out.data(), out.width(), out.height(), 4);
    p->apply(desc);
    return out;
}

OCIO::FileTransformRcPtr lutTransform(const std::string& path) {
    auto ft = OCIO::FileTransform::Create();
    ft->setSrc(path.c_str());
    ft->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
    return ft;
}

OCIO::ColorSpaceTransformRcPtr cst(const char* a, const char* b) {
    auto t = OCIO::ColorSpaceTransform::Create();
    t->setSrc(a);
    t->setDst(b);
    return t;
}

double worstDiff(const lut::Image& a, const lut::Image& b) {
    double w = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i)
        w = std::max(w, std::fabs(double(a.pixels()[i]) - b.pixels()[i]));
    return w;
}

TEST(Colour, ApplyRunsTheLutInItsOwnSpace) {
    const std::string dir = workDir();
    const std::string lut = writeGrade(dir + "/grade.cube"), in = dir + "/in.exr";
    const lut::Image img = hdrImage(4.0f);
    writeExr(in, img);
    // --to: lin -> log (the LUT's space) -> LUT -> log -> gamma22.
    auto r = runCli("apply --lut " + shellQuoted(lut) + " --config " + shellQuoted(testConfig()) +
                    " --from lin --lut-space log --to gamma22 " + shellQuoted(in) + " -o " +
                    shellQuoted(dir + "/to.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // Nothing the LUT saw was above its domain (log of 4 is below 1); the darkest values fall
    // below the log space's 0 and are reported as such (the worst one is negative).
    if (r.err.find("outside the LUT's domain") != std::string::npos) {
        EXPECT_THAT(r.err, HasSubstr("(worst -"));
    }
    auto group = OCIO::GroupTransform::Create();
    group->appendTransform(cst("lin", "log"));
    group->appendTransform(lutTransform(lut));
    group->appendTransform(cst("log", "gamma22"));
    const lut::Image want = ocioChain(img, group, testConfig());
    const auto got = lut::formats::readImage(dir + "/to.exr");
    EXPECT_LE(worstDiff(got.image, want), 1e-4);
    EXPECT_EQ(got.image.pixel(3, 3)[3], 0.5f); // alpha passes through
    // --display/--view instead of --to.
    r = runCli("apply --lut " + shellQuoted(lut) + " --config " + shellQuoted(testConfig()) +
               " --from lin --lut-space log --display Monitor --view Gamma " + shellQuoted(in) +
               " -o " + shellQuoted(dir + "/view.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto dv = OCIO::DisplayViewTransform::Create();
    dv->setSrc("log");
    dv->setDisplay("Monitor");
    dv->setView("Gamma");
    auto g2 = OCIO::GroupTransform::Create();
    g2->appendTransform(cst("lin", "log"));
    g2->appendTransform(lutTransform(lut));
    g2->appendTransform(dv);
    EXPECT_LE(worstDiff(lut::formats::readImage(dir + "/view.exr").image,
                        ocioChain(img, g2, testConfig())),
              1e-4);
    // A look between --from and the LUT's space.
    r = runCli("apply --lut " + shellQuoted(lut) + " --config " + shellQuoted(testConfig()) +
               " --from lin --lut-space log --look warm " + shellQuoted(in) + " -o " +
               shellQuoted(dir + "/look.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto lt = OCIO::LookTransform::Create();
    lt->setSrc("lin");
    lt->setDst("log");
    lt->setLooks("warm");
    auto g3 = OCIO::GroupTransform::Create();
    g3->appendTransform(lt);
    g3->appendTransform(lutTransform(lut));
    EXPECT_LE(worstDiff(lut::formats::readImage(dir + "/look.exr").image,
                        ocioChain(img, g3, testConfig())),
              1e-4);
}

TEST(Colour, ValuesOutsideTheLutsDomainAreReported) {
    const std::string dir = workDir();
    const std::string lut = writeGrade(dir + "/grade.cube"), in = dir + "/in.exr";
    const lut::Image img = hdrImage(7.25f);
    writeExr(in, img);
    std::size_t above = 0; // pixels with a channel above 1 (none below 0, no NaN here)
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            bool out = false;
            for (int c = 0; c < 3; ++c)
                out = out || img.pixel(x, y)[c] > 1.0f;
            above += out;
        }
    ASSERT_GT(above, 0u);
    const auto r = runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(in) + " -o " +
                          shellQuoted(dir + "/out.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr(std::to_string(above) + " of " +
                                 std::to_string(img.width() * img.height()) + " pixels ("));
    EXPECT_THAT(r.err, HasSubstr("outside the LUT's domain [0, 1] (worst 7.25)"));
}

TEST(Colour, BadColourOptionsAreBadUsage) {
    const std::string dir = workDir();
    const std::string lut = writeGrade(dir + "/grade.cube"), in = dir + "/in.exr";
    writeExr(in, hdrImage(1.0f));
    const std::string base =
        "apply --lut " + shellQuoted(lut) + " --config " + shellQuoted(testConfig()) + " ";
    auto r = runCli(base + "--from lni " + shellQuoted(in) + " -o " + shellQuoted(dir + "/o.exr"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("did you mean 'lin'?"));
    r = runCli(base + "--lut-space log " + shellQuoted(in) + " -o " + shellQuoted(dir + "/o.exr"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("--lut-space needs --from"));
    r = runCli(base + "--from lin --to log --display Monitor " + shellQuoted(in) + " -o " +
               shellQuoted(dir + "/o.exr"));
    EXPECT_EQ(r.exitCode, 2);
    r = runCli("preview " + shellQuoted(in) + " -o " + shellQuoted(dir + "/p.png") +
               " --display sRGB");
    EXPECT_EQ(r.exitCode, 2);
    r = runCli("preview " + shellQuoted(in) + " -o " + shellQuoted(dir + "/p.png") +
               " --from-screenshot --from sRGB");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_FALSE(fs::exists(dir + "/o.exr"));
}

TEST(Colour, PreviewFromAndTo) {
    const std::string dir = workDir();
    const std::string scene = samplePath("sample_scene.exr"),
                      cfg = " --config " + shellQuoted(shippedConfig());
    auto r = runCli("preview " + shellQuoted(scene) + " -o " + shellQuoted(dir + "/plain.png") +
                    " --preset filmic");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // --from the space the pipeline takes EXRs in: the same picture (to a 16-bit step).
    r = runCli("preview " + shellQuoted(scene) + " -o " + shellQuoted(dir + "/lin.png") +
               " --preset filmic" + cfg + " --from lin_srgb");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto plain = lut::formats::readImage(dir + "/plain.png");
    EXPECT_LE(worstDiff(lut::formats::readImage(dir + "/lin.png").image, plain.image), 1.5 / 65535);
    // --from another space: another picture.
    r = runCli("preview " + shellQuoted(scene) + " -o " + shellQuoted(dir + "/acescg.png") +
               " --preset filmic" + cfg + " --from ACEScg");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_GT(worstDiff(lut::formats::readImage(dir + "/acescg.png").image, plain.image), 0.01);
    // --to: the display-encoded sRGB output converted by OCIO.
    r = runCli("preview " + shellQuoted(scene) + " -o " + shellQuoted(dir + "/to.exr") +
               " --preset filmic" + cfg + " --to Rec.709");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runCli("preview " + shellQuoted(scene) + " -o " + shellQuoted(dir + "/srgb.exr") +
               " --preset filmic");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const lut::Image want = ocioChain(lut::formats::readImage(dir + "/srgb.exr").image,
                                      cst("sRGB", "Rec.709"), shippedConfig());
    EXPECT_LE(worstDiff(lut::formats::readImage(dir + "/to.exr").image, want), 1e-4);
}

TEST(Colour, ConvertBakesTheConversionsAroundTheLut) {
    // An identity LUT made for sRGB, asked for linear input: the result is OCIO's lin -> sRGB,
    // clamped to the LUT's domain 0..1, through a log2 shaper, within the error the report gives.
    const std::string dir = workDir();
    {
        std::ofstream o(dir + "/id.cube");
        o << "LUT_3D_SIZE 2\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n";
    }
    const auto r = runCli(
        "convert " + shellQuoted(dir + "/id.cube") + " " + shellQuoted(dir + "/lin.cube") +
        " --config " + shellQuoted(shippedConfig()) + " --from lin_srgb --lut-space sRGB --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("\"shaper\": \"log2"));
    const auto e = r.out.find("\"error\": {\"max\": ");
    ASSERT_NE(e, std::string::npos) << r.out;
    const double reported = std::stod(r.out.substr(e + 18));
    EXPECT_LT(reported, 0.02);
    auto cfg = OCIO::Config::CreateFromFile(shippedConfig().c_str());
    const auto truth = cfg->getProcessor("lin_srgb", "sRGB")->getDefaultCPUProcessor();
    const auto file = ocioFileProcessor(dir + "/lin.cube");
    // The reported maximum bounds the truth: 100,000 random inputs, uniform in stops over the
    // shaper's range (2^-12 .. 16).
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<float> stops(-12.0f, 4.0f);
    double worst = 0.0;
    for (int i = 0; i < 100000; ++i) {
        const glm::vec3 x(std::exp2(stops(rng)), std::exp2(stops(rng)), std::exp2(stops(rng)));
        const glm::vec3 a = ocioEval(file, x), b = ocioEval(truth, x);
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::fabs(double(a[c]) - std::clamp(b[c], 0.0f, 1.0f)));
    }
    std::printf("[ measured ] lin_srgb -> sRGB around an identity: truth %.5f, reported %.5f\n",
                worst, reported);
    EXPECT_GE(reported, worst);
    for (float v = 0.0f; v <= 16.0f; v = v * 1.7f + 0.003f) {
        const glm::vec3 x(v, 0.3f * v, 0.05f);
        const glm::vec3 a = ocioEval(file, x), b = ocioEval(truth, x);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(a[c], std::clamp(b[c], 0.0f, 1.0f), reported + 1e-6) << v;
    }
}

TEST(Hald, LevelAsImageMagickNamesIt) {
    const std::string dir = workDir();
    // --level 8 = ImageMagick's hald:8: 512x512, a 64^3 lattice.
    auto r = runCli("neutral --level 8 " + shellQuoted(dir + "/h8.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("64^3 (Hald level 8, 512x512)"));
    auto info = lut::formats::readImageInfo(dir + "/h8.png");
    EXPECT_EQ(info.width, 512);
    EXPECT_EQ(info.height, 512);
    // --size 8 keeps meaning 8^3: not a square, so 9^3 (level 3, 27x27), and the message says so
    // (it said 8^3).
    r = runCli("neutral --size 8 --layout hald " + shellQuoted(dir + "/s8.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("9^3 (Hald level 3, 27x27)"));
    EXPECT_THAT(r.out, Not(HasSubstr("neutral 8^3")));
    info = lut::formats::readImageInfo(dir + "/s8.png");
    EXPECT_EQ(info.width, 27);
    // convert --level: resampled once, to the size the image holds.
    r = runCli("convert " + shellQuoted(samplePath("sample_grade.cube")) + " " +
               shellQuoted(dir + "/c4.png") + " --level 4");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("resample 33^3 -> 16^3"));
    info = lut::formats::readImageInfo(dir + "/c4.png");
    EXPECT_EQ(info.width, 64);
    r = runCli("convert " + shellQuoted(samplePath("sample_grade.cube")) + " " +
               shellQuoted(dir + "/c.cube") + " --level 4");
    EXPECT_EQ(r.exitCode, 2);
    r = runCli("neutral --level 4 --size 16 " + shellQuoted(dir + "/x.png"));
    EXPECT_EQ(r.exitCode, 2);
}

} // namespace
