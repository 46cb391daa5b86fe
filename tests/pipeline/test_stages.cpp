// SPDX-License-Identifier: Apache-2.0
// The other stages against formulas written here, and the settings interface.
#include "PipelineTestUtil.h"

#include "core/FastMath.h"
#include "lut/Error.h"
#include "lut/pipeline/Pipeline.h"
#include "pipeline/ArrayKernels.h"
#include "smash/SmashDisplayFast.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

using namespace lut;
using namespace lut::test;

// madd's emulation (WebAssembly, an x86 without FMA) against the hardware's or the C library's
// fused multiply-add: random operands, and products that put the sum exactly halfway between two
// floats (where a plain double sum rounds twice).
TEST(FastMath, EmulatedFmaIsTheFusedMultiplyAdd) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-4.0f, 4.0f);
    std::uniform_int_distribution<int> ex(-60, 60);
    int checked = 0;
    for (int i = 0; i < 2000000; ++i) {
        const float a = std::ldexp(u(rng), ex(rng) / 4), b = std::ldexp(u(rng), ex(rng) / 4);
        float c = std::ldexp(u(rng), ex(rng) / 4);
        if (i % 3 == 0) // c cancels most of a * b: the sum's low bits decide
            c = -static_cast<float>(static_cast<double>(a) * b);
        const float want = std::fma(a, b, c);
        const float got = lut::detail::fmaEmulated(a, b, c);
        ASSERT_EQ(std::memcmp(&want, &got, sizeof want), 0)
            << a << " * " << b << " + " << c << ": " << want << " vs " << got;
        ++checked;
    }
    // Exact halfway sums: 1 + 2^-24 (halfway between 1 and the next float) made inexact by a
    // tiny product of either sign.
    for (const float tiny : {1e-30f, -1e-30f, 3e-40f, -3e-40f}) {
        const float c = 1.0f, a = 0x1p-24f;
        const float want = std::fma(a + tiny, 1.0f, c),
                    got = lut::detail::fmaEmulated(a + tiny, 1.0f, c);
        EXPECT_EQ(want, got) << tiny;
        const float w2 = std::fma(tiny, 1.0f, 1.0f + 0x1p-23f),
                    g2 = lut::detail::fmaEmulated(tiny, 1.0f, 1.0f + 0x1p-23f);
        EXPECT_EQ(w2, g2) << tiny;
    }
    EXPECT_EQ(checked, 2000000);
}

// exp2Times' exact p * e without a fused multiply-add: p split in two (splitHigh), each part
// times a binary exponent exact, and the two parts' sum p itself; against products in double
// (exact for floats), over random p of every sign and size and every exponent a normal float has.
TEST(FastMath, SplitHighGivesExactProductsWithExponents) {
    std::mt19937 rng(11);
    std::uniform_int_distribution<std::uint32_t> bits(0x00800000u, 0x7F7FFFFFu);
    for (int i = 0; i < 20000; ++i) {
        float p;
        const std::uint32_t b = bits(rng) | (i % 2 ? 0x80000000u : 0u);
        std::memcpy(&p, &b, 4);
        const float ph = detail::splitHigh(p), pl = p - ph;
        ASSERT_EQ(double(ph) + double(pl), double(p)) << p;
        for (int ei = -150; ei <= 150; ++ei) {
            const float e = static_cast<float>(ei);
            const double hi = double(ph) * ei, lo = double(pl) * ei;
            if (std::fabs(hi) > 3e38 || std::fabs(double(p) * ei) > 3e38 ||
                (lo != 0 && std::fabs(lo) < 1.2e-38))
                continue; // overflow or below the normal range: not an exponent's product
            ASSERT_EQ(double(ph * e), hi) << p << " * " << ei;
            ASSERT_EQ(double(pl * e), lo) << p << " * " << ei;
        }
    }
}

