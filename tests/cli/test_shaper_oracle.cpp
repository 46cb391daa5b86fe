// SPDX-License-Identifier: Apache-2.0
// A Resolve .cube holding a 1D shaper (a log2 shaper of 4096 entries over 0..64) and a 33^3
// grade, through every command that processes pixels with it, against OpenColorIO's processor of
// the same file (FileTransform, OPTIMIZATION_NONE): apply (float EXR), preview's LUT stage, the
// game's LUT made from it (the authoring formula of docs/specs/smash-pipeline.md written here in
// float64, the edit evaluated by OCIO), its inverse (OCIO evaluates both the file and the written
// inverse), a LUT image written from it (its entries against OCIO at the lattice, the printed
// error against the truth between lattice points, interpolated here in float64) and
// --original-lut (the note that says what sampling the stage's LUT cost). Before the fix the
// shaper and table were merged into one 33^3 table over 0..64 first: apply was off OCIO by mean
// 81 / max 108 8-bit steps on a [0,1] gradient.
#include "CliTestSupport.h"
#include "OcioTestUtil.h"
#include "ShapedCube.h"
#include "TestSupport.h"

#include "lut/Image.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>

namespace fs = std::filesystem;
using namespace lut;
using namespace lut::test;
using ::testing::HasSubstr;

namespace {

using lut::test::shellQuoted;

// The shared source (tests/support/ShapedCube.h), in dir.
std::string shapedCubeIn(const std::string& dir) {
    return lut::test::writeShapedCube(dir + "/shaped.cube");
}

// Reads every pixel of an image as float RGB through OpenImageIO.
std::vector<float> readRgb(const std::string& path, int& w, int& h) {
    auto in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << path;
    if (!in)
        return {};
    const OIIO::ImageSpec& spec = in->spec();
    w = spec.width;
    h = spec.height;
    std::vector<float> px(static_cast<std::size_t>(w) * h * spec.nchannels);
    in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data());
    std::vector<float> rgb(static_cast<std::size_t>(w) * h * 3);
    for (std::size_t i = 0; i < static_cast<std::size_t>(w) * h; ++i)
        for (int c = 0; c < 3; ++c)
            rgb[3 * i + c] = px[i * spec.nchannels + static_cast<std::size_t>(c)];
    return rgb;
}

// The number after `key` in text ("max 1.2e-03" -> 1.2e-03); NaN if absent.
double numberAfter(const std::string& text, const std::string& key) {
    const auto at = text.find(key);
    if (at == std::string::npos)
        return NAN;
    return std::strtod(text.c_str() + at + key.size(), nullptr);
}

glm::dvec3 srgbEncode(glm::dvec3 v) {
    for (int c = 0; c < 3; ++c)
        v[c] = v[c] <= 0.0031308 ? 12.92 * v[c] : 1.055 * std::pow(v[c], 1.0 / 2.4) - 0.055;
    return v;
}

glm::dvec3 srgbDecode(glm::dvec3 v) {
    for (int c = 0; c < 3; ++c)
        v[c] = v[c] <= 0.04045 ? v[c] / 12.92 : std::pow((v[c] + 0.055) / 1.055, 2.4);
    return v;
}

} // namespace

