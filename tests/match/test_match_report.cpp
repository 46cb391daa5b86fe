// SPDX-License-Identifier: Apache-2.0
// What match reports is checked from outside: the interpolation figure bounds what
// OpenColorIO's processor of the written .cube gives against the transfer, over every pixel; the
// clipping count is what that processor clips. Strength and preserve against Oklab and CIELAB
// written here (Ottosson's matrices; the sRGB curve; D65).
#include "MatchTestUtil.h"
#include "OcioTestUtil.h"

#include "lut/formats/Registry.h"
#include "lut/match/LutQuality.h"
#include "lut/match/Match.h"
#include "lut/match/MatchFinish.h"

#include <filesystem>

using namespace lut;
using namespace lut::matchtest;

namespace {

MatchPicture picture(const Image& img, const char* name) {
    MatchPicture p;
    p.pixels = img.view();
    p.bitDepth = 8;
    p.name = name;
    return p;
}

double decode(double v) {
    const double a = std::fabs(v);
    return std::copysign(a <= 0.04045 ? a / 12.92 : std::pow((a + 0.055) / 1.055, 2.4), v);
}

glm::dvec3 oklab(glm::dvec3 c) {
    const double r = decode(c.x), g = decode(c.y), b = decode(c.z);
    const double l = std::cbrt(0.4122214708 * r + 0.5363325363 * g + 0.0514459929 * b);
    const double m = std::cbrt(0.2119034982 * r + 0.6806995451 * g + 0.1073969566 * b);
    const double s = std::cbrt(0.0883024619 * r + 0.2817188376 * g + 0.6299787005 * b);
    return {0.2104542553 * l + 0.7936177850 * m - 0.0040720468 * s,
            1.9779984951 * l - 2.4285922050 * m + 0.4505937099 * s,
            0.0259040371 * l + 0.7827717662 * m - 0.8086757660 * s};
}

glm::dvec3 cielab(glm::dvec3 c) {
    const double r = decode(c.x), g = decode(c.y), b = decode(c.z);
    const double X = 0.4124564 * r + 0.3575761 * g + 0.1804375 * b;
    const double Y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
    const double Z = 0.0193339 * r + 0.1191920 * g + 0.9503041 * b;
    auto f = [](double t) {
        return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0;
    };
    const double fx = f(X / 0.9504559), fy = f(Y / 1.0), fz = f(Z / 1.0890578);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

struct Case {
    Image scene, reference;
};

const Case& gradedCase() {
    static const Case c = [] {
        Case k;
        k.scene = landscape(320, 180);
        k.reference = flippedAndShuffled(graded(k.scene, knownGrade));
        return k;
    }();
    return c;
}

} // namespace

TEST(MatchReport, InterpolationAndClippingAreWhatOpenColorIOSees) {
    const Case& c = gradedCase();
    for (MatchMethod m : {MatchMethod::HmMklHm, MatchMethod::Regularised}) {
        MatchOptions o;
        o.method = m;
        o.size = 17; // a coarse table: the interpolation error is large enough to matter
        const MatchResult r =
            matchLook(picture(c.scene, "scene"), {picture(c.reference, "ref")}, o);
        const std::string path = test::tempDir() + "-report-" + toString(m) + ".cube";
        formats::writeLut(path, r.lut, {}, "cube");
        const auto p = test::ocioFileProcessor(path);
        const MatchFinish finish = MatchFinish::fromOptions(o, false);
        double worst = 0.0;
        std::size_t clipped = 0, values = 0;
        for (int i = 0; i < c.scene.width() * c.scene.height(); ++i) {
            const float* in = c.scene.data() + 4 * i;
            const glm::dvec3 x(in[0], in[1], in[2]);
            const glm::vec3 got = test::ocioEval(p, glm::vec3(x));
            const glm::dvec3 want = finish(x, r.transfer(x));
            for (int k = 0; k < 3; ++k) {
                worst = std::max(worst, std::fabs(got[k] - want[k]) * 255.0);
                ++values;
                if (got[k] < -0.5 / 255.0 || got[k] > 1.0 + 0.5 / 255.0)
                    ++clipped;
            }
        }
        // float rounding of the file's values and of OpenColorIO's arithmetic: 1e-3 steps
        EXPECT_LE(worst, r.report.interpolation.maxSteps + 1e-3) << toString(m);
        EXPECT_GT(r.report.interpolation.maxSteps, 0.0);
        EXPECT_EQ(r.report.values, values);
        EXPECT_NEAR(static_cast<double>(r.report.clippedValues), static_cast<double>(clipped),
                    1e-4 * static_cast<double>(values) + 2.0);
    }
}

TEST(MatchReport, StrengthZeroIsNeutralAndHalfIsBetween) {
    const Case& c = gradedCase();
    MatchOptions o;
    o.method = MatchMethod::HmMklHm;
    const MatchFitResult fit =
        fitMatch(picture(c.scene, "scene"), {picture(c.reference, "ref")}, o);
    o.strength = 0.0;
    const LutFileSampler neutral(bakeMatch(fit.transfer, o));
    o.strength = 1.0;
    const LutFileSampler full(bakeMatch(fit.transfer, o));
    o.strength = 0.5;
    const LutFileSampler half(bakeMatch(fit.transfer, o));
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 500; ++i) {
        const glm::vec3 x(u(rng), u(rng), u(rng));
        const glm::vec3 n = neutral(x);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(n[k], x[k], 2e-4);
        // half way in Oklab lightness
        const double l0 = oklab(glm::dvec3(x)).x, l1 = oklab(glm::dvec3(full(x))).x;
        EXPECT_NEAR(oklab(glm::dvec3(half(x))).x, 0.5 * (l0 + l1), 2e-3);
    }
}