TEST(FastMath, PowFastIsWithin4e7RelativeOfStdPow) {
    for (float p : {0.454545f, 2.2f, 1.0f / 2.4f, 2.2f / 2.4f}) {
        Rng r(1);
        double worst = 0;
        for (int i = 0; i < 400000; ++i) {
            // e^-30 .. e^30 (1e-13 .. 1e13): every exponent the pipeline meets, and more.
            const float x = static_cast<float>(std::exp((r.uniform() - 0.5) * 60.0));
            const double want = std::pow(double(x), double(p));
            worst = std::max(worst, std::fabs(detail::powFast(x, p) - want) / want);
        }
        EXPECT_LT(worst, 4e-7) << p;
        // Powers of two and 1 are exact.
        EXPECT_EQ(detail::powFast(1.0f, p), 1.0f);
        EXPECT_EQ(detail::powFast(4.0f, 0.5f), 2.0f);
        EXPECT_EQ(detail::powFast(0.0f, p), 0.0f);
        EXPECT_EQ(detail::powFast(-0.0f, p), 0.0f);
        EXPECT_EQ(detail::powFast(-1.0f, p), 0.0f);
        EXPECT_EQ(detail::powFast(NAN, p), 0.0f);
        EXPECT_EQ(detail::powFast(1e-40f, p), 0.0f); // denormal
        EXPECT_TRUE(std::isfinite(detail::powFast(INFINITY, p)));
        EXPECT_TRUE(std::isfinite(detail::powFast(3e38f, 2.2f)));
        EXPECT_GT(detail::powFast(3e38f, 2.2f), 1e38f); // clamped, not wrapped
        EXPECT_EQ(detail::powFast(1e-30f, 2.2f), 0.0f); // below 2^-126: flushed
    }
}

TEST(FastMath, SrgbAndFusedDisplayFollowTheirFormulas) {
    Rng r(3);
    double worstSrgb = 0, worstDisplay = 0;
    for (int i = 0; i < 200000; ++i) {
        const float x = static_cast<float>((r.uniform() - 0.2) * 3.0);
        worstSrgb = std::max(worstSrgb, std::fabs(detail::srgbEncodeFast(x) - refSrgbEncode(x)));
        const float rr = static_cast<float>(r.uniform() * 4.0);
        const double want = refSrgbEncode(std::pow(double(rr), 2.2));
        worstDisplay = std::max(worstDisplay, relErr(detail::smashDisplayFast(rr), want));
    }
    EXPECT_LT(worstSrgb, 1e-6);
    EXPECT_LT(worstDisplay, 1e-6);
    // Both sides of the linear segment's end, and the limits.
    for (double x : {0.0031307, 0.0031309, 0.5, 1.0})
        EXPECT_NEAR(detail::smashDisplayFast(static_cast<float>(std::pow(x, 1 / 2.2))),
                    refSrgbEncode(x), 1e-6)
            << x;
    EXPECT_EQ(detail::smashDisplayFast(0.0f), 0.0f);
    EXPECT_EQ(detail::smashDisplayFast(-2.0f), 0.0f);
    EXPECT_EQ(detail::srgbEncodeFast(-0.0f), 0.0f);
    EXPECT_FALSE(std::signbit(detail::srgbEncodeFast(-0.0f)));
    EXPECT_NEAR(detail::srgbEncodeFast(-0.5f), -refSrgbEncode(0.5), 1e-6);
}

namespace {
std::vector<float> awkwardValues() {
    std::vector<float> in;
    Rng r(9);
    for (int i = 0; i < 4099; ++i)
        in.push_back(static_cast<float>((r.uniform() - 0.3) * std::exp((r.uniform() - 0.5) * 30)));
    for (float v : {0.0f, -0.0f, NAN, INFINITY, -INFINITY, 1e-40f, -1e-40f, 0.0031308f, 1.0f,
                    1.41421356f, 1.41421366f, 0.0727212795f, 65504.0f, 3e38f})
        in.push_back(v);
    return in;
}
bool sameBits(float a, float b) {
    return std::memcmp(&a, &b, 4) == 0;
}
} // namespace