TEST(ShaperOracle, ApplyEqualsOcioOnFloatImages) {
    const std::string dir = workDir();
    const std::string cube = shapedCubeIn(dir);
    // 64x64 pixels: most in [0,1], a quarter HDR up to 64 (the shaper's range).
    Image img(64, 64);
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), hdr(0.0f, 64.0f);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            float* p = img.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = y < 48 ? unit(rng) : hdr(rng);
            p[3] = 1.0f;
        }
    formats::ImageWriteOptions wo(32, false, false);
    formats::writeImage(dir + "/in.exr", img, wo);
    const RunResult r =
        runCli("apply --lut " + shellQuoted(cube) + " " + shellQuoted(dir + "/in.exr") + " -o " +
               shellQuoted(dir + "/out.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    int w = 0, h = 0;
    const std::vector<float> got = readRgb(dir + "/out.exr", w, h);
    ASSERT_EQ(w, 64);
    const auto ocio = ocioFileProcessor(cube);
    double worst = 0, sum = 0;
    for (int i = 0; i < 64 * 64; ++i) {
        const float* p = img.pixel(i % 64, i / 64);
        glm::vec3 want(p[0], p[1], p[2]);
        ocio->applyRGB(&want.x);
        for (int c = 0; c < 3; ++c) {
            const double d = std::fabs(double(got[3 * i + c]) - want[c]);
            worst = std::max(worst, d);
            sum += d;
        }
    }
    EXPECT_LT(worst * 255, 0.01) << "max 8-bit steps from OCIO; mean " << sum / (3 * 4096) * 255;
}

TEST(ShaperOracle, PreviewLutStageEqualsOcio) {
    // preview's LUT stage alone (preset none, lut on, display off) on a linear float scene: the
    // none preset's recipe (lut::planPreview, docs/pipeline.md) display-encodes a scene (the
    // piecewise sRGB curve), then runs the LUT.
    const std::string dir = workDir();
    const std::string cube = shapedCubeIn(dir);
    Image img(32, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            float* p = img.pixel(x, y);
            p[0] = x / 31.0f;
            p[1] = y / 31.0f;
            p[2] = (x + y) / 62.0f * 4.0f; // up to 4: HDR
            p[3] = 1.0f;
        }
    formats::writeImage(dir + "/scene.exr", img, formats::ImageWriteOptions(32, false, false));
    const RunResult r =
        runCli("preview " + shellQuoted(dir + "/scene.exr") + " -o " + shellQuoted(dir + "/p.exr") +
               " --preset none --enable lut --disable display --interp "
               "tetrahedral --lut " +
               shellQuoted(cube));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    int w = 0, h = 0;
    const std::vector<float> got = readRgb(dir + "/p.exr", w, h);
    ASSERT_EQ(w, 32);
    const auto ocio = ocioFileProcessor(cube);
    double worst = 0;
    for (int i = 0; i < 32 * 32; ++i) {
        const float* p = img.pixel(i % 32, i / 32);
        glm::vec3 want(srgbEncode(glm::dvec3(p[0], p[1], p[2])));
        ocio->applyRGB(&want.x);
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::fabs(double(got[3 * i + c]) - want[c]));
    }
    EXPECT_LT(worst * 255, 0.01) << "max 8-bit steps from OCIO";
}

