// SPDX-License-Identifier: Apache-2.0
// What a table's content says about its purpose (lut/LutFile.h's gameLutEvidence, the rule
// decidePurpose applies to a file that says nothing; issue 40): game LUTs made for the default
// brighten pass as Smush-LUT makes them are recognised, plausible edits are not. Both kinds are
// written here in float64: the game's LUT by Smush-LUT's formula (docs/specs/smash-pipeline.md,
// "The Smush compensation", on the displayed, clipped screenshot), the edits plainly.
#include "lut/LutFile.h"
#include "lut/Quantize.h"

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace lut;

namespace {

using Edit = std::function<glm::dvec3(glm::dvec3)>;

double clamp01(double v) {
    return std::clamp(v, 0.0, 1.0);
}
double srgbEnc(double x) {
    x = clamp01(x);
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055;
}
double srgbDec(double v) {
    v = clamp01(v);
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
double luma(glm::dvec3 c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// The edits: what a modder or a colourist might do to a picture.
std::vector<std::pair<std::string, Edit>> edits() {
    auto perChannel = [](std::function<double(double)> f) -> Edit {
        return [f](glm::dvec3 c) { return glm::dvec3(f(c.x), f(c.y), f(c.z)); };
    };
    auto exposure = [](double stops) {
        return [stops](double v) { return srgbEnc(srgbDec(v) * std::pow(2.0, stops)); };
    };
    auto sepia = [](double k) -> Edit {
        return [k](glm::dvec3 c) {
            return k * glm::dvec3(clamp01(0.393 * c.x + 0.769 * c.y + 0.189 * c.z),
                                  clamp01(0.349 * c.x + 0.686 * c.y + 0.168 * c.z),
                                  clamp01(0.272 * c.x + 0.534 * c.y + 0.131 * c.z));
        };
    };
    return {
        {"neutral", perChannel([](double v) { return v; })},
        {"darken x0.5", perChannel([](double v) { return 0.5 * v; })},
        {"darken x0.6", perChannel([](double v) { return 0.6 * v; })},
        {"darken x0.7", perChannel([](double v) { return 0.7 * v; })},
        {"darken x0.73", perChannel([](double v) { return 0.73 * v; })},
        {"darken x0.8", perChannel([](double v) { return 0.8 * v; })},
        {"exposure -0.5", perChannel(exposure(-0.5))},
        {"exposure -1", perChannel(exposure(-1.0))},
        {"exposure -1.5", perChannel(exposure(-1.5))},
        {"exposure -2", perChannel(exposure(-2.0))},
        {"gamma 1.5", perChannel([](double v) { return std::pow(v, 1.5); })},
        {"gamma 2.2", perChannel([](double v) { return std::pow(v, 2.2); })},
        {"gamma 2.2 x0.7", perChannel([](double v) { return 0.7 * std::pow(v, 2.2); })},
        {"S-curve", perChannel([](double v) { return v * v * (3 - 2 * v); })},
        {"sepia", sepia(1.0)},
        {"dark sepia", sepia(0.7)},
        {"crush blacks", perChannel([](double v) { return clamp01((v - 0.2) / 0.8); })},
        {"crush, white 180", perChannel([](double v) { return 0.706 * clamp01((v - 0.2) / 0.8); })},
        {"fade", perChannel([](double v) { return 0.1 + 0.7 * v; })},
        {"levels out 0..180", perChannel([](double v) { return v * 180.0 / 255.0; })},
        {"night",
         [](glm::dvec3 c) { return glm::dvec3(0.35 * c.x, 0.45 * c.y, 0.7 * c.z + 0.03); }},
        {"desaturate dark",
         [](glm::dvec3 c) { return glm::dvec3(0.6 * (0.5 * c + glm::dvec3(0.5 * luma(c)))); }},
        {"saturation x1.3",
         [](glm::dvec3 c) {
             const double l = luma(c);
             return glm::clamp(glm::dvec3(l) + 1.3 * (c - glm::dvec3(l)), 0.0, 1.0);
         }},
        {"warm", [](glm::dvec3 c) { return glm::dvec3(c.x, 0.95 * c.y, 0.85 * c.z); }},
        {"highlight clamp at 0.7",
         perChannel([](double v) { return std::min(v, 0.7); })}, // the one expected false positive
    };
}

// An edit as an N^3 table over [0,1], 8-bit (a strip or an 8-bit file).
Lut3D editTable(const Edit& e, int n) {
    Lut3D t(n);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::dvec3 o = e(glm::dvec3(r, g, b) / double(n - 1));
                for (int c = 0; c < 3; ++c)
                    t.at(r, g, b)[c] = fromUnorm8(toUnorm8(static_cast<float>(clamp01(o[c]))));
            }
    return t;
}

// Smush-LUT's game LUT for an edit of the neutral stage's screenshot, 16^3, 8-bit: for each
// lattice input s, the screenshot showed srgb(min(1, (1.3703 s)^2.2)); the entry makes the game
// show the edit of that: ((linear(edit)^(1/2.2) / 1.3703 - s) / 0.99961 + s, clamped.
Lut3D smushGameLut(const Edit& e) {
    Lut3D t(16);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r) {
                const glm::dvec3 s = glm::dvec3(r, g, b) / 15.0;
                glm::dvec3 shown;
                for (int c = 0; c < 3; ++c)
                    shown[c] = srgbEnc(std::min(1.0, std::pow(1.3703 * s[c], 2.2)));
                const glm::dvec3 w = e(shown);
                for (int c = 0; c < 3; ++c) {
                    const double l =
                        (std::pow(srgbDec(w[c]), 1 / 2.2) / 1.3703 - s[c]) / 0.99961 + s[c];
                    t.at(r, g, b)[c] = fromUnorm8(toUnorm8(static_cast<float>(clamp01(l))));
                }
            }
    return t;
}

} // namespace

