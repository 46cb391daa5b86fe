// SPDX-License-Identifier: Apache-2.0
// --strength, --luma-strength and --chroma-strength on convert, apply and extract: what they
// write against the float64 Oklab blend of tests/support/OklabReference.h, the ends (0 = neutral,
// 1 = the LUT) bit for bit, and bad values as bad usage.
#include "CliTestSupport.h"
#include "OklabReference.h"

#include "lut/Quantize.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

using namespace lut;
using namespace lut::test;

namespace {

// A grade that moves lightness, chroma and hue (contrast, saturation, a warm tint).
glm::dvec3 grade(glm::dvec3 c) {
    glm::dvec3 t;
    for (int i = 0; i < 3; ++i)
        t[i] = c[i] * c[i] * (3.0 - 2.0 * c[i]);
    const double y = 0.2126 * t.x + 0.7152 * t.y + 0.0722 * t.z;
    const glm::dvec3 s = glm::dvec3(y) + 1.5 * (t - glm::dvec3(y));
    return glm::clamp(s * glm::dvec3(1.06, 1.0, 0.88) + glm::dvec3(0.02, 0.0, -0.01), 0.0, 1.0);
}

// The grade on an n^3 lattice, as a .cube file written with 9 digits.
Lut3D writeGradeCube(const std::string& path, int n) {
    Lut3D l(n);
    std::ofstream f(path);
    f.precision(9);
    f << "LUT_3D_SIZE " << n << "\n";
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                l.at(r, g, b) = glm::vec3(grade(glm::dvec3(l.latticeInput(r, g, b))));
                const glm::vec3 e = l.at(r, g, b);
                f << e.r << " " << e.g << " " << e.b << "\n";
            }
    return l;
}

Lut3D readTable(const std::string& path) {
    return formats::readLut(path).toLut3D();
}

bool sameBits(const Lut3D& a, const Lut3D& b) {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), a.entryCount() * sizeof(glm::vec3)) == 0;
}

} // namespace

TEST(CliStrength, ConvertWritesTheOklabBlend) {
    const std::string dir = workDir();
    const Lut3D lut = writeGradeCube(dir + "/grade.cube", 9);
    const RunResult r = runCli("convert '" + dir + "/grade.cube' '" + dir +
                               "/out.cube' --luma-strength 0.3 --chroma-strength 0.9");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("strength luma 0.3, chroma 0.9"), std::string::npos) << r.out;
    const Lut3D out = readTable(dir + "/out.cube");
    ASSERT_EQ(out.size(), 9);
    double worst = 0;
    for (int b = 0; b < 9; ++b)
        for (int g = 0; g < 9; ++g)
            for (int rr = 0; rr < 9; ++rr) {
                const glm::dvec3 want = strengthBlend(glm::dvec3(lut.latticeInput(rr, g, b)),
                                                      glm::dvec3(lut.at(rr, g, b)), 0.3, 0.9);
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::fabs(out.at(rr, g, b)[c] - want[c]));
            }
    EXPECT_LT(worst, 2e-6);

    // The ends, bit for bit: 0 is the neutral LUT, 1 the LUT.
    ASSERT_EQ(
        runCli("convert '" + dir + "/grade.cube' '" + dir + "/zero.cube' --strength 0").exitCode,
        0);
    EXPECT_TRUE(sameBits(readTable(dir + "/zero.cube"), Lut3D::identity(9)));
    ASSERT_EQ(
        runCli("convert '" + dir + "/grade.cube' '" + dir + "/one.cube' --strength 1").exitCode, 0);
    EXPECT_TRUE(sameBits(readTable(dir + "/one.cube"), lut));
}

TEST(CliStrength, JsonSaysTheAmounts) {
    const std::string dir = workDir();
    writeGradeCube(dir + "/grade.cube", 5);
    RunResult r =
        runCli("convert '" + dir + "/grade.cube' '" + dir + "/a.cube' --strength 0.5 --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\"strength\": {\"luma\": 0.5, \"chroma\": 0.5}"), std::string::npos)
        << r.out;
    r = runCli("convert '" + dir + "/grade.cube' '" + dir + "/b.cube' --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\"strength\": null"), std::string::npos) << r.out;
}

