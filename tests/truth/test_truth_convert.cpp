// SPDX-License-Identifier: Apache-2.0
// The truth harness, convert: every output format x the options that change numbers (a shaper
// sampled onto one lattice, --size, the Adobe dialect), from a shaper + table source and from a
// steep random table. For each written file the truth is the source and the written file
// evaluated by OpenColorIO's unoptimised processors (a LUT image: tetrahedrally in float64 here)
// on 187,500 random inputs in [0,1] (the domain the printed figures name; a quarter of them in
// [0, 1/16], where a log shaper is steepest), and the printed maximum (resampling or sampling the
// shaper, plus storage: --json, the full value) must not be below it.
#include "TruthHarness.h"

#include <gtest/gtest.h>

using namespace lut::truth;

namespace {

struct Output {
    std::string ext;    // file name ending
    std::string args;   // more convert arguments
    bool image = false; // a LUT image (evaluated here), else OpenColorIO reads it
};

const std::vector<Output>& outputs() {
    static const std::vector<Output> v = {
        {".cube", ""},                     // Resolve: shaper kept
        {".cube", "--size 17"},            // the table resampled, shaper kept
        {".cube", "--format iridas_cube"}, // Adobe: the shaper sampled over 0..1
        {".cube", "--format iridas_cube --size 17"},
        {".3dl", ""}, // 12-bit, no shaper
        {".3dl", "--size 17"},
        {".csp", ""}, // the prelut OpenColorIO reads as a cubic
        {".clf", ""},
        {".ctf", ""},
        {".spi3d", ""},
        {".itx", ""},
        {".cub", ""},
        {".lut", ""},       // Houdini
        {".png", "", true}, // 8-bit strip
        {".png", "--size 16", true},
        {".exr", "--size 17", true}, // float strip
    };
    return v;
}

std::string tag(const Output& o) {
    std::string t = o.ext + (o.args.empty() ? "" : " " + o.args);
    return t;
}

// Runs convert src -> out with o, returns the printed bound (resample + storage) or NaN.
double convertPrinted(const std::string& src, const std::string& out, const Output& o,
                      std::string& text) {
    const auto r = lut::test::runCli("convert " + shellQuoted(src) + " " + shellQuoted(out) +
                                     " -y --json " + o.args);
    text = r.out + r.err;
    EXPECT_EQ(r.exitCode, 0) << r.err;
    if (r.exitCode != 0)
        return NAN;
    const auto rs = r.out.find("\"resample\": {");
    const double resample = rs == std::string::npos ? 0.0 : jsonNumber(r.out, "max", rs);
    const double storage = jsonNumber(r.out, "max", r.out.find("\"storage\": {"));
    EXPECT_FALSE(std::isnan(storage)) << r.out;
    return resample + storage;
}

void runMatrix(const std::string& name, const std::string& src) {
    const std::string dir = workDir(name);
    const std::vector<float> x = randomUnitInputs();
    std::vector<float> want = x;
    ocioApply(src, want);
    int i = 0;
    for (const Output& o : outputs()) {
        const std::string out = dir + "/out" + std::to_string(i++) + o.ext;
        std::string text;
        const double printed = convertPrinted(src, out, o, text);
        std::vector<float> got = x;
        if (o.image)
            stripApply(out, got);
        else
            ocioApply(out, got);
        const Truth t = compare(want, got);
        row("convert " + name + " -> " + tag(o), t.max, printed, t.mean);
        EXPECT_GE(printed + kOracleRounding, t.max) << name << " -> " << tag(o) << "\n" << text;
        // every printed maximum says what it covers
        EXPECT_EQ(text.find("max: \n"), std::string::npos) << text;
    }
}

} // namespace

TEST(Truth, ConvertOfAShaperAndTableToEveryFormat) {
    const std::string dir = workDir("shaped-src");
    runMatrix("shaper 4096 + 33^3", writeShapedCube(dir + "/shaped.cube"));
}

TEST(Truth, ConvertOfASteepTableToEveryFormat) {
    const std::string dir = workDir("steep-src");
    // a fresh random value per lattice point: steep everywhere, resampling costs the most
    const std::string src = writeCube(dir + "/steep.cube", 9, [](glm::dvec3 p) {
        std::mt19937 rng(static_cast<unsigned>(p.r * 1000 + p.g * 100000 + p.b * 1e7));
        std::uniform_real_distribution<double> u(0.0, 1.0);
        return glm::dvec3(u(rng), u(rng), u(rng));
    });
    runMatrix("random 9^3", src);
}

// Issue 40: a shaper .cube written with --format iridas_cube (what Photoshop reads) was baked over
// the shaper's 0..64, so inputs in 0..1 came out off by mean 85 / max 108 8-bit steps here (mean
// 115 / max 153 on the file) while the warning printed mean 0.238 (averaged over 0..64).
// Now sampled over 0..1 (said so), OpenColorIO's reading of both files within a step on average.
TEST(Truth, IridasCubeOfAShaperSamplesTheDisplayRange) {
    const std::string dir = workDir("iridas");
    const std::string src = writeShapedCube(dir + "/shaped.cube");
    const std::string out = dir + "/adobe.cube";
    const auto r = lut::test::runCli("convert " + shellQuoted(src) + " " + shellQuoted(out) +
                                     " --format iridas_cube");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("over 0..1, where display pictures live"), std::string::npos) << r.out;
    EXPECT_EQ(lut::test::fileBytes(out).find("DOMAIN_MAX 64"), std::string::npos);
    const std::vector<float> x = randomUnitInputs(200000, 41, false); // uniform in [0,1]^3
    std::vector<float> want = x, got = x;
    ocioApply(src, want);
    ocioApply(out, got);
    const Truth t = compare(want, got);
    // the printed mean is over 0..1 too: within a factor of 3 of the truth's
    const auto js =
        lut::test::runCli("convert " + shellQuoted(src) + " " + shellQuoted(dir + "/adobe2.cube") +
                          " --format iridas_cube --json");
    const double printedMean = jsonNumber(js.out, "mean", js.out.find("\"resample\": {"));
    row("iridas_cube of a shaper, uniform over 0..1", t.max,
        jsonNumber(js.out, "max", js.out.find("\"resample\": {")), t.mean);
    std::printf("[ truth    ] the same: mean truth %.3f, printed %.3f 8-bit steps\n", t.mean * 255,
                printedMean * 255);
    EXPECT_LT(t.mean * 255, 1.0);
    EXPECT_LT(printedMean, 3.0 * t.mean) << js.out;
    EXPECT_GT(printedMean, t.mean / 3.0) << js.out;
}
