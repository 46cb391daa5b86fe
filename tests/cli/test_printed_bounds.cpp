// SPDX-License-Identifier: Apache-2.0
// Every maximum error the LUT commands print is an upper bound of the truth: the truth measured
// here on 200,000 random inputs with OpenColorIO's processors (the files lutkit read and wrote,
// evaluated by OCIO, unoptimised), and the printed figure must not be below it. The tables are
// the kind where probing only lattice points and cell centres understated the error (issue 22):
// random (steep) tables, posterisation, a steep grade to invert, a config's conversion.
#include "CliTestSupport.h"
#include "OcioTestUtil.h"
#include "TestPaths.h"

#include <glm/exponential.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

namespace fs = std::filesystem;
using namespace lut::test;

namespace {

using lut::test::shellQuoted;

using Fn = std::function<glm::vec3(glm::vec3)>;

Fn randomTable(unsigned seed) {
    // a fresh random value per lattice point, from its position (the table is steep everywhere)
    return [seed](glm::vec3 x) {
        std::mt19937 rng(seed ^ static_cast<unsigned>(x.r * 1000 + x.g * 100000 + x.b * 1e7f));
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        return glm::vec3(u(rng), u(rng), u(rng));
    };
}

glm::vec3 posterise(glm::vec3 x) {
    glm::vec3 o;
    for (int c = 0; c < 3; ++c)
        o[c] = std::floor(std::min(x[c], 0.999f) * 4.0f) / 3.0f;
    return o;
}

// `count` random inputs, uniform in [lo, hi]^3 (fixed seed), packed RGB.
std::vector<float> randomInputs(glm::vec3 lo, glm::vec3 hi, int count = 200000,
                                unsigned seed = 22) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> v(3 * static_cast<std::size_t>(count));
    for (std::size_t i = 0; i < v.size(); ++i)
        v[i] = lo[static_cast<int>(i % 3)] + (hi - lo)[static_cast<int>(i % 3)] * u(rng);
    return v;
}

// OCIO's processor applied to packed RGB, in place.
void ocioApply(const OCIO::ConstCPUProcessorRcPtr& p, std::vector<float>& rgb) {
    OCIO::PackedImageDesc desc(rgb.data(), static_cast<long>(rgb.size() / 3), 1, 3);
    p->apply(desc);
}

double maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::fabs(double(a[i]) - double(b[i])));
    return worst;
}

// The number after "max " on the first line containing `line` (the printed figure: 3
// significant digits, rounded up).
double printedMax(const std::string& out, const std::string& line) {
    const auto l = out.find(line);
    EXPECT_NE(l, std::string::npos) << out;
    const auto m = out.find("max ", l);
    return m == std::string::npos ? NAN : std::stod(out.substr(m + 4));
}

double jsonNumber(const std::string& text, const std::string& key, std::size_t from = 0) {
    const auto k = text.find("\"" + key + "\": ", from);
    EXPECT_NE(k, std::string::npos) << key << " in " << text;
    return k == std::string::npos ? NAN : std::stod(text.substr(k + key.size() + 4));
}

void report(const std::string& what, double truth, double printed) {
    std::printf("[ measured ] %-48s truth %9.5f, printed max %9.5f (%.1f vs %.1f 8-bit steps)\n",
                what.c_str(), truth, printed, truth * 255, printed * 255);
}

} // namespace

TEST(PrintedBounds, ComposeOfSteepTables) {
    const std::string dir = workDir();
    const std::string a = writeCube(dir + "/a.cube", 5, randomTable(1));
    const std::string b = writeCube(dir + "/b.cube", 9, randomTable(2));
    for (int size : {9, 17}) {
        const std::string out = dir + "/ab" + std::to_string(size) + ".cube";
        const auto r = runCli("compose " + shellQuoted(a) + " " + shellQuoted(b) + " " +
                              shellQuoted(out) + " --size " + std::to_string(size));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        std::vector<float> x = randomInputs(glm::vec3(0.0f), glm::vec3(1.0f)), y = x;
        ocioApply(ocioFileProcessor(a), x);
        ocioApply(ocioFileProcessor(b), x);
        ocioApply(ocioFileProcessor(out), y);
        const double truth = maxDifference(x, y), printed = printedMax(r.out, "error");
        report("compose random 5^3 then 9^3 at " + std::to_string(size) + "^3", truth, printed);
        EXPECT_GE(printed, truth) << r.out;
        EXPECT_NE(r.out.find("a bound over every input"), std::string::npos) << r.out;
    }
}

