// SPDX-License-Identifier: Apache-2.0
// The 1024x32 strips (docs/specs/strip-layouts.md): files written in the reshade and unity-32
// layouts, read back with OpenImageIO directly and sampled with the engines' own shader formulas
// (tests/support/ShaderSamplers.h: ReShade's LUT.fx, Unity's ApplyLut2D) against a float64
// trilinear interpolation of the LUT: within half an 8-bit step. Detection names the 1024x32
// variants; other sizes are refused under those names.
#include "lut/Error.h"
#include "lut/formats/Registry.h"
#include "lut/io/Layout.h"

#include "ShaderSamplers.h"
#include "TestSupport.h"

#include <gtest/gtest.h>

#include <glm/vec3.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <random>

using lut::test::load;
using lut::test::reshadeSample;
using lut::test::tempDir;
using lut::test::Texture;
using lut::test::trilinear;
using lut::test::unitySample;

namespace {

lut::Lut3D lutOf(int n, const std::function<glm::dvec3(glm::dvec3)>& f) {
    lut::Lut3D l(n);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                l.at(r, g, b) = glm::vec3(f(glm::dvec3(l.latticeInput(r, g, b))));
    return l;
}

// Three different grades: a warm contrast curve, a channel swap with a cool tint, a sepia tone.
std::vector<lut::Lut3D> threeLuts(int n) {
    return {
        lutOf(n,
              [](glm::dvec3 c) {
                  return glm::dvec3(std::pow(c.x, 0.8), c.y * c.y * (3 - 2 * c.y),
                                    0.9 * std::pow(c.z, 1.2));
              }),
        lutOf(n, [](glm::dvec3 c) { return glm::dvec3(0.8 * c.y, 0.9 * c.z, 0.1 + 0.9 * c.x); }),
        lutOf(n, [](glm::dvec3 c) {
            const double y = 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
            return glm::dvec3(std::min(1.0, 1.07 * y), 0.74 * y + 0.1, 0.43 * y + 0.05);
        })};
}

std::string write(const std::string& path, const lut::Lut3D& l, lut::LutLayout layout,
                  lut::Diagnostics* diags = nullptr) {
    lut::LutFile f;
    f.cube = l;
    lut::FormatOptions o;
    o.layout = layout;
    const lut::Diagnostics d = lut::formats::writeLut(path, f, o);
    if (diags)
        *diags = d;
    return path;
}

// Largest difference (8-bit steps) between a shader's sampling of the file and the LUT, at every
// lattice point and at 3000 random colours.
double worstSteps(const lut::Lut3D& l,
                  const std::function<std::array<double, 3>(glm::dvec3)>& shader) {
    double worst = 0;
    auto check = [&](glm::dvec3 c) {
        const auto got = shader(c), want = trilinear(l, c);
        for (int ch = 0; ch < 3; ++ch)
            worst = std::max(worst, std::fabs(got[ch] - want[ch]) * 255.0);
    };
    const int n = l.size();
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                check(glm::dvec3(r, g, b) / double(n - 1));
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 3000; ++i)
        check(glm::dvec3(u(rng), u(rng), u(rng)));
    return worst;
}

} // namespace

TEST(Reshade, StripsAreWhatLutFxSamples) {
    const std::string dir = tempDir();
    int k = 0;
    for (const lut::Lut3D& l : threeLuts(32)) {
        const std::string path =
            write(dir + "/l" + std::to_string(k++) + ".png", l, lut::LutLayout::Reshade);
        const Texture tex = load(path);
        ASSERT_EQ(tex.w, 1024);
        ASSERT_EQ(tex.h, 32);
        const double worst = worstSteps(l, [&](glm::dvec3 c) { return reshadeSample(tex, c); });
        // half a step, plus float rounding of v * 255 at a tie (the writer rounds floats)
        EXPECT_LE(worst, 0.5 + 1e-4) << "LUT " << k;
        // and the same file is not a Unity strip: green runs the other way
        EXPECT_GT(worstSteps(l, [&](glm::dvec3 c) { return unitySample(tex, c); }), 10.0);
    }
}