TEST(FastMath, ArrayKernelsAreBitIdenticalToScalar) {
    // The SIMD path (if this CPU has one) must give the scalar bits, or fused/unfused and
    // skipped/forced runs could differ.
    const std::vector<float> in = awkwardValues();
    std::vector<float> out(in.size());
    for (float p : {0.454545f, 2.2f}) {
        detail::powArray(p, in.data(), out.data(), in.size());
        for (std::size_t i = 0; i < in.size(); ++i)
            EXPECT_TRUE(sameBits(out[i], detail::powFast(in[i], p)))
                << in[i] << " " << detail::arrayKernelIsa();
    }
    detail::srgbEncodeArray(in.data(), out.data(), in.size());
    for (std::size_t i = 0; i < in.size(); ++i) {
        if (!std::isfinite(in[i]))
            continue; // never reaches it: frames are sanitized first
        EXPECT_TRUE(sameBits(out[i], detail::srgbEncodeFast(in[i]))) << in[i];
    }
}

TEST(FastMath, GradeKernelsGiveEachPixelTheSameBitsInAnyGroup) {
    // Runs the two grading halves over a long run of pixels (the 8-wide path) and over each pixel
    // alone (the scalar path): a pixel's result may not depend on its neighbours or the path.
    Rng r(21);
    const std::size_t n = 203; // 25 groups of 8 and a tail of 3
    std::vector<float> x(4 * n);
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c)
            x[4 * i + c] = static_cast<float>((r.uniform() - 0.1) * std::exp(r.uniform() * 6.0));
        const double u = r.uniform();
        x[4 * i + 3] = u < 0.5 ? 1.0f : (u < 0.7 ? 0.0f : static_cast<float>(r.uniform()));
        if (i >= 80 && i < 96)
            x[4 * i + 3] = 1.0f; // two groups fully graded
        if (i >= 96 && i < 104)
            x[4 * i + 3] = 0.0f; // one group not graded at all
    }
    for (bool fused : {false, true}) {
        std::vector<float> s(4 * n), l(4 * n), sl(4 * n), ll(4 * n);
        detail::smashEncodePixels(x.data(), s.data(), l.data(), n);
        for (std::size_t i = 0; i < n; ++i)
            detail::smashEncodePixels(&x[4 * i], &sl[4 * i], &ll[4 * i], 1);
        ASSERT_EQ(std::memcmp(s.data(), sl.data(), s.size() * 4), 0);
        ASSERT_EQ(std::memcmp(l.data(), ll.data(), l.size() * 4), 0);
        // A stand-in for the LUT lookup: any finite values will do.
        for (std::size_t i = 0; i < l.size(); ++i)
            l[i] = l[i] * 0.9f + 0.02f;
        std::vector<float> wide = x, alone = x;
        detail::smashFinishPixels(wide.data(), s.data(), l.data(), n, fused);
        for (std::size_t i = 0; i < n; ++i)
            detail::smashFinishPixels(&alone[4 * i], &s[4 * i], &l[4 * i], 1, fused);
        for (std::size_t i = 0; i < 4 * n; ++i)
            ASSERT_TRUE(sameBits(wide[i], alone[i]))
                << "pixel " << i / 4 << " channel " << i % 4 << " fused " << fused << " "
                << detail::arrayKernelIsa();
        // And against the formula: alpha 0 untouched (or display-encoded), alpha kept.
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_TRUE(sameBits(wide[4 * i + 3], x[4 * i + 3]));
            if (x[4 * i + 3] == 0.0f)
                for (int c = 0; c < 3; ++c) {
                    const float want = fused ? detail::srgbEncodeFast(x[4 * i + c]) : x[4 * i + c];
                    EXPECT_TRUE(sameBits(wide[4 * i + c], want));
                }
            if (x[4 * i + 3] == 1.0f)
                for (int c = 0; c < 3; ++c) {
                    const double rr =
                        ((double(l[4 * i + c]) - s[4 * i + c]) * 0.99961 + s[4 * i + c]) * 1.3703;
                    const double g = std::pow(std::max(rr, 0.0), 2.2);
                    EXPECT_LT(relErr(wide[4 * i + c], fused ? refSrgbEncode(g) : g), 2e-6);
                }
        }
    }
}