TEST(PrintedBounds, ResizeOfPosterisation) {
    const std::string dir = workDir();
    const std::string src = writeCube(dir + "/p.cube", 33, posterise);
    for (int size : {9, 17, 24}) {
        const std::string out = dir + "/p" + std::to_string(size) + ".cube";
        const auto r = runCli("resize " + shellQuoted(src) + " " + shellQuoted(out) + " --size " +
                              std::to_string(size));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        std::vector<float> x = randomInputs(glm::vec3(0.0f), glm::vec3(1.0f)), y = x;
        ocioApply(ocioFileProcessor(src), x);
        ocioApply(ocioFileProcessor(out), y);
        const double truth = maxDifference(x, y), printed = printedMax(r.out, "error");
        report("resize posterised 33^3 -> " + std::to_string(size), truth, printed);
        EXPECT_GE(printed, truth) << r.out;
    }
    // convert resamples the same way and prints the same kind of figure
    const std::string out = dir + "/p17.3dl";
    const auto r =
        runCli("convert " + shellQuoted(src) + " " + shellQuoted(out) + " --size 17 --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const double printed = jsonNumber(r.out, "max", r.out.find("\"resample\""));
    Fn identity = [](glm::vec3 v) { return v; };
    std::vector<float> x = randomInputs(glm::vec3(0.0f), glm::vec3(1.0f)), y = x;
    ocioApply(ocioFileProcessor(src), x);
    // the resampling alone: the 17^3 table before the 12-bit storage, as a float .cube
    const auto f =
        runCli("resize " + shellQuoted(src) + " " + shellQuoted(dir + "/r17.cube") + " --size 17");
    ASSERT_EQ(f.exitCode, 0) << f.err;
    ocioApply(ocioFileProcessor(dir + "/r17.cube"), y);
    const double truth = maxDifference(x, y);
    report("convert posterised 33^3 -> 17^3 .3dl (resampling)", truth, printed);
    EXPECT_GE(printed, truth) << r.out;
}

TEST(PrintedBounds, InvertResidualAndRoundTrip) {
    const std::string dir = workDir();
    // steep gamma curves that fix 0 and 1 and crosstalk that vanishes on the faces: the cube
    // onto itself, so every target has a preimage and the lattice points are solved exactly
    const std::string a = writeCube(dir + "/g.cube", 17, [](glm::vec3 x) {
        const float bump = 0.08f * std::sin(3.14159265f * x.r) * std::sin(3.14159265f * x.g) *
                           std::sin(3.14159265f * x.b);
        const glm::vec3 t = glm::pow(x, glm::vec3(0.35f, 0.5f, 2.2f));
        return glm::vec3(t.r + bump, t.g - bump, t.b + 0.5f * bump);
    });
    const std::string inv = dir + "/inv.cube";
    const auto r = runCli("invert " + shellQuoted(a) + " " + shellQuoted(inv) + " --size 9 --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto pa = ocioFileProcessor(a), pi = ocioFileProcessor(inv);
    std::vector<float> y = randomInputs(glm::vec3(0.0f), glm::vec3(1.0f)), ay = y;
    ocioApply(pi, ay);
    ocioApply(pa, ay);
    const double residual = maxDifference(ay, y);
    const double printedResidual = jsonNumber(r.out, "max", r.out.find("\"residual\": {"));
    report("invert residual |A(inv(y)) - y|", residual, printedResidual);
    EXPECT_GE(printedResidual, residual) << r.out;
    EXPECT_LT(jsonNumber(r.out, "max_residual"), residual) << "the lattice points understate it";
    std::vector<float> x = y, ix = y;
    ocioApply(pa, ix);
    ocioApply(pi, ix);
    const double roundTrip = maxDifference(ix, x);
    const double printedRoundTrip = jsonNumber(r.out, "max", r.out.find("\"round_trip\""));
    report("invert round trip |inv(A(x)) - x|", roundTrip, printedRoundTrip);
    EXPECT_GE(printedRoundTrip, roundTrip) << r.out;
}

TEST(PrintedBounds, BakeFromAConfig) {
    const std::string dir = workDir();
    const std::string cfg = std::string(LUTKIT_BINARY_DIR) + "/share/lutkit/ocio/config.ocio";
    auto config = OCIO::Config::CreateFromFile(cfg.c_str());
    struct Case {
        const char* in;
        const char* out;
        int size;
    };
    for (const Case& c :
         {Case{"ACEScct", "Rec.709", 17}, Case{"ACEScct", "sRGB", 9}, Case{"ACEScg", "sRGB", 33}}) {
        const std::string name = std::string(c.in) + "_" + c.out + std::to_string(c.size);
        const std::string out = dir + "/" + name + ".cube";
        const auto r = runCli("bake --config " + shellQuoted(cfg) + " --inputspace " + c.in +
                              " --outputspace " + c.out + " --cubesize " + std::to_string(c.size) +
                              " --json " + shellQuoted(out));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const double printed = jsonNumber(r.out, "max", r.out.find("\"error\""));
        glm::vec3 lo, hi;
        const auto dmin = r.out.find("\"domain_min\": [");
        const auto dmax = r.out.find("\"domain_max\": [");
        lo = glm::vec3(std::stof(r.out.substr(dmin + 15)));
        hi = glm::vec3(std::stof(r.out.substr(dmax + 15)));
        // inputs uniform over the domain, and (a log2 shaper's case) uniform in stops over it
        std::vector<float> x = randomInputs(lo, hi, 100000);
        std::vector<float> stops =
            randomInputs(glm::vec3(-12.0f), glm::vec3(std::log2(hi.x)), 100000, 23);
        for (float& v : stops)
            v = std::exp2(v);
        x.insert(x.end(), stops.begin(), stops.end());
        std::vector<float> want = x;
        ocioApply(config->getProcessor(c.in, c.out)
                      ->getOptimizedCPUProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                                 OCIO::OPTIMIZATION_NONE),
                  want);
        ocioApply(ocioFileProcessor(out), x);
        double truth = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i)
            if (std::isfinite(want[i]))
                truth = std::max(truth, std::fabs(double(x[i]) - want[i]));
        report("bake " + name, truth, printed);
        EXPECT_GE(printed, truth) << r.out;
        EXPECT_TRUE(r.out.find("\"max_is_bound\": true") != std::string::npos) << r.out;
    }
}