TEST(GameLutEvidence, SmushLutsGameLutsAreRecognisedAndEditsAreNot) {
    int gameFound = 0, gameTotal = 0, editsTaken = 0, editTotal = 0;
    std::string taken;
    for (const auto& [name, e] : edits()) {
        const bool game = gameLutEvidence(smushGameLut(e)).has_value();
        ++gameTotal;
        gameFound += game;
        EXPECT_TRUE(game) << "the game's LUT for " << name << " is not recognised";
        for (int n : {16, 17, 33, 65}) {
            const bool fooled = gameLutEvidence(editTable(e, n)).has_value();
            ++editTotal;
            editsTaken += fooled;
            if (fooled)
                taken += " " + name + " " + std::to_string(n) + "^3;";
            if (name != "highlight clamp at 0.7") {
                EXPECT_FALSE(fooled) << "the edit " << name << " at " << n << "^3 is taken "
                                     << "for the game's LUT";
            }
        }
    }
    std::printf("[ measured ] game LUTs made for the brighten (Smush-LUT's formula) recognised: "
                "%d of %d; edits taken for game LUTs: %d of %d (%s)\n",
                gameFound, gameTotal, editsTaken, editTotal, taken.c_str());
}

TEST(GameLutEvidence, DecidePurposeTakesItOnlyWhenTheFileSaysNothing) {
    LutFile f;
    f.cube = smushGameLut([](glm::dvec3 c) { return 0.9 * c; });
    PurposeDecision d = decidePurpose(f);
    EXPECT_EQ(d.purpose, LutPurpose::Smash);
    EXPECT_EQ(d.source, PurposeSource::Content);
    EXPECT_NE(d.text("--in-target").find("--in-target raw if it is an edit"), std::string::npos)
        << d.text("--in-target");
    // what the user says, or the file, comes first
    d = decidePurpose(f, LutPurpose::Raw);
    EXPECT_EQ(d.purpose, LutPurpose::Raw);
    f.purpose = LutPurpose::Raw;
    d = decidePurpose(f);
    EXPECT_EQ(d.purpose, LutPurpose::Raw);
    EXPECT_EQ(d.source, PurposeSource::File);
    // an --original-lut (assumed the game's) needs no evidence
    f.purpose.reset();
    EXPECT_EQ(decidePurpose(f, std::nullopt, LutPurpose::Smash).source, PurposeSource::Assumed);
}
