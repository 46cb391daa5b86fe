// SPDX-License-Identifier: Apache-2.0
// The truth harness, the LUT-maths commands: compose, resize, mix, smooth and bake, each x the
// outputs that change numbers (float .cube, 12-bit .3dl, 8-bit .png strip) x the options that do
// (--size, sources steep and smooth). The truth is what the command stands for, computed from the
// sources as OpenColorIO reads them (compose: B after A; mix: (1 - t) A + t B; resize, smooth and
// bake: the source itself), against the written file (OpenColorIO; a LUT image interpolated here
// in float64), on random inputs in [0,1] between the lattice points. The printed figure is the
// operation's maximum plus what storing cost (the writer's "quantised to 8 bits" or "stores
// 12-bit integers" note; bake's figure is the file read back, storage included); it must not be
// below the truth.
#include "TruthHarness.h"

#include <gtest/gtest.h>

using namespace lut::truth;

namespace {

// What storing the written file cost, as its writer said (0 for a float format).
double storagePrinted(const std::string& text) {
    for (const char* key : {"quantised to", "-bit integers:"})
        if (const double v = maxAfter(text, key); !std::isnan(v))
            return v;
    return 0.0;
}

std::string steepSource(const std::string& dir) {
    return writeCube(dir + "/steep.cube", 9, [](glm::dvec3 p) {
        std::mt19937 rng(static_cast<unsigned>(p.r * 1000 + p.g * 100000 + p.b * 1e7));
        std::uniform_real_distribution<double> u(0.0, 1.0);
        return glm::dvec3(u(rng), u(rng), u(rng));
    });
}

std::string smoothSource(const std::string& dir) {
    return writeCube(dir + "/grade.cube", 17, [](glm::dvec3 p) {
        glm::dvec3 t(std::pow(p.r, 0.8), std::pow(p.g, 0.9), std::pow(p.b, 1.2));
        const double y = 0.3 * t.x + 0.6 * t.y + 0.1 * t.z;
        t = glm::dvec3(y) + 1.3 * (t - glm::dvec3(y));
        for (int c = 0; c < 3; ++c)
            t[c] = std::clamp(t[c], 0.0, 1.0);
        return t;
    });
}

struct Out {
    std::string ext;
    bool image = false;
};
const Out kOutputs[] = {{".cube"}, {".3dl"}, {".png", true}};

std::vector<float> applyFile(const std::string& file, bool image, std::vector<float> x) {
    if (image)
        stripApply(file, x);
    else
        ocioApply(file, x);
    return x;
}

// Runs `args` (the output last), compares with `want` and checks the printed bound.
void check(const std::string& what, const std::string& args, const std::string& out, const Out& o,
           const std::string& key, const std::vector<float>& x, const std::vector<float>& want,
           bool storageIncluded = false) {
    const auto r = lut::test::runCli(args + " " + shellQuoted(out) + " -y");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const double op = maxAfter(r.out, key);
    ASSERT_FALSE(std::isnan(op)) << what << "\n" << r.out;
    const double printed = op + (storageIncluded ? 0.0 : storagePrinted(r.out));
    const Truth t = compare(want, applyFile(out, o.image, x));
    row(what + " -> " + o.ext, t.max, printed, t.mean);
    EXPECT_GE(printed + kOracleRounding, t.max) << what << " -> " << o.ext << "\n" << r.out;
}

} // namespace

TEST(Truth, ComposePrintedMaximaBoundBAfterA) {
    const std::string dir = workDir("compose");
    const std::string steep = steepSource(dir), grade = smoothSource(dir);
    const std::vector<float> x = randomUnitInputs(100000, 46);
    struct Case {
        std::string a, b, args, name;
    };
    int i = 0;
    for (const Case& c : {Case{grade, steep, "", "grade then steep 9^3"},
                          Case{steep, grade, "--size 17", "steep then grade, --size 17"},
                          Case{grade, grade, "--size 9", "grade twice, --size 9"}}) {
        std::vector<float> want = x;
        ocioApply(c.a, want);
        ocioApply(c.b, want);
        for (const Out& o : kOutputs)
            check("compose " + c.name,
                  "compose " + shellQuoted(c.a) + " " + shellQuoted(c.b) + " " + c.args,
                  dir + "/c" + std::to_string(i++) + o.ext, o, "against B(A(x))", x, want);
    }
}

