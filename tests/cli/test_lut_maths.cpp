// SPDX-License-Identifier: Apache-2.0
// The LUT-maths subcommands on files: diff against a float64 CIEDE2000 written here from Sharma,
// Wu and Dalal (2005); a LUT against itself exactly 0; invert then compose back to neutral; mix,
// resize and adjust against values computed here; plot and heat-map pictures written.
#include "CliTestSupport.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

namespace fs = std::filesystem;
using namespace lut::test;
using ::testing::HasSubstr;

namespace {

using lut::test::shellQuoted;

using Fn = std::function<glm::vec3(glm::vec3)>;

double jsonNumber(const std::string& text, const std::string& key, std::size_t from = 0) {
    const auto k = text.find("\"" + key + "\": ", from);
    EXPECT_NE(k, std::string::npos) << key << " in " << text;
    return k == std::string::npos ? NAN : std::stod(text.substr(k + key.size() + 4));
}

// The number after "max " on the line starting with `line`.
double printedMax(const std::string& out, const std::string& line) {
    const auto l = out.find(line);
    EXPECT_NE(l, std::string::npos) << out;
    const auto m = out.find("max ", l);
    return m == std::string::npos ? NAN : std::stod(out.substr(m + 4));
}

// ---- CIEDE2000 in float64, from the papers, for sRGB-encoded values ----

using D3 = std::array<double, 3>;

double decode(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// sRGB (linear) to XYZ from the primaries' and D65's chromaticities.
D3 toXyz(D3 rgb) {
    const double xy[4][2] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, {0.3127, 0.3290}};
    double P[3][3];
    for (int i = 0; i < 3; ++i) {
        P[0][i] = xy[i][0] / xy[i][1];
        P[1][i] = 1.0;
        P[2][i] = (1 - xy[i][0] - xy[i][1]) / xy[i][1];
    }
    const D3 w = {xy[3][0] / xy[3][1], 1.0, (1 - xy[3][0] - xy[3][1]) / xy[3][1]};
    // S = P^-1 w by Cramer's rule.
    auto det = [](double m[3][3]) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double d = det(P);
    D3 s;
    for (int i = 0; i < 3; ++i) {
        double m[3][3];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                m[r][c] = c == i ? w[r] : P[r][c];
        s[i] = det(m) / d;
    }
    D3 out{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            out[r] += P[r][c] * s[c] * rgb[c];
    return out;
}

D3 toLab(D3 srgb) {
    const D3 xyz = toXyz({decode(srgb[0]), decode(srgb[1]), decode(srgb[2])});
    const D3 white = toXyz({1, 1, 1});
    auto f = [](double t) {
        const double e = 6.0 / 29.0;
        return t > e * e * e ? std::cbrt(t) : t / (3 * e * e) + 4.0 / 29.0;
    };
    const double fx = f(xyz[0] / white[0]), fy = f(xyz[1] / white[1]), fz = f(xyz[2] / white[2]);
    return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

double deg(double r) {
    return r * 180.0 / M_PI;
}
double rad(double d) {
    return d * M_PI / 180.0;
}

double ciede2000(D3 lab1, D3 lab2) {
    const double c1 = std::hypot(lab1[1], lab1[2]), c2 = std::hypot(lab2[1], lab2[2]);
    const double cbar = (c1 + c2) / 2, p7 = std::pow(25.0, 7);
    const double g = 0.5 * (1 - std::sqrt(std::pow(cbar, 7) / (std::pow(cbar, 7) + p7)));
    const double a1 = (1 + g) * lab1[1], a2 = (1 + g) * lab2[1];
    const double c1p = std::hypot(a1, lab1[2]), c2p = std::hypot(a2, lab2[2]);
    auto hue = [](double b, double a) {
        if (a == 0 && b == 0)
            return 0.0;
        double h = deg(std::atan2(b, a));
        return h < 0 ? h + 360 : h;
    };
    const double h1 = hue(lab1[2], a1), h2 = hue(lab2[2], a2);
    const double dL = lab2[0] - lab1[0], dC = c2p - c1p;
    double dh = 0;
    if (c1p * c2p != 0) {
        dh = h2 - h1;
        if (dh > 180)
            dh -= 360;
        else if (dh < -180)
            dh += 360;
    }
    const double dH = 2 * std::sqrt(c1p * c2p) * std::sin(rad(dh / 2));
    const double lbar = (lab1[0] + lab2[0]) / 2, cbarp = (c1p + c2p) / 2;
    double hbar = h1 + h2;
    if (c1p * c2p != 0) {
        if (std::fabs(h1 - h2) <= 180)
            hbar = (h1 + h2) / 2;
        else if (h1 + h2 < 360)
            hbar = (h1 + h2 + 360) / 2;
        else
            hbar = (h1 + h2 - 360) / 2;
    }
    const double t = 1 - 0.17 * std::cos(rad(hbar - 30)) + 0.24 * std::cos(rad(2 * hbar)) +
                     0.32 * std::cos(rad(3 * hbar + 6)) - 0.20 * std::cos(rad(4 * hbar - 63));
    const double dTheta = 30 * std::exp(-std::pow((hbar - 275) / 25, 2));
    const double rc = 2 * std::sqrt(std::pow(cbarp, 7) / (std::pow(cbarp, 7) + p7));
    const double sl = 1 + 0.015 * std::pow(lbar - 50, 2) / std::sqrt(20 + std::pow(lbar - 50, 2));
    const double sc = 1 + 0.045 * cbarp, sh = 1 + 0.015 * cbarp * t;
    const double rt = -std::sin(rad(2 * dTheta)) * rc;
    return std::sqrt(std::pow(dL / sl, 2) + std::pow(dC / sc, 2) + std::pow(dH / sh, 2) +
                     rt * (dC / sc) * (dH / sh));
}

glm::vec3 gradeB(glm::vec3 x) {
    return {0.9f * x.x + 0.05f, std::pow(x.y, 1.3f), 0.8f * x.z + 0.1f * x.y};
}

TEST(LutMaths, CiedeReferenceMatchesSharmasTestData) {
    // Pairs 1, 7 and 17 of Sharma, Wu and Dalal's table: the reference above can be wrong too.
    EXPECT_NEAR(ciede2000({50, 2.6772, -79.7751}, {50, 0, -82.7485}), 2.0425, 1e-4);
    EXPECT_NEAR(ciede2000({50, 0, 0}, {50, -1, 2}), 2.3669, 1e-4);
    EXPECT_NEAR(ciede2000({50, 2.5, 0}, {73, 25, -18}), 27.1492, 1e-4);
}

TEST(LutMaths, DiffOfALutWithItselfIsExactlyZero) {
    const std::string dir = workDir();
    for (const std::string& a :
         {samplePath("sample_grade.cube"), writeCube(dir + "/b.cube", 5, gradeB)}) {
        const auto r = runCli("diff " + shellQuoted(a) + " " + shellQuoted(a) + " --json");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_THAT(r.out, HasSubstr("\"identical\": true"));
        EXPECT_EQ(jsonNumber(r.out, "max"), 0.0);
        EXPECT_EQ(jsonNumber(r.out, "mean"), 0.0);
    }
}

TEST(LutMaths, DiffOfTwoKnownLutsEqualsTheFloat64Reference) {
    const std::string dir = workDir();
    const std::string a = writeCube(dir + "/a.cube", 5, [](glm::vec3 x) { return x; });
    const std::string b = writeCube(dir + "/b.cube", 5, gradeB);
    double maxDe = 0, sumDe = 0;
    D3 maxSteps{}, sumSteps{};
    int n = 0;
    for (int bb = 0; bb < 5; ++bb)
        for (int g = 0; g < 5; ++g)
            for (int r = 0; r < 5; ++r) {
                const glm::vec3 x = glm::vec3(r, g, bb) / 4.0f;
                const glm::vec3 y = gradeB(x);
                const double de = ciede2000(toLab({x.x, x.y, x.z}), toLab({y.x, y.y, y.z}));
                maxDe = std::max(maxDe, de);
                sumDe += de;
                for (int c = 0; c < 3; ++c) {
                    const double s = std::fabs(double(x[c]) - double(y[c])) * 255.0;
                    maxSteps[c] = std::max(maxSteps[c], s);
                    sumSteps[c] += s;
                }
                ++n;
            }
    const auto r = runCli("diff " + shellQuoted(a) + " " + shellQuoted(b) + " --json --heatmap " +
                          shellQuoted(dir + "/h.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("\"identical\": false"));
    EXPECT_EQ(jsonNumber(r.out, "colors"), 125);
    EXPECT_NEAR(jsonNumber(r.out, "max"), maxDe, 1e-6 * maxDe);
    EXPECT_NEAR(jsonNumber(r.out, "mean"), sumDe / n, 1e-6 * sumDe / n);
    const auto steps = r.out.find("\"max_8bit_steps\": [");
    ASSERT_NE(steps, std::string::npos);
    double got[3];
    ASSERT_EQ(std::sscanf(r.out.c_str() + steps + 19, "%lf, %lf, %lf", &got[0], &got[1], &got[2]),
              3);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[c], maxSteps[c], 1e-4);
    // The heat map of the slices exists and is not black everywhere (the LUTs differ).
    const auto heat = lut::formats::readImage(dir + "/h.png");
    double brightest = 0;
    for (float v : heat.image.pixels())
        brightest = std::max(brightest, double(v));
    EXPECT_GT(brightest, 0.5);
}

// diff --fail-above DE (issue 43: diff always exited 0): exit 1 when the largest ΔE2000 is above
// DE, judged against the float64 reference's largest over the lattice (diff compares A's 5^3
// lattice: the same colours); 0 at or under it; the answer said on stderr, even with -q.
TEST(LutMaths, DiffFailAboveExitsOneAboveTheLargestDifference) {
    const std::string dir = workDir();
    const std::string a = writeCube(dir + "/a.cube", 5, [](glm::vec3 x) { return x; });
    const std::string b = writeCube(dir + "/b.cube", 5, gradeB);
    double maxDe = 0;
    for (int bb = 0; bb < 5; ++bb)
        for (int g = 0; g < 5; ++g)
            for (int r = 0; r < 5; ++r) {
                const glm::vec3 x = glm::vec3(r, g, bb) / 4.0f;
                const glm::vec3 y = gradeB(x);
                maxDe = std::max(maxDe, ciede2000(toLab({x.x, x.y, x.z}), toLab({y.x, y.y, y.z})));
            }
    ASSERT_GT(maxDe, 1.0);
    const std::string ab = "diff " + shellQuoted(a) + " " + shellQuoted(b);
    auto above = [&](double x) {
        std::ostringstream s;
        s.precision(9);
        s << " --fail-above " << x;
        return s.str();
    };
    auto r = runCli(ab + above(maxDe * 1.001));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("ΔE2000   max"));
    r = runCli(ab + above(maxDe * 0.999));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.out, HasSubstr("ΔE2000   max")) << "the report still printed";
    EXPECT_THAT(r.err, HasSubstr("differ by up to ΔE2000 "));
    EXPECT_THAT(r.err, HasSubstr("above --fail-above"));
    r = runCli(ab + above(maxDe * 0.999) + " -q");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_THAT(r.err, HasSubstr("lutkit: error: "));
    r = runCli(ab + above(maxDe * 0.999) + " --json");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NEAR(jsonNumber(r.out, "max"), maxDe, 1e-6 * maxDe);
    // 0: any difference fails; none passes.
    EXPECT_EQ(runCli(ab + " --fail-above 0 -q").exitCode, 1);
    EXPECT_EQ(
        runCli("diff " + shellQuoted(a) + " " + shellQuoted(a) + " --fail-above 0 -q").exitCode, 0);
    EXPECT_EQ(runCli(ab + " --fail-above -1").exitCode, 2);
}

