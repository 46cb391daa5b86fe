// SPDX-License-Identifier: Apache-2.0
// lutkit convert: exact round trips, the error report checked against float64 references
// computed here, refusal to overwrite the input, and usage errors.
#include "CliTestSupport.h"
#include "test_convert_json.h"

#include "lut/formats/Registry.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace fs = std::filesystem;
using lut::test::runCli;
using lut::test::samplePath;
using lut::test::workDir;

namespace {

// Our own folder: TestSupport's runCli() clears the test's tempDir() on every call.
using lut::test::shellQuoted;

using lut::test::fileBytes;

// Float64 trilinear evaluation with the same clamp-to-edge policy as lutlib.
struct Vec3d {
    double v[3];
};
Vec3d trilinear(const lut::Lut3D& l, const double in[3]) {
    const int n = l.size();
    int i0[3];
    double f[3];
    for (int c = 0; c < 3; ++c) {
        const double lo = l.domainMin()[c], hi = l.domainMax()[c];
        double x = (in[c] - lo) / (hi - lo) * (n - 1);
        x = std::clamp(x, 0.0, double(n - 1));
        i0[c] = std::min(int(std::floor(x)), n - 2);
        f[c] = x - i0[c];
    }
    Vec3d out{{0, 0, 0}};
    for (int corner = 0; corner < 8; ++corner) {
        const int dr = corner & 1, dg = (corner >> 1) & 1, db = (corner >> 2) & 1;
        const double w = (dr ? f[0] : 1 - f[0]) * (dg ? f[1] : 1 - f[1]) * (db ? f[2] : 1 - f[2]);
        const glm::vec3 e = l.at(i0[0] + dr, i0[1] + dg, i0[2] + db);
        for (int c = 0; c < 3; ++c)
            out.v[c] += w * e[c];
    }
    return out;
}

lut::Lut3D readCube(const std::string& path) {
    const lut::LutFile f = lut::formats::readLut(path);
    EXPECT_TRUE(f.cube.has_value()) << path;
    return *f.cube;
}

} // namespace