TEST(Stages, ExposureAndTonemapFollowTheirFormulas) {
    Image img(3, 1);
    const float v[3] = {0.5f, 2.0f, 10.0f};
    for (int x = 0; x < 3; ++x)
        for (int c = 0; c < 3; ++c)
            img.pixel(x, 0)[c] = v[x];
    auto e = makeStage("exposure");
    e->setParam("stops", "1.5");
    Image a = img;
    e->process(a.view());
    EXPECT_FLOAT_EQ(a.pixel(1, 0)[0], 2.0f * std::pow(2.0f, 1.5f));
    auto t = makeStage("tonemap");
    Image b = img;
    t->process(b.view());
    EXPECT_FLOAT_EQ(b.pixel(2, 0)[1], 10.0f / 11.0f);
    t->setParam("curve", "aces");
    Image c = img;
    t->process(c.view());
    const double x = 2.0;
    EXPECT_NEAR(c.pixel(1, 0)[0], (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 1e-6);
}

TEST(Stages, FilterBloomUsesThe9TapKernel) {
    // One bright pixel, knee 0, threshold 0.5, one pass: bloom = colour * w[|dx|] * w[|dy|].
    Image img(21, 21, 0.0f);
    for (auto i = 3u; i < img.pixels().size(); i += 4)
        img.pixels()[i] = 1.0f;
    img.pixel(10, 10)[0] = img.pixel(10, 10)[1] = img.pixel(10, 10)[2] = 2.0f;
    auto s = makeStage("filter-bloom");
    s->setParam("knee", "0");
    s->setParam("threshold", "0.5");
    s->setParam("passes", "1");
    s->process(img.view());
    const double w[5] = {0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216};
    // contribution weight = (l - th) / l with l = 2: 0.75
    for (int dy = -4; dy <= 4; ++dy)
        for (int dx = -4; dx <= 4; ++dx) {
            const double want =
                2.0 * 0.75 * w[std::abs(dx)] * w[std::abs(dy)] + (dx == 0 && dy == 0 ? 2.0 : 0.0);
            EXPECT_NEAR(img.pixel(10 + dx, 10 + dy)[1], want, 1e-6) << dx << "," << dy;
        }
    EXPECT_EQ(img.pixel(10 + 5, 10)[1], 0.0f);
}

TEST(Stages, HdrBloomSubtractsOneBlursAndAdds) {
    Image img(31, 1, 0.5f);
    img.pixel(15, 0)[0] = 3.0f;
    auto s = makeStage("hdr-bloom");
    s->setParam("sigma", "2");
    s->process(img.view());
    // 1D: the vertical pass on a 1-row image is the identity (clamp to edge, weights sum to 1).
    double sum = 0, norm = 0;
    for (int k = -6; k <= 6; ++k)
        norm += std::exp(-0.5 * k * k / 4.0);
    for (int k = -6; k <= 6; ++k) {
        const double want = 2.0 * std::exp(-0.5 * k * k / 4.0) / norm;
        sum += img.pixel(15 + k, 0)[0] - (k == 0 ? 3.0 : 0.5);
        EXPECT_NEAR(img.pixel(15 + k, 0)[0] - (k == 0 ? 3.0 : 0.5), want, 1e-5) << k;
    }
    EXPECT_NEAR(sum, 2.0, 1e-4); // energy above 1 is conserved
    EXPECT_EQ(img.pixel(0, 0)[1], 0.5f);
}

TEST(Stages, SugarBloomBlendsBaseAndHalo) {
    Image img(16, 16, 0.2f);
    img.pixel(8, 8)[0] = img.pixel(8, 8)[1] = img.pixel(8, 8)[2] = 1.8f;
    auto s = makeStage("sugar-bloom");
    s->setParam("f0", "0.5");
    s->setParam("threshold", "0.8");
    Image out = img;
    s->process(out.view());
    // Far from the light the halo is zero... except through the coarse mips; f0 halves the base.
    EXPECT_NEAR(out.pixel(0, 0)[0], 0.1, 0.05);
    EXPECT_GT(out.pixel(8, 7)[0], 0.1f); // halo next to the light (i = 0 there)
    // At the light i = 1.0: (1 - i) = 0, no halo on the light itself.
    EXPECT_FLOAT_EQ(out.pixel(8, 8)[0], 0.9f);
}

TEST(Stages, VignetteDarkensCornersOnly) {
    Image img(40, 30, 1.0f);
    auto s = makeStage("vignette");
    s->setParam("strength", "0.5");
    s->setParam("radius", "0.3");
    s->setParam("softness", "0.7");
    s->process(img.view());
    EXPECT_FLOAT_EQ(img.pixel(20, 15)[0], 1.0f);
    // Corner pixel centre: d = |(0.5-20, 0.5-15)| / 25 = 0.975..., t = (d - 0.3)/0.7
    const double d = std::hypot(19.5, 14.5) / 25.0, t = (d - 0.3) / 0.7;
    EXPECT_NEAR(img.pixel(0, 0)[0], 1.0 - 0.5 * t * t * (3 - 2 * t), 1e-6);
    EXPECT_EQ(img.pixel(0, 0)[3], 1.0f);
}

TEST(Stages, ChromaticAberrationMovesRedAndBlueOnly) {
    Image img(41, 41, 0.0f);
    for (int y = 0; y < 41; ++y)
        for (int x = 0; x < 41; ++x) {
            float* p = img.pixel(x, y);
            p[0] = p[1] = p[2] = static_cast<float>(x);
        }
    auto s = makeStage("chromatic-aberration");
    s->setParam("strength", "0.1");
    s->process(img.view());
    // At pixel x=40 (dx = 40.5 - 20.5 = 20): red samples at 20.5 + 22 - 0.5 = 42 -> clamped 40,
    // blue at 20.5 + 18 - 0.5 = 38.
    EXPECT_FLOAT_EQ(img.pixel(40, 20)[1], 40.0f);
    EXPECT_NEAR(img.pixel(40, 20)[2], 38.0f, 1e-4);
    EXPECT_NEAR(img.pixel(30, 20)[0], 31.0f, 1e-4); // 20.5 + 10*1.1 - 0.5
    EXPECT_NEAR(img.pixel(20, 20)[0], 20.0f, 1e-4); // centre pixel barely moves
}

TEST(Stages, GrainIsSeededAndChangesPerFrame) {
    Pipeline p(Preset::None);
    p.setEnabled("grain", true);
    const Image scene(32, 32, 0.4f);
    RunOptions o;
    o.frameIndex = 7;
    Image a = p.run(scene, o), b = p.run(scene, o);
    EXPECT_EQ(a.pixels(), b.pixels());
    o.frameIndex = 8;
    Image c = p.run(scene, o);
    EXPECT_NE(a.pixels(), c.pixels());
    p.assign("grain.seed=99");
    o.frameIndex = 7;
    Image d = p.run(scene, o);
    EXPECT_NE(a.pixels(), d.pixels());
    double mean = 0;
    for (int i = 0; i < 32 * 32; ++i)
        mean += a.pixels()[4 * i] - refSrgbEncode(0.4);
    EXPECT_NEAR(mean / 1024, 0.0, 0.01); // zero-mean noise
}

TEST(Stages, SettingsErrorsNameTheProblem) {
    Pipeline p(Preset::Smash);
    EXPECT_THROW(p.assign("nosuch.strength=1"), Error);
    EXPECT_THROW(p.assign("smash-bloom.nosuch=1"), Error);
    EXPECT_THROW(p.assign("smash-bloom.strength=abc"), Error);
    EXPECT_THROW(p.assign("smash-bloom.strength=-1"), Error);
    EXPECT_THROW(p.assign("strength=1"), Error);
    EXPECT_THROW(p.setEnabled("sanitize", false), Error);
    try {
        p.assign("tonemap.curve=bogus");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("reinhard|aces|hable"), std::string::npos);
    }
    p.assign("bloom.strength=0.5");
    EXPECT_FLOAT_EQ(p.stage("smash-bloom").param("strength"), 0.5f);
    EXPECT_EQ(parsePreset("lecture"), Preset::Lecture);
    EXPECT_THROW(parsePreset("x"), Error);
    PipelineSettings s;
    s.preset = Preset::Pilot;
    s.bloom = false;
    s.enable = {"vignette"};
    s.assignments = {"vignette.strength=0.2"};
    Pipeline q(s);
    EXPECT_FALSE(q.stage("filter-bloom").enabled());
    EXPECT_TRUE(q.stage("vignette").enabled());
    EXPECT_FLOAT_EQ(q.stage("vignette").param("strength"), 0.2f);
}
