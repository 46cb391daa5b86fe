// SPDX-License-Identifier: Apache-2.0
// lutkit match end to end: the sample scene graded by a formula written here (channel mix,
// curves, saturation), the graded pixels flipped and shuffled, matched; the written .cube is
// evaluated by OpenColorIO's processor (the oracle), never by lutkit, and must land near the
// truly graded scene (issue 23: mean 1.0, p99 8 8-bit steps). Then the command's rules: -y, bad
// usage, masks, the report picture, the game's LUT.
#include "OcioTestUtil.h"
#include "TestSupport.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <random>

namespace fs = std::filesystem;
using namespace lut::test;
using ::testing::HasSubstr;

namespace {

using lut::test::shellQuoted;

double q8(double v) {
    return std::round(std::clamp(v, 0.0, 1.0) * 255.0) / 255.0;
}

// The look: channel mix, a lift and gamma on red, an S-curve on green, a gain on blue, then
// saturation 1.25 about Rec.709 luma.
glm::dvec3 grade(glm::dvec3 in) {
    const double m[3][3] = {{0.86, 0.10, 0.04}, {0.06, 0.84, 0.10}, {0.02, 0.14, 0.84}};
    double x[3], c[3];
    for (int i = 0; i < 3; ++i)
        x[i] = m[i][0] * in.x + m[i][1] * in.y + m[i][2] * in.z;
    c[0] = 0.04 + 0.96 * std::pow(std::max(x[0], 0.0), 0.85);
    c[1] = 0.5 + 0.5 * std::tanh(2.4 * (x[1] - 0.5)) / std::tanh(1.2);
    c[2] = 0.92 * x[2] + 0.02;
    const double luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    return {luma + 1.25 * (c[0] - luma), luma + 1.25 * (c[1] - luma), luma + 1.25 * (c[2] - luma)};
}

struct Scene {
    std::string dir, source, reference;
    lut::Image scene, truth;
};

const Scene& scene() {
    static const Scene s = [] {
        Scene out;
        out.dir = tempDir() + "-match";
        fs::remove_all(out.dir);
        fs::create_directories(out.dir);
        out.source = samplePath("sample_scene.png");
        out.scene = lut::formats::readImage(out.source).image;
        const int w = out.scene.width(), h = out.scene.height();
        out.truth = lut::Image(w, h, 1.0f);
        for (int i = 0; i < w * h; ++i) {
            const float* p = out.scene.data() + 4 * i;
            const glm::dvec3 g = grade(glm::dvec3(p[0], p[1], p[2]));
            for (int c = 0; c < 3; ++c)
                out.truth.data()[4 * i + c] = static_cast<float>(q8(g[c]));
        }
        std::vector<int> order(static_cast<std::size_t>(w * h));
        std::iota(order.begin(), order.end(), 0);
        std::shuffle(order.begin(), order.end(), std::mt19937(7));
        lut::Image ref(w, h, 1.0f);
        for (int i = 0; i < w * h; ++i)
            for (int c = 0; c < 3; ++c) // flipped (w*h-1-k) and shuffled
                ref.data()[4 * i + c] = out.truth.data()[4 * (w * h - 1 - order[i]) + c];
        out.reference = out.dir + "/reference.png";
        lut::formats::writeImage(out.reference, ref,
                                 lut::formats::ImageWriteOptions(8, false, false));
        return out;
    }();
    return s;
}

} // namespace

TEST(CliMatch, TheLutOpenColorIOReadsLandsOnTheTrueGrade) {
    const Scene& s = scene();
    const std::string out = s.dir + "/look.cube";
    const auto r = runCli("match " + shellQuoted(s.source) + " " + shellQuoted(s.reference) + " " +
                          shellQuoted(out) + " -y --json");
    ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
    EXPECT_THAT(r.out, HasSubstr("\"method\": "));
    const auto p = ocioFileProcessor(out);
    std::vector<double> steps;
    for (int i = 0; i < s.scene.width() * s.scene.height(); ++i) {
        const float* in = s.scene.data() + 4 * i;
        const glm::vec3 v = ocioEval(p, glm::vec3(in[0], in[1], in[2]));
        for (int c = 0; c < 3; ++c)
            steps.push_back(std::fabs(q8(v[c]) - s.truth.data()[4 * i + c]) * 255.0);
    }
    const double mean = std::accumulate(steps.begin(), steps.end(), 0.0) / steps.size();
    std::sort(steps.begin(), steps.end());
    const double p99 = steps[static_cast<std::size_t>(0.99 * (steps.size() - 1))];
    EXPECT_LE(mean, 1.0);
    EXPECT_LE(p99, 8.0);
    RecordProperty("mean_steps", std::to_string(mean));
    RecordProperty("p99_steps", std::to_string(p99));
}

