// SPDX-License-Identifier: Apache-2.0
// The truth harness, the printed maxima of embed --original-lut and of match's form choice:
// - `embed --original-lut` of a shaper file prints what sampling it at the game's 16^3 lattice
//   over [0,1] costs, read trilinearly as the game reads it. The truth: OpenColorIO's reading of
//   the file at the lattice's points, interpolated trilinearly in float64 here, against
//   OpenColorIO's reading of the file on random inputs in [0,1] that are no lattice points.
// - `match` prints what the table alone would cost ("the table alone would be max ... from the
//   match") when it keeps the shaper form, over the source's colours. The match (the transfer)
//   is lutkit's own, so the truth is reached through the two written files: |T - S| <= |T - M| +
//   |S - M| on each colour, so the printed table-alone maximum plus the printed shaper form's
//   maximum must cover the largest |T - S| OpenColorIO shows on the source's pixels.
#include "TruthHarness.h"

#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>

using namespace lut::truth;

namespace {

// Smooth gradients with noise, like a screenshot's colours (8-bit RGB).
std::vector<unsigned char> picture(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> u(0, 8);
    std::vector<unsigned char> px(static_cast<std::size_t>(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                const double v = 0.5 + 0.48 * std::sin(0.017 * x * (c + 1) + 0.029 * y * (3 - c));
                px[(static_cast<std::size_t>(y) * w + x) * 3 + c] = static_cast<unsigned char>(
                    std::clamp(std::lround(v * 255.0) + u(rng) - 4, 0l, 255l));
            }
    return px;
}

} // namespace

TEST(Truth, EmbedOriginalLutOfAShaperBoundsTheGamesTrilinearLattice) {
    const std::string dir = workDir("embed");
    const std::string stage = writeShapedCube(dir + "/stage.cube");
    const int w = 640, h = 600;
    writePng(dir + "/shot.png", w, h, picture(w, h, 41));
    const auto r = lut::test::runCli("embed " + shellQuoted(dir + "/shot.png") + " " +
                                     shellQuoted(dir + "/patched.png") + " --original-lut " +
                                     shellQuoted(stage) + " -y");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const double printed = maxAfter(r.err, "sampled at the game's 16^3 lattice over [0,1]");
    ASSERT_FALSE(std::isnan(printed)) << r.err;

    // The game's lattice: OpenColorIO's reading of the file at its 16^3 points.
    constexpr int n = 16;
    std::vector<float> lattice;
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int rr = 0; rr < n; ++rr)
                for (const int i : {rr, g, b})
                    lattice.push_back(static_cast<float>(i / double(n - 1)));
    ocioApply(stage, lattice);
    auto at = [&](int rr, int g, int b) {
        const std::size_t k = 3 * ((static_cast<std::size_t>(b) * n + g) * n + rr);
        return glm::dvec3(lattice[k], lattice[k + 1], lattice[k + 2]);
    };
    const std::vector<float> x = randomUnitInputs(100000, 52);
    std::vector<float> want = x, got = x;
    ocioApply(stage, want);
    for (std::size_t i = 0; i < x.size(); i += 3) {
        int i0[3];
        double f[3];
        for (int c = 0; c < 3; ++c) {
            const double t = std::clamp(double(x[i + c]), 0.0, 1.0) * (n - 1);
            i0[c] = std::min(static_cast<int>(t), n - 2);
            f[c] = t - i0[c];
        }
        glm::dvec3 v(0.0);
        for (int corner = 0; corner < 8; ++corner) {
            double wgt = 1.0;
            int idx[3];
            for (int c = 0; c < 3; ++c) {
                const int bit = (corner >> c) & 1;
                idx[c] = i0[c] + bit;
                wgt *= bit ? f[c] : 1.0 - f[c];
            }
            v += wgt * at(idx[0], idx[1], idx[2]);
        }
        for (int c = 0; c < 3; ++c)
            got[i + c] = static_cast<float>(v[c]);
    }
    const Truth t = compare(want, got);
    row("embed --original-lut shaper + 33^3 (the game's 16^3, trilinear)", t.max, printed, t.mean);
    EXPECT_GE(printed + kOracleRounding, t.max) << r.err;
    EXPECT_LE(printed, 1.2 * t.max + 0.5 / 255.0) << r.err; // a bound, not a blanket figure
}

