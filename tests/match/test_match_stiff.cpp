// SPDX-License-Identifier: Apache-2.0
// Stiff inputs (issue 23): a reference of two flat colours, a black reference, one of far wider
// gamut, an HDR reference, an almost grey source. Each must give a finite, monotone LUT without
// fold-overs, and a warning that says what happened.
#include "MatchTestUtil.h"

#include "lut/match/LutQuality.h"
#include "lut/match/Match.h"

#include <gmock/gmock.h>

using namespace lut;
using namespace lut::matchtest;
using ::testing::HasSubstr;

namespace {

MatchPicture picture(const Image& img, const char* name, int bitDepth = 8, bool linear = false) {
    MatchPicture p;
    p.pixels = img.view();
    p.bitDepth = bitDepth;
    p.linear = linear;
    p.name = name;
    return p;
}

std::string allText(const Diagnostics& d) {
    std::string s;
    for (const auto& x : d)
        s += x.str() + "\n";
    return s;
}

// Finite entries, monotone along each channel's axis and along grey, no fold-overs, slopes
// within what the options allow (the curves' and the MKL gain's product, with room for the
// table's interpolation).
void expectSmooth(const MatchResult& r) {
    for (const auto& e : r.lut.cube->entries())
        for (int c = 0; c < 3; ++c) {
            ASSERT_TRUE(std::isfinite(e[c]));
        }
    if (r.lut.shaper) {
        for (const auto& e : r.lut.shaper->entries())
            for (int c = 0; c < 3; ++c) {
                ASSERT_TRUE(std::isfinite(e[c]));
            }
    }
    const LutQuality& q = r.report.quality;
    SCOPED_TRACE(std::string(toString(r.report.method)) + ": " + q.str());
    EXPECT_EQ(q.decreasingSteps, 0u);
    EXPECT_EQ(q.foldedCells, 0u);
    EXPECT_LE(q.largestSlope, 4.0 * 4.0 * 4.0) << q.str();
    EXPECT_TRUE(std::isfinite(r.report.after.slicedWasserstein));
}

} // namespace

TEST(MatchStiff, TwoFlatColours) {
    const Image src = landscape(160, 90);
    Image ref(64, 64, 1.0f);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const float v = x < 32 ? 0.2f : 0.8f;
            ref.pixel(x, y)[0] = v;
            ref.pixel(x, y)[1] = 0.9f - 0.5f * v;
            ref.pixel(x, y)[2] = 0.5f;
        }
    for (MatchMethod m : {MatchMethod::Auto, MatchMethod::Hm}) {
        MatchOptions o;
        o.method = m;
        const MatchResult r = matchLook(picture(src, "src"), {picture(ref, "flat.png")}, o);
        // Two colours are a look with steps (issue 42): auto keeps them with the gradient map,
        // a colour per luma, flat on each side of the step by design (every cell "folds").
        EXPECT_EQ(r.report.look, "posterised palette of 2 colours");
        if (r.report.method == MatchMethod::GradientMap) {
            for (const auto& e : r.lut.cube->entries())
                for (int c = 0; c < 3; ++c)
                    ASSERT_TRUE(std::isfinite(e[c]));
        } else {
            expectSmooth(r);
        }
        EXPECT_THAT(allText(r.diagnostics), HasSubstr("flat.png: warning: the picture has only 2"));
    }
}

TEST(MatchStiff, BlackReference) {
    const Image src = landscape(160, 90);
    const Image ref(32, 32, 0.0f);
    const MatchResult r = matchLook(picture(src, "src"), {picture(ref, "black.png")}, {});
    expectSmooth(r);
    EXPECT_THAT(allText(r.diagnostics), HasSubstr("black.png: warning: the picture is black"));
    // everything lands near black
    const LutFileSampler f(r.lut);
    EXPECT_LT(f(glm::vec3(0.8f)).x, 0.1f);
}