TEST(CliMatch, OutputRulesAndBadUsage) {
    const Scene& s = scene();
    const std::string out = s.dir + "/rules.cube";
    ASSERT_EQ(runCli("match " + shellQuoted(s.source) + " " + shellQuoted(s.reference) + " " +
                     shellQuoted(out) + " --method hm -q")
                  .exitCode,
              0);
    const auto before = fs::last_write_time(out);
    auto r = runCli("match " + shellQuoted(s.source) + " " + shellQuoted(s.reference) + " " +
                    shellQuoted(out));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("-y"));
    EXPECT_EQ(fs::last_write_time(out), before);
    r = runCli("match " + shellQuoted(s.source) + " " + shellQuoted(s.reference) + " " +
               shellQuoted(out) + " -y --method hmm");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("did you mean 'hm'"));
    r = runCli("match " + shellQuoted(s.source) + " " + shellQuoted(out));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("REFERENCE"));
    r = runCli("match " + shellQuoted(s.source) + " " + shellQuoted(s.reference) + " " +
               shellQuoted(out) + " -y --strength 3");
    EXPECT_EQ(r.exitCode, 2);
    // the output may not be an input
    r = runCli("match " + shellQuoted(s.source) + " " + shellQuoted(s.reference) + " " +
               shellQuoted(s.reference) + " -y");
    EXPECT_EQ(r.exitCode, 1);
}

TEST(CliMatch, AMaskOfAnotherSizeIsNamed) {
    const Scene& s = scene();
    const std::string mask = s.dir + "/small-mask.png";
    lut::formats::writeImage(mask, lut::Image(10, 10, 1.0f), lut::formats::ImageWriteOptions(8));
    const auto r =
        runCli("match " + shellQuoted(s.source) + " " + shellQuoted(s.reference) + " " +
               shellQuoted(s.dir + "/masked.cube") + " -y --mask-source " + shellQuoted(mask));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("sample_scene.png: the mask is 10x10"));
}

TEST(CliMatch, AMaskLeavesPixelsOut) {
    // Every pixel masked but the top rows (the sky): the match only sees sky, so the report
    // counts those rows only.
    const Scene& s = scene();
    const int w = s.scene.width(), h = s.scene.height();
    lut::Image mask(w, h, 0.0f);
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < w; ++x)
            std::fill(mask.pixel(x, y), mask.pixel(x, y) + 4, 1.0f);
    const std::string path = s.dir + "/sky-mask.png";
    lut::formats::writeImage(path, mask, lut::formats::ImageWriteOptions(8));
    const auto r =
        runCli("match " + shellQuoted(s.source) + " " + shellQuoted(s.reference) + " " +
               shellQuoted(s.dir + "/sky.cube") + " -y --json --mask-source " + shellQuoted(path));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("\"source_counted\": " + std::to_string(20 * w)));
}

TEST(CliMatch, ReportPictureAndTheGamesLut) {
    const Scene& s = scene();
    const std::string png = s.dir + "/report.png", game = s.dir + "/color_grading_lut.nutexb";
    const auto r =
        runCli("match " + shellQuoted(s.source) + " " + shellQuoted(s.reference) + " " +
               shellQuoted(game) + " -y --method hm-mkl-hm --report-image " + shellQuoted(png));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("in game"));
    const auto pic = lut::formats::readImage(png);
    EXPECT_EQ(pic.image.width(), 3 * 480 + 4 * 16);
    const lut::LutFile f = lut::formats::readLut(game);
    ASSERT_TRUE(f.cube.has_value());
    EXPECT_EQ(f.cube->size(), 16);
}