TEST(CliStrength, ApplyGivesTheBlendAtTheLatticePoints) {
    // An 18^3 LUT: 8-bit codes 15 k are its lattice inputs, where apply returns the (blended)
    // entries exactly, so the 8-bit output is the float64 blend rounded to nearest.
    const std::string dir = workDir();
    const Lut3D lut = writeGradeCube(dir + "/grade.cube", 18);
    Image img(18, 18);
    for (int y = 0; y < 18; ++y)
        for (int x = 0; x < 18; ++x) {
            float* p = img.pixel(x, y);
            p[0] = static_cast<float>(15 * x / 255.0);
            p[1] = static_cast<float>(15 * y / 255.0);
            p[2] = static_cast<float>(15 * ((x * 7 + y * 5) % 18) / 255.0);
            p[3] = 1.0f;
        }
    formats::writeImage(dir + "/in.png", img, {8, false, true});
    const RunResult r = runCli("apply --lut '" + dir + "/grade.cube' --strength 0.6 '" + dir +
                               "/in.png' -o '" + dir + "/out.png'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Image got = formats::readImage(dir + "/out.png").image;
    int checked = 0;
    for (int y = 0; y < 18; ++y)
        for (int x = 0; x < 18; ++x) {
            const float* p = img.pixel(x, y);
            const int ri = x, gi = y, bi = (x * 7 + y * 5) % 18;
            const glm::dvec3 want = strengthBlend(glm::dvec3(p[0], p[1], p[2]),
                                                  glm::dvec3(lut.at(ri, gi, bi)), 0.6, 0.6);
            for (int c = 0; c < 3; ++c) {
                const double s = std::clamp(want[c], 0.0, 1.0) * 255.0;
                if (std::fabs(s - std::floor(s) - 0.5) < 1e-3)
                    continue; // float and double may round apart
                EXPECT_EQ(std::lround(got.pixel(x, y)[c] * 255.0), std::lround(s))
                    << x << "," << y << " channel " << c;
                ++checked;
            }
        }
    EXPECT_GT(checked, 900);
}

TEST(CliStrength, ExtractFromAGradedStripAtHalfStrength) {
    // A graded neutral strip (Smush-LUT's neutral.png workflow), extracted raw at strength 0.5:
    // the strip's entries blended with their inputs.
    const std::string dir = workDir();
    Lut3D strip(16);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                const glm::dvec3 e = grade(glm::dvec3(strip.latticeInput(r, g, b)));
                strip.at(r, g, b) =
                    glm::vec3(toUnorm8(static_cast<float>(e.x)), toUnorm8(static_cast<float>(e.y)),
                              toUnorm8(static_cast<float>(e.z))) /
                    255.0f;
            }
    LutFile f;
    f.cube = strip;
    formats::writeLut(dir + "/graded.png", f, {});
    const RunResult r = runCli("extract '" + dir + "/graded.png' '" + dir +
                               "/half.cube' --target raw --strength 0.5");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("strength: 0.5"), std::string::npos) << r.out;
    const Lut3D out = readTable(dir + "/half.cube");
    ASSERT_EQ(out.size(), 16);
    double worst = 0;
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int rr = 0; rr < 16; ++rr) {
                const glm::dvec3 in = glm::dvec3(rr, g, b) * (1.0 / 15.0);
                // the strip's 8-bit neutral is 17 k / 255 = k / 15 exactly
                const glm::dvec3 want = strengthBlend(in, glm::dvec3(strip.at(rr, g, b)), 0.5, 0.5);
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::fabs(out.at(rr, g, b)[c] - want[c]));
            }
    EXPECT_LT(worst, 2e-6);
}

TEST(CliStrength, TheGamesLutIsMadeFromTheBlendedEdit) {
    // convert --target smash at a strength: the game's LUT for the edit blended with neutral, the
    // same file as the one made from a .cube of that blend written here from the reference.
    const std::string dir = workDir();
    const Lut3D lut = writeGradeCube(dir + "/grade.cube", 17);
    {
        std::ofstream f(dir + "/blend.cube");
        f.precision(9);
        f << "LUT_3D_SIZE 17\n";
        for (int b = 0; b < 17; ++b)
            for (int g = 0; g < 17; ++g)
                for (int r = 0; r < 17; ++r) {
                    const glm::dvec3 e = strengthBlend(glm::dvec3(lut.latticeInput(r, g, b)),
                                                       glm::dvec3(lut.at(r, g, b)), 0.7, 0.2);
                    f << static_cast<float>(e.x) << " " << static_cast<float>(e.y) << " "
                      << static_cast<float>(e.z) << "\n";
                }
    }
    RunResult r = runCli("convert '" + dir + "/grade.cube' '" + dir +
                         "/a.nutexb' --luma-strength 0.7 --chroma-strength 0.2");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("of the edit"), std::string::npos) << r.out;
    r = runCli("convert '" + dir + "/blend.cube' '" + dir + "/b.nutexb'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Lut3D a = readTable(dir + "/a.nutexb"), b = readTable(dir + "/b.nutexb");
    double worst = 0;
    for (std::size_t i = 0; i < a.entryCount(); ++i)
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::fabs(double(a.entries()[i][c]) - b.entries()[i][c]));
    // 8-bit entries: at most one code apart (the blend went through 9-digit text); a strength
    // that was ignored would put them tens of codes apart.
    EXPECT_LE(worst * 255.0, 1.0 + 1e-6);
}