TEST(LutMaths, InvertThenComposeIsCloseToNeutral) {
    const std::string dir = workDir();
    // Invertible: per-channel increasing curves from 0 to 1, on a 3D lattice.
    const std::string a = writeCube(dir + "/a.cube", 17, [](glm::vec3 x) {
        return glm::vec3(std::pow(x.x, 0.7f), std::pow(x.y, 1.2f), 0.5f * x.z + 0.5f * x.z * x.z);
    });
    // The table form (auto writes a shaper for x^1.2's steep inverse): compose then works on
    // the same lattice, so its entries are the round trip's.
    auto r = runCli("invert " + shellQuoted(a) + " " + shellQuoted(dir + "/inv.cube") +
                    " --json --lut-form table");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("\"invertible\": true"));
    EXPECT_EQ(jsonNumber(r.out, "unreachable"), 0);
    const double roundTrip = jsonNumber(r.out, "max", r.out.find("\"round_trip\""));
    EXPECT_LT(roundTrip, 0.02);
    r = runCli("compose " + shellQuoted(a) + " " + shellQuoted(dir + "/inv.cube") + " " +
               shellQuoted(dir + "/c.cube"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("error    between lattice points"));
    const lut::LutFile c = lut::formats::readLut(dir + "/c.cube");
    ASSERT_EQ(c.cube->size(), 17);
    double worst = 0;
    for (int b = 0; b < 17; ++b)
        for (int g = 0; g < 17; ++g)
            for (int rr = 0; rr < 17; ++rr)
                for (int ch = 0; ch < 3; ++ch)
                    worst = std::max(worst, std::fabs(double(c.cube->at(rr, g, b)[ch]) -
                                                      double(glm::vec3(rr, g, b)[ch]) / 16.0));
    EXPECT_LT(worst, 0.02);
    EXPECT_LE(worst, roundTrip + 1e-6); // the invert report said how far it would be
}