TEST(CliMatch, EachCandidateSaysWhyItIsNotEligibleAndTheFigureHolds) {
    // A reference of two flat colours: auto's closer candidates make LUTs that go down along grey
    // (or fold). For every candidate, its own LUT (written with --method, in the form auto
    // judged: the shaper and the table) is read by OpenColorIO and its largest drop along grey
    // measured at 4097 points: a candidate said to go down by X steps does (within a tenth), and
    // one said to be eligible goes down by no more than the quarter step auto allows (between
    // the points the report sampled too), except HM-MKL-HM, the floor, eligible with a drop
    // along grey, reported (issue 42), and the gradient map, a colour per luma by design.
    const std::string dir = tempDir() + "-eligible";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const int w = 320, h = 200;
    lut::Image src(w, h, 1.0f), ref(w, h, 1.0f);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> noise(0.0, 0.05);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double u = x / (w - 1.0), v = y / (h - 1.0);
            const double c[3] = {0.1 + 0.8 * u - 0.1 * v, 0.2 + 0.2 * u + 0.6 * v,
                                 0.3 - 0.2 * u + 0.3 * v};
            const bool first = ((x / 16) + (y / 16)) % 2 == 0;
            const double r[3] = {first ? 0.9 : 0.1, first ? 0.3 : 0.2, first ? 0.1 : 0.7};
            for (int k = 0; k < 3; ++k) {
                src.pixel(x, y)[k] = static_cast<float>(q8(c[k] + noise(rng)));
                ref.pixel(x, y)[k] = static_cast<float>(q8(r[k]));
            }
        }
    const std::string s = dir + "/source.png", rf = dir + "/two-colours.png";
    lut::formats::writeImage(s, src, lut::formats::ImageWriteOptions(8, false, false));
    lut::formats::writeImage(rf, ref, lut::formats::ImageWriteOptions(8, false, false));
    const auto r = runCli("match " + shellQuoted(s) + " " + shellQuoted(rf) + " " +
                          shellQuoted(dir + "/auto.cube") + " -y --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    int notEligible = 0, checked = 0, candidates = 0;
    for (const char* m : {"hm", "mkl", "hm-mkl-hm", "regularised", "gradient-map"}) {
        const std::string key = std::string("{\"method\": \"") + m + "\"";
        const auto at = r.out.find(key);
        if (std::string(m) == "regularised" || std::string(m) == "gradient-map") {
            if (at == std::string::npos) // regularised is not tried on a look with steps
                continue;
        } else {
            ASSERT_NE(at, std::string::npos) << m << "\n" << r.out;
        }
        ++candidates;
        const bool floor = std::string(m) == "hm-mkl-hm";
        const std::string entry =
            r.out.substr(at, r.out.find('}', r.out.find("shape_problem", at)) - at);
        const bool eligible = entry.find("\"eligible\": true") != std::string::npos;
        const auto grey = entry.find("goes down along grey by ");
        double said = 0.0;
        if (grey != std::string::npos)
            said = std::stod(entry.substr(grey + std::strlen("goes down along grey by ")));
        notEligible += eligible ? 0 : 1;

        const std::string lutPath = dir + "/" + m + ".cube";
        ASSERT_EQ(runCli("match " + shellQuoted(s) + " " + shellQuoted(rf) + " " +
                         shellQuoted(lutPath) + " -y -q --lut-form shaper --method " + m)
                      .exitCode,
                  0);
        if (std::string(m) == "gradient-map")
            continue;
        const auto p = ocioFileProcessor(lutPath);
        double drop = 0.0;
        glm::dvec3 peak(-INFINITY);
        for (int i = 0; i <= 4096; ++i) {
            const float t = static_cast<float>(i / 4096.0);
            const glm::vec3 o = ocioEval(p, glm::vec3(t));
            for (int c = 0; c < 3; ++c) {
                peak[c] = std::max(peak[c], static_cast<double>(o[c]));
                drop = std::max(drop, (peak[c] - o[c]) * 255.0);
            }
        }
        if (grey != std::string::npos) {
            // the floor is eligible with a dip along grey and nothing else
            EXPECT_EQ(eligible, floor && entry.find("folds") == std::string::npos &&
                                    entry.find("channel's own axis") == std::string::npos)
                << m << ": " << entry;
            // A table written alone has its dip along grey repaired (issue 42: the diagonal put
            // in order); with a shaper, grey is off the diagonal and the figure holds as said.
            if (fileBytes(lutPath).find("LUT_1D_SIZE") == std::string::npos)
                EXPECT_LE(drop, 1e-3) << m << ": " << entry;
            else
                EXPECT_NEAR(drop, said, std::max(0.1, 0.01 * said)) << m << ": " << entry;
            ++checked;
        } else {
            EXPECT_LE(drop, 0.25 + 0.05) << m << ": " << entry;
        }
    }
    EXPECT_GE(notEligible, 1) << r.out;
    EXPECT_GE(checked, 1) << r.out;
    EXPECT_GE(candidates, 4) << r.out;
}

// Issue 42: the default .cube (Resolve's form: a 1D shaper, then the 3D table) is refused by
// ffmpeg's lut3d ("Invalid data found") and nothing said so. Now a warning names the form that
// every tool reads, and --format iridas_cube writes it: ffmpeg, the oracle here, applies it.
TEST(CliMatch, TheCubeFormEveryToolReadsIsNamedAndWritten) {
    if (!haveProgram("ffmpeg"))
        GTEST_SKIP() << "ffmpeg is not installed";
    const Scene& s = scene();
    const std::string resolve = s.dir + "/resolve.cube", iridas = s.dir + "/iridas.cube";
    const auto r = runCli("match " + shellQuoted(s.source) + " " + shellQuoted(s.reference) + " " +
                          shellQuoted(resolve) + " -y --method hm-mkl-hm --lut-form shaper");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_THAT(fileBytes(resolve), HasSubstr("LUT_1D_SIZE")) << "the shaper form, as asked";
    const auto ffmpeg = [&](const std::string& cube) {
        return runCommand("ffmpeg -v error -nostdin -y -i " + shellQuoted(s.source) +
                          " -vf lut3d=file=" + shellQuoted(cube) + " -frames:v 1 " +
                          shellQuoted(s.dir + "/ff.png"));
    };
    EXPECT_NE(ffmpeg(resolve).exitCode, 0)
        << "ffmpeg now reads the shaper form: the warning can go";
    const auto w = runCli("match " + shellQuoted(s.source) + " " + shellQuoted(s.reference) + " " +
                          shellQuoted(iridas) + " -y --method hm-mkl-hm --format iridas_cube");
    ASSERT_EQ(w.exitCode, 0) << w.err;
    EXPECT_THAT(w.out + w.err, ::testing::Not(HasSubstr("--format iridas_cube")));
    EXPECT_THAT(fileBytes(iridas), ::testing::Not(HasSubstr("LUT_1D_SIZE")));
    const auto f = ffmpeg(iridas);
    EXPECT_EQ(f.exitCode, 0) << f.err;
}