TEST(ShaperOracle, GameLutIsTheFormulaOfTheExactEdit) {
    // convert shaped.cube game.nutexb (the default target: the game shows the edit): every entry
    // is L(s) = (srgb^-1(wanted(s))^(1/2.2) / 1.3703 - s) / 0.99961 + s with shown(s) =
    // srgb(min(1, (s * 1.3703)^2.2)) (neutral stage LUT) and the edit evaluated by OCIO on that
    // displayed, clipped colour (wanted = edit(shown) clamped to [0,1]; where wanted is white, the
    // neutral stage's own entry s when it shows white too: the one rule above white,
    // lut/smash/SmashAuthoring.h), clamped to [0,1] and rounded to 8 bits.
    const std::string dir = workDir();
    const std::string cube = shapedCubeIn(dir);
    const RunResult r =
        runCli("convert " + shellQuoted(cube) + " " + shellQuoted(dir + "/game.nutexb"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const LutFile back = formats::readLut(dir + "/game.nutexb");
    ASSERT_TRUE(back.cube);
    const auto ocio = ocioFileProcessor(cube);
    int off = 0;
    double worst = 0;
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int rr = 0; rr < 16; ++rr) {
                const glm::dvec3 s = glm::dvec3(rr, g, b) / 15.0;
                glm::dvec3 shown;
                for (int c = 0; c < 3; ++c)
                    shown[c] = std::min(1.0, std::pow(s[c] * 1.3703, 2.2));
                shown = srgbEncode(shown);
                glm::vec3 e(shown);
                ocio->applyRGB(&e.x);
                glm::dvec3 wanted;
                for (int c = 0; c < 3; ++c)
                    wanted[c] = std::clamp(double(e[c]), 0.0, 1.0);
                const glm::dvec3 lin = srgbDecode(wanted);
                for (int c = 0; c < 3; ++c) {
                    double l = (std::pow(lin[c], 1.0 / 2.2) / 1.3703 - s[c]) / 0.99961 + s[c];
                    if (wanted[c] >= 1.0 - 1e-6)
                        l = std::max(l, s[c]);
                    const double want = std::round(std::clamp(l, 0.0, 1.0) * 255.0);
                    const double have = std::round(back.cube->at(rr, g, b)[c] * 255.0);
                    worst = std::max(worst, std::fabs(have - want));
                    off += have != want;
                }
            }
    EXPECT_LE(worst, 1.0) << "8-bit codes from the formula";
    EXPECT_LT(off, 16 * 16 * 16 * 3 / 100) << "codes off by one (rounding near a half)";
}

TEST(ShaperOracle, InverseResidualWithinThePrintedBound) {
    const std::string dir = workDir();
    const std::string cube = shapedCubeIn(dir);
    const std::string inv = dir + "/inverse.cube";
    const RunResult r = runCli("invert " + shellQuoted(cube) + " " + shellQuoted(inv));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_THAT(r.out, HasSubstr("between the inverse's lattice points"));
    const double printed = numberAfter(r.out.substr(r.out.find("between  ")), ": max ");
    ASSERT_TRUE(std::isfinite(printed)) << r.out;
    // The truth on other targets: OCIO reads the inverse and the source.
    const auto f = ocioFileProcessor(cube);
    const auto g = ocioFileProcessor(inv);
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    double truth = 0;
    for (int k = 0; k < 20000; ++k) {
        const glm::vec3 y(u(rng), u(rng), u(rng));
        glm::vec3 x = y;
        g->applyRGB(&x.x);
        f->applyRGB(&x.x);
        for (int c = 0; c < 3; ++c)
            truth = std::max(truth, std::fabs(double(x[c]) - y[c]));
    }
    EXPECT_GE(printed * 1.0001 + 1e-6, truth) << r.out;
}

TEST(ShaperOracle, LutImageSampledFromTheExactFile) {
    // A format that stores no shaper (an EXR strip): the shaper then the table at the strip's
    // lattice over [0,1], and a printed error that bounds the truth between lattice points.
    const std::string dir = workDir();
    const std::string cube = shapedCubeIn(dir);
    const std::string strip = dir + "/strip.exr";
    const RunResult r = runCli("convert " + shellQuoted(cube) + " " + shellQuoted(strip) +
                               " --size 17 --target raw");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_THAT(r.out + r.err, HasSubstr("sampled at a 17^3 lattice over 0..1"));
    const std::string all = r.out + r.err;
    const double printed = numberAfter(all.substr(all.find("sampled at a 17^3")), "): max ");
    ASSERT_TRUE(std::isfinite(printed)) << all;
    const LutFile back = formats::readLut(strip);
    ASSERT_TRUE(back.cube);
    ASSERT_EQ(back.cube->size(), 17);
    const auto ocio = ocioFileProcessor(cube);
    for (int b = 0; b < 17; b += 4)
        for (int g = 0; g < 17; g += 4)
            for (int rr = 0; rr < 17; ++rr) {
                glm::vec3 x = glm::vec3(rr, g, b) / 16.0f;
                ocio->applyRGB(&x.x);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(back.cube->at(rr, g, b)[c], x[c], 2e-5)
                        << rr << " " << g << " " << b;
            }
    // Between lattice points: the strip interpolated tetrahedrally (written here in float64)
    // against the source evaluated by OCIO.
    const Lut3D& t = *back.cube;
    auto tetra = [&](glm::vec3 x) {
        double f[3];
        int i[3];
        for (int c = 0; c < 3; ++c) {
            const double v = std::clamp(double(x[c]), 0.0, 1.0) * 16.0;
            i[c] = std::min(15, static_cast<int>(v));
            f[c] = v - i[c];
        }
        auto e = [&](int dr, int dg, int db) {
            return glm::dvec3(t.at(i[0] + dr, i[1] + dg, i[2] + db));
        };
        const double fr = f[0], fg = f[1], fb = f[2];
        const glm::dvec3 c000 = e(0, 0, 0), c111 = e(1, 1, 1);
        if (fr > fg) {
            if (fg > fb)
                return (1 - fr) * c000 + (fr - fg) * e(1, 0, 0) + (fg - fb) * e(1, 1, 0) +
                       fb * c111;
            if (fr > fb)
                return (1 - fr) * c000 + (fr - fb) * e(1, 0, 0) + (fb - fg) * e(1, 0, 1) +
                       fg * c111;
            return (1 - fb) * c000 + (fb - fr) * e(0, 0, 1) + (fr - fg) * e(1, 0, 1) + fg * c111;
        }
        if (fb > fg)
            return (1 - fb) * c000 + (fb - fg) * e(0, 0, 1) + (fg - fr) * e(0, 1, 1) + fr * c111;
        if (fb > fr)
            return (1 - fg) * c000 + (fg - fb) * e(0, 1, 0) + (fb - fr) * e(0, 1, 1) + fr * c111;
        return (1 - fg) * c000 + (fg - fr) * e(0, 1, 0) + (fr - fb) * e(1, 1, 0) + fb * c111;
    };
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    double truth = 0;
    for (int k = 0; k < 20000; ++k) {
        glm::vec3 a(u(rng), u(rng), u(rng));
        const glm::dvec3 b = tetra(a);
        ocio->applyRGB(&a.x);
        for (int c = 0; c < 3; ++c)
            truth = std::max(truth, std::fabs(double(a[c]) - b[c]));
    }
    EXPECT_GE(printed * 1.0001 + 1e-6, truth) << all;
}

TEST(ShaperOracle, OriginalLutWithAShaperSaysWhatSamplingCost) {
    const std::string dir = workDir();
    const std::string cube = shapedCubeIn(dir);
    Image shot(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            float* p = shot.pixel(x, y);
            p[0] = x / 63.0f;
            p[1] = y / 63.0f;
            p[2] = 0.5f;
            p[3] = 1.0f;
        }
    formats::writeImage(dir + "/shot.png", shot, formats::ImageWriteOptions(8, false, false));
    const RunResult r =
        runCli("preview " + shellQuoted(dir + "/shot.png") + " -o " + shellQuoted(dir + "/p.png") +
               " --original-lut " + shellQuoted(cube));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr("sampled at the game's 16^3 lattice over [0,1]"));
    EXPECT_THAT(r.err, HasSubstr("inputs between lattice points"));
}