TEST(MatchReport, PreserveKeepsWhatItNames) {
    const Case& c = gradedCase();
    MatchOptions o;
    o.method = MatchMethod::HmMklHm;
    const MatchFitResult fit =
        fitMatch(picture(c.scene, "scene"), {picture(c.reference, "ref")}, o);
    o.preserve = {MatchPreserve::Luma};
    const LutFileSampler luma(bakeMatch(fit.transfer, o));
    o.preserve = {MatchPreserve::Neutrals};
    const LutFileSampler neutrals(bakeMatch(fit.transfer, o));
    o.preserve = {MatchPreserve::Skin};
    const LutFileSampler skin(bakeMatch(fit.transfer, o));
    o.preserve = {};
    const LutFileSampler plain(bakeMatch(fit.transfer, o));
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.05f, 0.95f);
    double lumaWorst = 0.0;
    for (int i = 0; i < 500; ++i) {
        const glm::vec3 x(u(rng), u(rng), u(rng));
        lumaWorst =
            std::max(lumaWorst, std::fabs(oklab(glm::dvec3(luma(x))).x - oklab(glm::dvec3(x)).x));
    }
    EXPECT_LT(lumaWorst, 0.005); // the table's interpolation between exact lattice points
    double greyChroma = 0.0, plainGreyChroma = 0.0;
    for (float t = 0.1f; t < 0.95f; t += 0.05f) {
        const glm::dvec3 a = cielab(glm::dvec3(neutrals(glm::vec3(t))));
        const glm::dvec3 b = cielab(glm::dvec3(plain(glm::vec3(t))));
        greyChroma = std::max(greyChroma, std::hypot(a.y, a.z));
        plainGreyChroma = std::max(plainGreyChroma, std::hypot(b.y, b.z));
    }
    EXPECT_LT(greyChroma, 1.5);
    EXPECT_GT(plainGreyChroma, 2.0 * greyChroma); // the look does tint greys
    // a skin tone (CIELAB hue ~55 degrees, chroma ~25) keeps its hue
    const glm::vec3 face(0.87f, 0.65f, 0.52f);
    const glm::dvec3 before = cielab(glm::dvec3(face)), after = cielab(glm::dvec3(skin(face)));
    const double hue0 = std::atan2(before.z, before.y) * 180.0 / 3.14159265358979;
    const double hue1 = std::atan2(after.z, after.y) * 180.0 / 3.14159265358979;
    EXPECT_NEAR(hue1, hue0, 1.5);
    EXPECT_NEAR(std::hypot(after.y, after.z), std::hypot(before.y, before.z), 1.5);
}