TEST(CliStrength, BadAmountsAreBadUsage) {
    const std::string dir = workDir();
    writeGradeCube(dir + "/grade.cube", 3);
    const std::string conv = "convert '" + dir + "/grade.cube' '" + dir + "/o.cube' ";
    for (const char* bad : {"--strength 2.5", "--strength -0.1", "--luma-strength nan",
                            "--chroma-strength x", "--strength"}) {
        const RunResult r = runCli(conv + bad);
        EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir + "/o.cube"));
    // With colour conversions: not yet, said as bad usage.
    const RunResult r = runCli(conv + "--strength 0.5 --from ACEScg --lut-space sRGB --to sRGB");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("--strength"), std::string::npos) << r.err;
}

// Issue 40: ReShade's LUT.fx sliders of the same names blend the stored RGB by its length and its
// direction, not in Oklab. --strength-blend reshade writes that blend: each entry against the
// shader's formula written here in float64 (crosire/reshade-shaders, Shaders/LUT.fx:
// lerp(normalize(x), normalize(y), chroma) * lerp(length(x), length(y), luma)); the default stays
// the Oklab blend, and the two are far apart.
TEST(CliStrength, ReShadeBlendIsTheShadersFormula) {
    const std::string dir = workDir();
    const Lut3D lut = writeGradeCube(dir + "/grade.cube", 9);
    const RunResult r =
        runCli("convert '" + dir + "/grade.cube' '" + dir +
               "/rs.cube' --luma-strength 0.5 --chroma-strength 0.3 --strength-blend reshade");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("as ReShade's LUT.fx"), std::string::npos) << r.out;
    ASSERT_EQ(runCli("convert '" + dir + "/grade.cube' '" + dir +
                     "/ok.cube' --luma-strength 0.5 --chroma-strength 0.3")
                  .exitCode,
              0);
    const Lut3D rs = readTable(dir + "/rs.cube"), ok = readTable(dir + "/ok.cube");
    double worst = 0, apart = 0, apartSum = 0;
    for (int b = 0; b < 9; ++b)
        for (int g = 0; g < 9; ++g)
            for (int rr = 0; rr < 9; ++rr) {
                const glm::dvec3 x(lut.latticeInput(rr, g, b)), y(lut.at(rr, g, b));
                const double lx = std::sqrt(x.x * x.x + x.y * x.y + x.z * x.z);
                const double ly = std::sqrt(y.x * y.x + y.y * y.y + y.z * y.z);
                const glm::dvec3 nx = lx > 0 ? x / lx : glm::dvec3(0.0);
                const glm::dvec3 ny = ly > 0 ? y / ly : glm::dvec3(0.0);
                const glm::dvec3 want = (nx + 0.3 * (ny - nx)) * (lx + 0.5 * (ly - lx));
                for (int c = 0; c < 3; ++c) {
                    worst = std::max(worst, std::fabs(rs.at(rr, g, b)[c] - want[c]));
                    const double d = std::fabs(double(rs.at(rr, g, b)[c]) - ok.at(rr, g, b)[c]);
                    apart = std::max(apart, d);
                    apartSum += d;
                }
            }
    EXPECT_LT(worst, 2e-6);
    std::printf("[ measured ] ReShade vs Oklab blend at luma 0.5, chroma 0.3: mean %.2f, max %.1f "
                "8-bit steps\n",
                apartSum / (3 * 729) * 255, apart * 255);
    EXPECT_GT(apart * 255, 4.0);
    EXPECT_EQ(runCli("convert '" + dir + "/grade.cube' '" + dir +
                     "/bad.cube' --strength 0.5 --strength-blend lab")
                  .exitCode,
              2);
}