TEST(Truth, ResizeSmoothAndMixPrintedMaximaBoundTheTruth) {
    const std::string dir = workDir("lutmaths");
    const std::string steep = steepSource(dir), grade = smoothSource(dir);
    const std::vector<float> x = randomUnitInputs(100000, 47);
    std::vector<float> steepOut = x, gradeOut = x;
    ocioApply(steep, steepOut);
    ocioApply(grade, gradeOut);
    int i = 0;
    for (const Out& o : kOutputs) {
        const std::string n = std::to_string(i++);
        check("resize steep 9^3 --size 17", "resize " + shellQuoted(steep) + " --size 17",
              dir + "/r17_" + n + o.ext, o, "against the original", x, steepOut);
        check("resize steep 9^3 --size 5", "resize " + shellQuoted(steep) + " --size 5",
              dir + "/r5_" + n + o.ext, o, "against the original", x, steepOut);
        check("resize grade 17^3 --size 9", "resize " + shellQuoted(grade) + " --size 9",
              dir + "/rg9_" + n + o.ext, o, "against the original", x, gradeOut);
        // smooth prints how far it moved the LUT: a bound of |smoothed - original|
        check("smooth steep 9^3 --sigma 1", "smooth " + shellQuoted(steep) + " --sigma 1",
              dir + "/s_" + n + o.ext, o, "against the original", x, steepOut);
        std::vector<float> mixed(x.size());
        for (std::size_t k = 0; k < x.size(); ++k)
            mixed[k] = static_cast<float>(0.7 * gradeOut[k] + 0.3 * steepOut[k]);
        check("mix grade 17^3 + 0.3 steep 9^3 (resampled)",
              "mix " + shellQuoted(grade) + " " + shellQuoted(steep) + " --strength 0.3",
              dir + "/m_" + n + o.ext, o, "B resampled onto A's lattice", x, mixed);
    }
}

TEST(Truth, BakePrintedMaximaBoundTheSourceFile) {
    const std::string dir = workDir("bake");
    const std::string steep = steepSource(dir), shaped = writeShapedCube(dir + "/shaped.cube");
    const std::vector<float> x = randomUnitInputs(100000, 48);
    for (const std::string& src : {steep, shaped}) {
        std::vector<float> want = x;
        ocioApply(src, want);
        int i = 0;
        for (const Out& o : kOutputs)
            for (const int size : {17, 33}) {
                const std::string out =
                    dir + "/b" + std::to_string(i++) + (src == steep ? "steep" : "shaped") + o.ext;
                check(std::string("bake --lut ") + (src == steep ? "steep 9^3" : "shaper + 33^3") +
                          " --cubesize " + std::to_string(size),
                      "bake --lut " + shellQuoted(src) + " --cubesize " + std::to_string(size), out,
                      o, "error", x, want);
            }
    }
}

// Issue 40's fault in bake: `bake --lut` of a shaper .cube to a format that keeps one input range
// (Resolve .cube, .clf) or none (Adobe .cube) sampled the table over the shaper's 0..64, so inputs
// in 0..1 fell in the first cells: OpenColorIO's reading of the written file was off its reading
// of the source by mean 42.7 / max 81.8 8-bit steps (Resolve, 64^3) and 78.5 / 109.0 (Adobe, 32^3)
// on these inputs. Now sampled over 0..1 as convert does (ociobakelut's files: 0.224 / 16.06 and
// 0.750 / 19.00), said so, and the printed maximum is over 0..1 and bounds the truth.
TEST(Truth, BakeOfAShaperSamplesTheDisplayRange) {
    const std::string dir = workDir("bake-display");
    const std::string src = writeShapedCube(dir + "/shaped.cube");
    const std::vector<float> x = randomUnitInputs(100000, 49);
    std::vector<float> want = x;
    ocioApply(src, want);
    const std::pair<const char*, const char*> outs[] = {{"resolve.cube", "--format resolve_cube"},
                                                        {"adobe.cube", "--format iridas_cube"},
                                                        {"table.clf", ""}};
    for (const auto& [name, args] : outs) {
        const std::string out = dir + "/" + name;
        const auto r = lut::test::runCli("bake --lut " + shellQuoted(src) + " " + args + " " +
                                         shellQuoted(out) + " -y --json");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.out.find("over 0..1, where display pictures live"), std::string::npos) << r.out;
        const std::string bytes = lut::test::fileBytes(out);
        for (const char* range : {"INPUT_RANGE 0 64", "DOMAIN_MAX 64", "<maxInValue>64"})
            EXPECT_EQ(bytes.find(range), std::string::npos) << name << ": " << range;
        const double printed = jsonNumber(r.out, "max", r.out.find("\"error\": "));
        std::vector<float> got = x;
        ocioApply(out, got);
        const Truth t = compare(want, got);
        row(std::string("bake --lut shaper + 33^3 ") + args + " (" + name + ")", t.max, printed,
            t.mean);
        EXPECT_LT(t.mean * 255, 1.0) << name;
        EXPECT_GE(printed + kOracleRounding, t.max) << name << "\n" << r.out;
    }
}