TEST(CliConvert, CubeToCubeIsExact) {
    const std::string dir = workDir();
    const std::string out = dir + "/copy.cube";
    const auto r = runCli("convert " + shellQuoted(samplePath("sample_grade.cube")) + " " +
                          shellQuoted(out) + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto js = lut::test::json::parse(r.out);
    EXPECT_TRUE(js["resample"].isNull());
    EXPECT_EQ(js["storage"]["max"].number, 0.0);
    EXPECT_EQ(js["output_format"].string, "cube");
    const lut::Lut3D a = readCube(samplePath("sample_grade.cube"));
    const lut::Lut3D b = readCube(out);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.entryCount(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(a.entries()[i][c], b.entries()[i][c]) << i;
    EXPECT_EQ(a.title(), b.title());
    EXPECT_EQ(a.comments(), b.comments());
}

TEST(CliConvert, ResampleReportMatchesFloat64Reference) {
    const std::string dir = workDir();
    const std::string out = dir + "/small.cube";
    const auto r = runCli("convert " + shellQuoted(samplePath("sample_grade.cube")) + " " +
                          shellQuoted(out) + " --size 17 --interp trilinear --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto js = lut::test::json::parse(r.out);
    ASSERT_FALSE(js["resample"].isNull());
    EXPECT_EQ(js["resample"]["from"].number, 33);
    EXPECT_EQ(js["resample"]["to"].number, 17);
    EXPECT_EQ(js["resample"]["interp"].string, "trilinear");
    EXPECT_GE(js["resample"]["error"]["seconds"].number, 0.0);

    const lut::Lut3D src = readCube(samplePath("sample_grade.cube"));
    const lut::Lut3D dst = readCube(out);
    ASSERT_EQ(dst.size(), 17);
    // The written table is the source evaluated at the 17^3 lattice.
    for (int b = 0; b < 17; ++b)
        for (int g = 0; g < 17; ++g)
            for (int rr = 0; rr < 17; ++rr) {
                const double in[3] = {rr / 16.0, g / 16.0, b / 16.0};
                const Vec3d want = trilinear(src, in);
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(dst.at(rr, g, b)[c], want.v[c], 2e-6);
            }
    // The reported maximum bounds the error over every input: measured here on 100,000 random
    // inputs, both tables evaluated (trilinear) in float64; the mean is close to theirs.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double maxAbs = 0, sum = 0;
    std::size_t count = 0;
    for (int i = 0; i < 100000; ++i) {
        const double in[3] = {u(rng), u(rng), u(rng)};
        const Vec3d a = trilinear(src, in), b2 = trilinear(dst, in);
        for (int c = 0; c < 3; ++c) {
            const double d = std::fabs(a.v[c] - b2.v[c]);
            maxAbs = std::max(maxAbs, d);
            sum += d;
            ++count;
        }
    }
    const double mean = sum / double(count);
    ASSERT_GT(maxAbs, 1e-4); // the grade is curved: resampling it to 17^3 must cost something
    EXPECT_GE(js["resample"]["error"]["max"].number, maxAbs);
    EXPECT_LE(js["resample"]["error"]["max"].number, 1.3 * maxAbs);
    EXPECT_NEAR(js["resample"]["error"]["mean"].number, mean, 0.05 * mean);
    EXPECT_NEAR(js["resample"]["error"]["max_8bit_steps"].number,
                255 * js["resample"]["error"]["max"].number, 1e-6);
    EXPECT_TRUE(js["resample"]["error"]["max_is_bound"].boolean);
    // A float .cube stores the resampled floats: no storage loss.
    EXPECT_LE(js["storage"]["max"].number, 1e-7);
}

TEST(CliConvert, EightBitQuantisationMatchesReference) {
    const std::string dir = workDir();
    const std::string out = dir + "/strip.png";
    const auto r = runCli("convert " + shellQuoted(samplePath("sample_grade.cube")) + " " +
                          shellQuoted(out) + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto js = lut::test::json::parse(r.out);
    ASSERT_FALSE(js["storage"].isNull()) << r.out;
    const lut::Lut3D src = readCube(samplePath("sample_grade.cube"));
    double maxAbs = 0, sum = 0;
    for (const auto& e : src.entries())
        for (int c = 0; c < 3; ++c) {
            const double v = std::clamp(double(e[c]), 0.0, 1.0);
            const double d = std::fabs(double(e[c]) - std::round(v * 255.0) / 255.0);
            maxAbs = std::max(maxAbs, d);
            sum += d;
        }
    const double mean = sum / (3.0 * double(src.entryCount()));
    EXPECT_GT(maxAbs, 1e-3);
    EXPECT_NEAR(js["storage"]["max"].number, maxAbs, 1e-6);
    EXPECT_NEAR(js["storage"]["mean"].number, mean, 1e-6);
    EXPECT_LE(js["storage"]["max_8bit_steps"].number, 0.5 + 1e-4);
}

TEST(CliConvert, ToNutexbResamplesTo16Tetrahedral) {
    const std::string dir = workDir();
    const std::string out = dir + "/color_grading_lut.nutexb";
    const auto r = runCli("convert " + shellQuoted(samplePath("sample_grade.cube")) + " " +
                          shellQuoted(out) + " --json --target raw");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto js = lut::test::json::parse(r.out);
    ASSERT_FALSE(js["resample"].isNull()) << r.out;
    EXPECT_EQ(js["resample"]["to"].number, 16);
    EXPECT_EQ(js["resample"]["interp"].string, "tetrahedral");
    EXPECT_GT(js["resample"]["error"]["max"].number, 0.0);
    EXPECT_EQ(js["output"]["size"].number, 16);
    EXPECT_LE(js["storage"]["max"].number, 0.5 / 255 + 1e-6);
}

TEST(CliConvert, TextReportNamesBothErrors) {
    const std::string dir = workDir();
    const auto r = runCli("convert " + shellQuoted(samplePath("sample_grade.cube")) + " " +
                          shellQuoted(dir + "/x.cube") + " --size 9");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("resample 33^3 -> 9^3 (tetrahedral): max"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("8-bit steps"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("storage"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" ms"), std::string::npos) << r.out;
}

TEST(CliConvert, RefusesToOverwriteTheInput) {
    const std::string dir = workDir();
    const std::string in = dir + "/in.cube";
    fs::copy_file(samplePath("sample_grade.cube"), in);
    const std::string before = fileBytes(in);

    auto r = runCli("convert " + shellQuoted(in) + " " + shellQuoted(in));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("refusing to overwrite"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(in), std::string::npos) << r.err;

    r = runCli("convert " + shellQuoted(in) + " " + shellQuoted(dir + "/./in.cube"));
    EXPECT_EQ(r.exitCode, 1) << r.err;

    const std::string link = dir + "/link.cube";
    ASSERT_EQ(::link(in.c_str(), link.c_str()), 0);
    r = runCli("convert " + shellQuoted(in) + " " + shellQuoted(link));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("refusing to overwrite"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;

    EXPECT_EQ(fileBytes(in), before);
}

TEST(CliConvert, BadUsageExitsTwo) {
    const std::string dir = workDir();
    const std::string in = shellQuoted(samplePath("sample_grade.cube"));
    const std::string out = shellQuoted(dir + "/o.cube");
    EXPECT_EQ(runCli("convert").exitCode, 2);
    EXPECT_EQ(runCli("convert " + in).exitCode, 2);
    EXPECT_EQ(runCli("convert " + in + " " + out + " --size 1").exitCode, 2);
    EXPECT_EQ(runCli("convert " + in + " " + out + " --size 257").exitCode, 2);
    EXPECT_EQ(runCli("convert " + in + " " + out + " --interp cubic").exitCode, 2);
    EXPECT_EQ(runCli("convert " + in + " " + out + " --bit-depth 12").exitCode, 2);
    EXPECT_EQ(runCli("convert " + in + " " + out + " --no-such-option").exitCode, 2);
    EXPECT_EQ(runCli("convert " + in + " " + out + " --format no-such-format").exitCode, 2);
    EXPECT_EQ(runCli("convert " + in + " " + out + " --in-format no-such-format").exitCode, 2);
    EXPECT_FALSE(fs::exists(dir + "/o.cube"));
}

TEST(CliConvert, BadInputExitsOneNamingTheFile) {
    const std::string dir = workDir();
    const auto r = runCli("convert " + shellQuoted(dir + "/missing.cube") + " " +
                          shellQuoted(dir + "/o.cube"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("missing.cube"), std::string::npos) << r.err;
    const auto r2 = runCli("convert " + shellQuoted(samplePath("sample_grade.cube")) + " " +
                           shellQuoted(dir + "/o.unknownext"));
    EXPECT_EQ(r2.exitCode, 1);
    EXPECT_NE(r2.err.find("o.unknownext"), std::string::npos) << r2.err;
}

TEST(CliConvert, ThroughOcioFormatsAndBack) {
    const std::string dir = workDir();
    // cube -> .3dl (12-bit) -> cube: the report's storage error is the 12-bit rounding.
    auto r = runCli("convert " + shellQuoted(samplePath("sample_grade.cube")) + " " +
                    shellQuoted(dir + "/g.3dl") + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto js = lut::test::json::parse(r.out);
    EXPECT_EQ(js["output_format"].string, "flame");
    EXPECT_GT(js["storage"]["max"].number, 0.0);
    EXPECT_LE(js["storage"]["max"].number, 0.5 / 4095 + 1e-6);
    r = runCli("convert " + shellQuoted(dir + "/g.3dl") + " " + shellQuoted(dir + "/back.cube") +
               " --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    js = lut::test::json::parse(r.out);
    EXPECT_EQ(js["input"]["format"].string, "ocio");
    EXPECT_EQ(js["input"]["bit_depth"].number, 12);
    const lut::Lut3D a = readCube(samplePath("sample_grade.cube"));
    const lut::Lut3D b = readCube(dir + "/back.cube");
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.entryCount(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(a.entries()[i][c], b.entries()[i][c], 0.5 / 4095 + 1e-6);
}