namespace {

// One match, both forms: the form auto keeps is written, the other one's printed maximum ("the
// table alone would be max ..." or "with a 1D shaper before it: max ...") is checked against it
// through the file of the other form (--lut-form). Returns whether auto kept the shaper.
bool checkMatchForms(const std::string& dir, const std::string& name, int w, int h,
                     const std::vector<unsigned char>& src, const std::vector<unsigned char>& ref) {
    writePng(dir + "/" + name + "-src.png", w, h, src);
    writePng(dir + "/" + name + "-ref.png", w, h, ref);
    const std::string in = shellQuoted(dir + "/" + name + "-src.png") + " " +
                           shellQuoted(dir + "/" + name + "-ref.png");
    const std::string kept = dir + "/" + name + "-auto.cube",
                      other = dir + "/" + name + "-other.cube";
    const auto a = lut::test::runCli("match " + in + " " + shellQuoted(kept) + " -y");
    EXPECT_EQ(a.exitCode, 0) << a.err;
    const double keptMax = maxAfter(a.out, "LUT      against the transfer");
    const bool shaper = a.out.find("the table alone would be") != std::string::npos;
    const double otherMax =
        maxAfter(a.out, shaper ? "the table alone would be" : "with a 1D shaper before it:");
    EXPECT_FALSE(std::isnan(keptMax) || std::isnan(otherMax)) << a.out;
    const auto b = lut::test::runCli("match " + in + " " + shellQuoted(other) + " --lut-form " +
                                     (shaper ? "table" : "shaper") + " -y");
    EXPECT_EQ(b.exitCode, 0) << b.err;
    // The same LUT as the one measured (nothing repaired or refitted after the choice).
    EXPECT_NEAR(maxAfter(b.out, "LUT      against the transfer"), otherMax, 0.006) << b.out;
    std::vector<float> x(src.size());
    for (std::size_t i = 0; i < x.size(); ++i)
        x[i] = src[i] / 255.0f;
    std::vector<float> fk = x, fo = x;
    ocioApply(kept, fk);
    ocioApply(other, fo);
    const Truth d = compare(fk, fo);
    // |O - M| >= |O - K| - |K - M| on every colour: the truth of O's maximum is at least this.
    const double truthFloor = d.max - keptMax / 255.0;
    row("match " + name + ": " + (shaper ? "the table alone" : "the shaper form") +
            " (|O - K| less K's printed max)",
        truthFloor, otherMax / 255.0);
    EXPECT_GE(otherMax / 255.0 + kOracleRounding, truthFloor) << a.out;
    return shaper;
}

} // namespace

// The figure printed for the form match did not keep, both ways: a gentle curve (the table alone
// kept, the shaper form's figure printed) and x^0.25 on a dark picture (the shaper kept: "the
// table alone would be ...").
TEST(Truth, MatchPrintsWhatTheOtherFormWouldCost) {
    const std::string dir = workDir("match");
    const int w = 320, h = 240;
    std::vector<unsigned char> src = picture(w, h, 42), ref(src.size());
    for (std::size_t i = 0; i < src.size(); ++i)
        ref[i] = static_cast<unsigned char>(std::lround(std::pow(src[i] / 255.0, 0.7) * 255.0));
    EXPECT_FALSE(checkMatchForms(dir, "gentle", w, h, src, ref));
    for (std::size_t i = 0; i < src.size(); ++i) {
        src[i] = static_cast<unsigned char>(std::lround(std::pow(src[i] / 255.0, 2.5) * 255.0));
        ref[i] = static_cast<unsigned char>(std::lround(std::pow(src[i] / 255.0, 0.25) * 255.0));
    }
    EXPECT_TRUE(checkMatchForms(dir, "steep", w, h, src, ref));
}