TEST(Reshade, Unity32IsWhatApplyLut2DSamples) {
    const std::string dir = tempDir();
    int k = 0;
    for (const lut::Lut3D& l : threeLuts(32)) {
        const std::string path =
            write(dir + "/u" + std::to_string(k++) + ".png", l, lut::LutLayout::Unity32);
        const Texture tex = load(path);
        ASSERT_EQ(tex.w, 1024);
        ASSERT_EQ(tex.h, 32);
        EXPECT_LE(worstSteps(l, [&](glm::dvec3 c) { return unitySample(tex, c); }), 0.5 + 1e-4);
    }
}

TEST(Reshade, OtherSizesAreResampledTo32WithTheErrorSaid) {
    const std::string dir = tempDir();
    const lut::Lut3D l33 = threeLuts(33)[0];
    lut::Diagnostics d;
    const std::string path = dir + "/r.png";
    write(path, l33, lut::LutLayout::Reshade, &d);
    bool said = false;
    for (const auto& x : d)
        said = said || x.message.find("resampled 33^3 -> 32^3") != std::string::npos;
    EXPECT_TRUE(said);
    EXPECT_EQ(load(path).w, 1024);
    // An explicit other size is refused, naming the base layout that takes any N.
    lut::LutFile f;
    f.cube = l33;
    lut::FormatOptions o;
    o.layout = lut::LutLayout::Reshade;
    o.size = 16;
    try {
        lut::formats::writeLut(dir + "/x.png", f, o);
        FAIL();
    } catch (const lut::Error& e) {
        EXPECT_NE(std::string(e.what()).find("1024x32 (32^3), not 16^3 (unreal"), std::string::npos)
            << e.what();
    }
}

TEST(Reshade, The1024x32VariantsAreDetectedByName) {
    const std::string dir = tempDir();
    const lut::Lut3D graded = threeLuts(32)[0]; // each channel follows its own axis
    for (const lut::LutLayout layout :
         {lut::LutLayout::Reshade, lut::LutLayout::Unity32, lut::LutLayout::Smush}) {
        SCOPED_TRACE(lut::toString(layout));
        for (const lut::Lut3D& l : {lut::Lut3D::identity(32), graded}) {
            const std::string path = write(dir + "/d.png", l, layout);
            const lut::LutFile f = lut::formats::readLut(path);
            EXPECT_EQ(f.dialect, lut::toString(layout));
            double worst = 0;
            for (std::size_t i = 0; i < l.entryCount(); ++i)
                for (int c = 0; c < 3; ++c)
                    worst = std::max(
                        worst, std::fabs(double(f.cube->entries()[i][c]) - l.entries()[i][c]));
            EXPECT_LE(worst * 255.0, 0.5 + 1e-4);
        }
    }
    // Unreal's and Unity's names read the same pixels at 1024x32.
    write(dir + "/r.png", graded, lut::LutLayout::Reshade);
    lut::FormatOptions unreal;
    unreal.layout = lut::LutLayout::Pilot;
    EXPECT_EQ(lut::formats::readLut(dir + "/r.png", unreal).cube->entries(),
              lut::formats::readLut(dir + "/r.png").cube->entries());
    lut::FormatOptions alias;
    alias.layout = lut::parseLayout("unreal-32");
    EXPECT_EQ(lut::formats::readLut(dir + "/r.png", alias).dialect, "reshade");
    // A 256x16 strip is not a reshade strip.
    write(dir + "/s.png", lut::Lut3D::identity(16), lut::LutLayout::Pilot);
    lut::FormatOptions reshade;
    reshade.layout = lut::LutLayout::Reshade;
    try {
        (void)lut::formats::readLut(dir + "/s.png", reshade);
        FAIL();
    } catch (const lut::Error& e) {
        EXPECT_NE(std::string(e.what()).find("the reshade layout needs 1024x32"), std::string::npos)
            << e.what();
    }
}