TEST(MatchStiff, FarWiderGamutReference) {
    // A reference stored as float display values far outside [0, 1] (a wide-gamut picture read
    // without conversion): warned about, and the LUT stays smooth.
    const Image src = landscape(160, 90);
    Image ref = landscape(160, 90);
    for (float& v : ref.pixels())
        v = v * 2.2f - 0.5f;
    MatchPicture rp = picture(ref, "wide.exr", 0, false);
    const MatchResult r = matchLook(picture(src, "src"), {rp}, {});
    expectSmooth(r);
    EXPECT_THAT(allText(r.diagnostics), HasSubstr("wide.exr: warning:"));
    EXPECT_THAT(allText(r.diagnostics), HasSubstr("outside [0, 1]"));
}

TEST(MatchStiff, HdrReference) {
    // A scene-linear reference with values up to 40: converted to the source's display values,
    // said so, and the LUT keeps a finite, monotone shape.
    const Image src = landscape(160, 90);
    Image ref = landscape(160, 90);
    for (int i = 0; i < ref.width() * ref.height(); ++i)
        for (int c = 0; c < 3; ++c) {
            float& v = ref.data()[4 * i + c];
            const double lin = std::pow(v, 2.2) * (i % 7 == 0 ? 40.0 : 1.0);
            v = static_cast<float>(lin);
        }
    const MatchResult r = matchLook(picture(src, "src"), {picture(ref, "hdr.exr", 0, true)}, {});
    expectSmooth(r);
    EXPECT_THAT(allText(r.diagnostics), HasSubstr("hdr.exr: warning: a scene-linear picture"));
    EXPECT_THAT(allText(r.diagnostics), HasSubstr("HDR"));
}

TEST(MatchStiff, AlmostGreySource) {
    Image src(160, 90, 1.0f);
    for (int y = 0; y < 90; ++y)
        for (int x = 0; x < 160; ++x) {
            const float t = static_cast<float>(x) / 159.0f;
            src.pixel(x, y)[0] = static_cast<float>(q8(t));
            src.pixel(x, y)[1] = static_cast<float>(q8(t + ((x + y) % 3 == 0 ? 1.0 / 255 : 0.0)));
            src.pixel(x, y)[2] = static_cast<float>(q8(t));
        }
    const Image ref = landscape(160, 90);
    for (MatchMethod m : {MatchMethod::Mkl, MatchMethod::HmMklHm, MatchMethod::Auto}) {
        MatchOptions o;
        o.method = m;
        const MatchResult r = matchLook(picture(src, "grey.png"), {picture(ref, "ref")}, o);
        expectSmooth(r);
        if (m == MatchMethod::Mkl) {
            EXPECT_THAT(allText(r.diagnostics), HasSubstr("almost flat in some colour direction"));
            // the limits said are the options' (both ends), not whatever the stack held
            EXPECT_THAT(allText(r.diagnostics), HasSubstr("limited to [1/4, 4]"));
        }
    }
}

TEST(MatchStiff, HdrSourceKeepsItsRange) {
    // A scene-linear source up to 20: the LUT's domain covers it, its outputs are not clipped
    // to 1, and the shaper keeps the range.
    Image src = landscape(160, 90);
    for (int i = 0; i < src.width() * src.height(); ++i)
        for (int c = 0; c < 3; ++c) {
            float& v = src.data()[4 * i + c];
            v = static_cast<float>(std::pow(v, 2.2) * (i % 11 == 0 ? 20.0 : 1.0));
        }
    Image ref = src;
    for (float& v : ref.pixels())
        v *= 1.5f; // one stop brighter, roughly
    const MatchResult r =
        matchLook(picture(src, "scene.exr", 0, true), {picture(ref, "brighter.exr", 0, true)}, {});
    expectSmooth(r);
    ASSERT_TRUE(r.lut.shaper.has_value());
    EXPECT_GE(r.lut.shaper->domainMax().x, 20.0f);
    const LutFileSampler f(r.lut);
    const glm::vec3 bright = f(glm::vec3(10.0f));
    EXPECT_GT(bright.x, 10.0f); // brighter, never clipped to 1
    EXPECT_TRUE(std::isfinite(bright.x));
    EXPECT_NEAR(f(glm::vec3(0.18f)).x / 0.18f, 1.5f, 0.2f);
}