namespace {

// The largest difference between two OpenColorIO processors over random inputs in 0..top (the
// shaper's range 0..64 by default; inputs neither file's lattice was built on).
double largestDifference(const OCIO::ConstCPUProcessorRcPtr& p,
                         const OCIO::ConstCPUProcessorRcPtr& q, int count, unsigned seed,
                         float top = 64.0f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, top);
    double worst = 0;
    for (int k = 0; k < count; ++k) {
        const glm::vec3 x(u(rng), u(rng), u(rng));
        const glm::vec3 a = ocioEval(p, x), b = ocioEval(q, x);
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::fabs(double(a[c]) - b[c]));
    }
    return worst;
}

} // namespace

// A titled Resolve file (lutkit reads the TITLE; OpenColorIO's Resolve reader refuses it):
// convert keeps the shaper and the title, as a comment, so OpenColorIO reads what lutkit wrote
// and gives what it gives for the same file without its title. Before the fix the TITLE line was
// written as it came, and OpenColorIO refused the output ("Unsupported tag: 'TITLE'").
TEST(ShaperOracle, TitledShaperCubeWrittenSoOcioReadsIt) {
    const std::string dir = workDir();
    const std::string plain = shapedCubeIn(dir);
    const std::string titled = dir + "/titled.cube";
    {
        std::ifstream in(plain);
        std::ofstream out(titled);
        out << "TITLE \"warm log grade\"\n" << in.rdbuf();
    }
    const std::string out = dir + "/out.cube";
    const RunResult r = runCli("convert " + shellQuoted(titled) + " " + shellQuoted(out));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::ifstream written(out);
    const std::string text((std::istreambuf_iterator<char>(written)), {});
    EXPECT_THAT(text, HasSubstr("LUT_1D_SIZE 4096")); // the shaper kept
    EXPECT_THAT(text, HasSubstr("warm log grade"));   // and the title
    const auto want = ocioFileProcessor(plain);
    OCIO::ConstCPUProcessorRcPtr got;
    ASSERT_NO_THROW(got = ocioFileProcessor(out)) << text.substr(0, 200);
    EXPECT_LT(largestDifference(want, got, 5000, 5), 1e-6);
}

// --format iridas_cube (OpenColorIO's baker name for the Adobe dialect, which has no shaper):
// the shaper and table are sampled at one lattice over 0..1 (where display pictures live; issue
// 40: over the shaper's 0..64 inputs in 0..1 were off by mean 85 steps) with a warning that says
// what it cost, and OpenColorIO's Iridas reader reads the result; the printed maximum bounds the
// truth over 0..1, OpenColorIO's result for the written file against its result for the source,
// at inputs the sampling did not use. Before the first fix the alias was ignored and a Resolve
// file with LUT_1D_SIZE was written.
TEST(ShaperOracle, IridasCubeBakesTheShaperWithinThePrintedError) {
    const std::string dir = workDir();
    const std::string cube = shapedCubeIn(dir);
    const std::string out = dir + "/adobe.cube";
    const RunResult r =
        runCli("convert " + shellQuoted(cube) + " " + shellQuoted(out) + " --format iridas_cube");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::ifstream written(out);
    const std::string text((std::istreambuf_iterator<char>(written)), {});
    EXPECT_THAT(text, ::testing::Not(HasSubstr("LUT_1D"))) << text.substr(0, 200);
    const std::string all = r.out + r.err;
    const std::string said = "sampled at a 33^3 lattice over 0..1, where display pictures live";
    ASSERT_THAT(all, HasSubstr(said));
    const double printed = numberAfter(all.substr(all.find(said)), "max ");
    ASSERT_TRUE(std::isfinite(printed)) << all;
    const auto src = ocioFileProcessor(cube);
    const auto got = ocioFileProcessor(out);
    const double truth = largestDifference(src, got, 20000, 11, 1.0f);
    EXPECT_GE(printed * 1.0001 + 1e-6, truth) << all;
}