TEST(LutMaths, InvertReportsWhereThereIsNoInverse) {
    const std::string dir = workDir();
    // Flat in green: no input reaches a target with another green.
    const std::string a =
        writeCube(dir + "/a.cube", 9, [](glm::vec3 x) { return glm::vec3(x.x, 0.5f, x.z); });
    const auto r = runCli("invert " + shellQuoted(a) + " " + shellQuoted(dir + "/inv.cube"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("have no exact preimage"));
    EXPECT_THAT(r.out, HasSubstr("where    no inverse:"));
    const lut::LutFile inv = lut::formats::readLut(dir + "/inv.cube");
    for (const auto& e : inv.cube->entries())
        for (int c = 0; c < 3; ++c)
            EXPECT_TRUE(std::isfinite(e[c]));
}

TEST(LutMaths, MixResizeSmoothAdjust) {
    const std::string dir = workDir();
    const std::string a = writeCube(dir + "/a.cube", 5, [](glm::vec3 x) { return x; });
    const std::string b = writeCube(dir + "/b.cube", 5, gradeB);
    // mix: (1 - t) A + t B per entry, exactly.
    auto r = runCli("mix " + shellQuoted(a) + " " + shellQuoted(b) + " " +
                    shellQuoted(dir + "/m.cube") + " --strength 0.25");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("the mix is exact"));
    const lut::LutFile m = lut::formats::readLut(dir + "/m.cube");
    for (int i = 0; i < 125; ++i) {
        const glm::vec3 x = glm::vec3(i % 5, (i / 5) % 5, i / 25) / 4.0f;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(m.cube->entries()[i][c], 0.75 * x[c] + 0.25 * gradeB(x)[c], 1e-6);
    }
    // resize of an affine LUT: every interpolation reproduces it, error 0.
    const auto affine = [](glm::vec3 x) {
        return glm::vec3(0.1f + 0.8f * x.x, 0.2f + 0.3f * x.x + 0.5f * x.y, 0.9f - 0.7f * x.z);
    };
    const std::string af = writeCube(dir + "/af.cube", 3, affine);
    r = runCli("resize " + shellQuoted(af) + " " + shellQuoted(dir + "/r.cube") + " --size 9");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_LT(printedMax(r.out, "error    "), 1e-6);
    const lut::LutFile rs = lut::formats::readLut(dir + "/r.cube");
    ASSERT_EQ(rs.cube->size(), 9);
    for (int i = 0; i < 729; ++i) {
        const glm::vec3 want = affine(glm::vec3(i % 9, (i / 9) % 9, i / 81) / 8.0f);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(rs.cube->entries()[i][c], want[c], 1e-6);
    }
    // smooth leaves an affine LUT as it is.
    r = runCli("smooth " + shellQuoted(af) + " " + shellQuoted(dir + "/s.cube") + " --sigma 2");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_LT(printedMax(r.out, "change   "), 1e-6);
    r = runCli("smooth " + shellQuoted(b) + " " + shellQuoted(dir + "/s2.cube") + " --sigma 2");
    EXPECT_GT(printedMax(r.out, "change   "), 1e-3); // a curved LUT does change
    // adjust: contrast -1 makes every entry flat grey 0.5.
    { std::ofstream(dir + "/flat.txt") << "# lutkit adjustment list 1\ncontrast -1\n"; }
    r = runCli("adjust " + shellQuoted(b) + " --adjustments " + shellQuoted(dir + "/flat.txt") +
               " " + shellQuoted(dir + "/flat.cube"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const lut::LutFile flat = lut::formats::readLut(dir + "/flat.cube");
    for (const auto& e : flat.cube->entries())
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(e[c], 0.5, 1e-6);
    // A bad list names the file, the line and the column: bad input.
    { std::ofstream(dir + "/bad.txt") << "exposure 1\ncontrast x\n"; }
    r = runCli("adjust " + shellQuoted(b) + " --adjustments " + shellQuoted(dir + "/bad.txt") +
               " " + shellQuoted(dir + "/bad.cube"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("bad.txt:2:"));
    EXPECT_FALSE(fs::exists(dir + "/bad.cube"));
}

TEST(LutMaths, PlotAndNeverOverTheInput) {
    const std::string dir = workDir();
    auto r = runCli("plot " + shellQuoted(samplePath("sample_grade.cube")) + " " +
                    shellQuoted(dir + "/p.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto img = lut::formats::readImageInfo(dir + "/p.png");
    EXPECT_GT(img.width, img.height);
    EXPECT_GE(img.height, 200);
    const std::string a = writeCube(dir + "/a.cube", 5, gradeB);
    for (const std::string& cmd :
         {"resize " + shellQuoted(a) + " " + shellQuoted(a) + " --size 3",
          "smooth " + shellQuoted(a) + " " + shellQuoted(a),
          "compose " + shellQuoted(a) + " " + shellQuoted(a) + " " + shellQuoted(a),
          "invert " + shellQuoted(a) + " " + shellQuoted(a),
          "plot " + shellQuoted(a) + " " + shellQuoted(a)}) {
        SCOPED_TRACE(cmd);
        r = runCli(cmd);
        EXPECT_EQ(r.exitCode, 1);
        const lut::LutFile same = lut::formats::readLut(a);
        EXPECT_EQ(same.cube->size(), 5);
    }
}

} // namespace
