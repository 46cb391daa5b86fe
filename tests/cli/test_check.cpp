// SPDX-License-Identifier: Apache-2.0
// lutkit check, lutkit chart and the quiet check after writing a LUT, run as users run them: exit
// codes, the figures against formulas written here, the JSON read by Python's json module (an
// independent parser), the pictures read back, and the output rules (-y, a folder for several).
#include "CliTestSupport.h"

#include "lut/Image.h"
#include "lut/formats/ImageIO.h"

#include <glm/vec3.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>

namespace fs = std::filesystem;
using namespace lut::test;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {

using lut::test::shellQuoted;

using Fn = std::function<glm::vec3(glm::vec3)>;

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

// Red folds back near the red axis (as tests/ops' fold-over LUT): 20.4 8-bit steps at g = b = 0.
glm::vec3 fold(glm::vec3 x) {
    return {static_cast<float>(x.r - 0.25 * (1 - x.g) * (1 - x.b) * smoothstep(0.45, 0.65, x.r)),
            x.g, x.b};
}
// Red held at 1 above r = 0.95: 5% of the cube.
glm::vec3 clip(glm::vec3 x) {
    return {std::min(1.0f, x.r / 0.95f), x.g, x.b};
}
glm::vec3 same(glm::vec3 x) {
    return x;
}

// Python's json module reads `json` and prints what `expression` (over d, the document) gives
// (a tuple: its items separated by spaces).
std::string python(const std::string& dir, const std::string& json, const std::string& expression) {
    const std::string in = dir + "/report.json", script = dir + "/read.py",
                      out = dir + "/python.txt";
    std::ofstream(in) << json;
    std::ofstream(script) << "import json, sys\n"
                             "d = json.load(open(sys.argv[1]))\n"
                             "v = ("
                          << expression
                          << ")\n"
                             "print(' '.join(map(str, v)) if isinstance(v, tuple) else v)\n";
    const std::string cmd = "python3 " + shellQuoted(script) + " " + shellQuoted(in) + " > " +
                            shellQuoted(out) + " 2>&1";
    const int rc = std::system(cmd.c_str());
    std::ifstream f(out);
    std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    EXPECT_EQ(rc, 0) << text;
    while (!text.empty() && text.back() == '\n')
        text.pop_back();
    return text;
}

} // namespace

TEST(CliCheck, FailsOnAFoldOverAndSaysWhere) {
    const std::string dir = workDir();
    const std::string lut = writeCube(dir + "/fold.cube", 33, fold);
    RunResult r = runCli("check " + shellQuoted(lut));
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_THAT(r.out, HasSubstr(lut + ": fail"));
    EXPECT_THAT(r.out, HasSubstr("monotonicity   fail"));
    EXPECT_THAT(r.out, HasSubstr("1 fail fold-over"));
    EXPECT_THAT(r.out, HasSubstr("along red"));
    // The same as JSON, read by Python.
    r = runCli("check " + shellQuoted(lut) + " --json");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(python(dir, r.out, "d['status'], d['files'][0]['status']"), "fail fail");
    EXPECT_EQ(python(dir, r.out, "d['files'][0]['findings'][0]['kind']"), "fold-over");
    // The formula's fold at g = b = 0, from its peak to its trough, in float64.
    double peak = -1, drop = 0;
    for (int i = 0; i <= 100000; ++i) {
        const double v = fold({float(i / 100000.0), 0, 0}).x;
        peak = std::max(peak, v);
        drop = std::max(drop, peak - v);
    }
    const double size = std::stod(python(dir, r.out, "d['files'][0]['findings'][0]['size']"));
    EXPECT_NEAR(size, 255 * drop, 0.1 * 255 * drop);
    const double red = std::stod(python(dir, r.out, "d['files'][0]['findings'][0]['input'][0]"));
    EXPECT_NEAR(red, 0.55, 1.0 / 32);
    EXPECT_EQ(python(dir, r.out, "d['files'][0]['figures']['grey_worst_fold_over']"), "0");
    // -q: nothing but warnings and errors: the failed verdict, one line on stderr.
    r = runCli("check -q " + shellQuoted(lut));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_THAT(r.err, HasSubstr("lutkit: error: " + lut + ": fail ("));
}

TEST(CliCheck, WarningsPassUnlessStrict) {
    const std::string dir = workDir();
    const std::string lut = writeCube(dir + "/clip.cube", 33, clip);
    RunResult r = runCli("check " + shellQuoted(lut) + " --json");
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_EQ(python(dir, r.out, "d['files'][0]['status']"), "warn");
    const double share =
        std::stod(python(dir, r.out, "d['files'][0]['figures']['clipped_share'][0]"));
    EXPECT_NEAR(share, 0.05, 0.005); // r above 0.95
    EXPECT_EQ(python(dir, r.out,
                     "[c['status'] for c in d['files'][0]['checks'] if "
                     "c['check']=='range'][0]"),
              "warn");
    r = runCli("check --strict " + shellQuoted(lut));
    EXPECT_EQ(r.exitCode, 1);
    const std::string neutral = writeCube(dir + "/neutral.cube", 17, same);
    r = runCli("check --strict " + shellQuoted(neutral));
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_THAT(r.out, HasSubstr(": pass (3D 17^3, 0 findings"));
}

TEST(CliCheck, ReportPictureFollowsTheOutputRules) {
    const std::string dir = workDir();
    const std::string a = writeCube(dir + "/a.cube", 17, fold);
    const std::string b = writeCube(dir + "/b.cube", 17, same);
    RunResult r = runCli("check " + shellQuoted(a) + " --report " + shellQuoted(dir + "/a.png"));
    EXPECT_EQ(r.exitCode, 1);
    const lut::formats::LoadedImage pic = lut::formats::readImage(dir + "/a.png");
    EXPECT_EQ(pic.image.width(), 1600);
    EXPECT_GT(pic.image.height(), 900);
    EXPECT_THAT(r.out, HasSubstr("wrote " + dir + "/a.png"));
    // It exists: refused without -y (the check still runs), replaced with -y.
    const auto before = fs::last_write_time(dir + "/a.png");
    r = runCli("check " + shellQuoted(a) + " --report " + shellQuoted(dir + "/a.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("already exists; pass -y/--overwrite"));
    EXPECT_EQ(fs::last_write_time(dir + "/a.png"), before);
    r = runCli("check " + shellQuoted(b) + " --report " + shellQuoted(dir + "/a.png") + " -y");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    // Several LUTs: a folder, one picture each.
    r = runCli("check " + shellQuoted(a) + " " + shellQuoted(b) + " --report " +
               shellQuoted(dir + "/pics/"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(fs::exists(dir + "/pics/a.check.png"));
    EXPECT_TRUE(fs::exists(dir + "/pics/b.check.png"));
    r = runCli("check " + shellQuoted(a) + " " + shellQuoted(b) + " --report " +
               shellQuoted(dir + "/one.png"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("name a folder"));
}

TEST(CliCheck, BadFilesAndThresholds) {
    const std::string dir = workDir();
    const std::string good = writeCube(dir + "/good.cube", 9, same);
    std::ofstream(dir + "/bad.cube") << "LUT_3D_SIZE 2\n0 0 0\n";
    RunResult r = runCli("check " + shellQuoted(dir + "/bad.cube") + " " + shellQuoted(good));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("bad.cube"));
    EXPECT_THAT(r.out, HasSubstr(good + ": pass")); // the other file is still checked
    std::ofstream(dir + "/t.txt") << "# stricter\nsteep = 0.5 0.9\nfoldover = 1 2\n";
    r = runCli("check " + shellQuoted(good) + " --thresholds " + shellQuoted(dir + "/t.txt"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("t.txt:3:1: unknown threshold 'foldover'; did you mean "
                                 "'fold-over'?"));
    std::ofstream(dir + "/t.txt") << "steep = 0.5 0.9\n";
    r = runCli("check " + shellQuoted(good) + " --thresholds " + shellQuoted(dir + "/t.txt"));
    EXPECT_EQ(r.exitCode, 1) << r.out; // the identity's slope 1 now fails
    EXPECT_THAT(r.out, HasSubstr("banding        fail"));
    EXPECT_EQ(runCli("check").exitCode, 2);
    EXPECT_EQ(runCli("check " + shellQuoted(good) + " --format cube").exitCode, 2);
}

TEST(CliCheck, OverAPicture) {
    const std::string dir = workDir();
    const std::string lut = writeCube(dir + "/fold.cube", 17, fold);
    // Greys only: the fold near the red axis is not in this picture.
    lut::Image shot(64, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 64; ++x) {
            float* p = shot.pixel(x, y);
            p[0] = p[1] = p[2] = x / 63.0f;
            p[3] = 1.0f;
        }
    lut::formats::ImageWriteOptions w;
    w.alpha = false;
    w.bitDepth = 8;
    lut::formats::writeImage(dir + "/greys.png", shot, w);
    RunResult r = runCli("check " + shellQuoted(lut) + " --image " +
                         shellQuoted(dir + "/greys.png") + " --json");
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_EQ(python(dir, r.out, "d['files'][0]['over'], len(d['files'][0]['findings'])"),
              "picture 0");
}

TEST(CliChart, WritesTheCharts) {
    const std::string dir = workDir();
    RunResult r = runCli("chart hue-saturation " + shellQuoted(dir + "/hs.png") +
                         " --width 361 --height 101");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const lut::formats::LoadedImage img = lut::formats::readImage(dir + "/hs.png");
    ASSERT_EQ(img.image.width(), 361);
    ASSERT_EQ(img.image.height(), 101);
    // HSV hue = column, saturation = 1 - row, value 1 (16-bit PNG: within half a 16-bit step).
    for (int y = 0; y < 101; y += 25)
        for (int x = 0; x < 361; x += 30) {
            const double h = x, s = 1.0 - y / 100.0;
            auto f = [&](double n) {
                const double k = std::fmod(n + h / 60.0, 6.0);
                return 1.0 - s * std::max(0.0, std::min({k, 4.0 - k, 1.0}));
            };
            const double want[3] = {f(5), f(3), f(1)};
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(img.image.pixel(x, y)[c], want[c], 0.6 / 65535) << x << "," << y;
        }
    r = runCli("chart all " + shellQuoted(dir + "/all.png") + " --bit-depth 8");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(lut::formats::readImage(dir + "/all.png").image.width(), 1024);
    r = runCli("chart all " + shellQuoted(dir + "/all.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("already exists"));
    r = runCli("chart hue-sat " + shellQuoted(dir + "/x.png"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("did you mean 'hue-saturation'"));
}

TEST(CliCheck, QuietCheckAfterWritingALut) {
    const std::string dir = workDir();
    const std::string folded = writeCube(dir + "/fold.cube", 17, fold);
    const std::string neutral = writeCube(dir + "/neutral.cube", 17, same);
    RunResult r = runCli("compose " + shellQuoted(folded) + " " + shellQuoted(neutral) + " " +
                         shellQuoted(dir + "/c.cube"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr("warning: " + dir +
                                 "/c.cube: check monotonicity fails: "
                                 "fold-over"));
    EXPECT_THAT(r.err, HasSubstr("lutkit check " + dir + "/c.cube --report"));
    r = runCli("convert " + shellQuoted(folded) + " " + shellQuoted(dir + "/c.3dl"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr("check monotonicity fails"));
    // A game LUT is judged by what the game shows with it, not by its compensated numbers: the
    // neutral one passes, the folded one fails the same way.
    r = runCli("convert " + shellQuoted(neutral) + " " + shellQuoted(dir + "/n.nutexb"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.err, Not(HasSubstr("check")));
    r = runCli("convert " + shellQuoted(folded) + " " + shellQuoted(dir + "/f.nutexb"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr("check monotonicity of the edit the game shows fails"));
    r = runCli("check " + shellQuoted(dir + "/n.nutexb"));
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_THAT(r.out, HasSubstr("checked as the edit the game shows"));
    // -q is nothing but warnings and errors: the failing check is a warning and stays.
    r = runCli("compose -q " + shellQuoted(folded) + " " + shellQuoted(neutral) + " " +
               shellQuoted(dir + "/q.cube"));
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out, "");
    EXPECT_THAT(r.err, HasSubstr("lutkit: warning: " + dir + "/q.cube: check monotonicity fails"));
    r = runCli("compose " + shellQuoted(neutral) + " " + shellQuoted(neutral) + " " +
               shellQuoted(dir + "/n.cube"));
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.err, "");
    r = runCli("invert " + shellQuoted(neutral) + " " + shellQuoted(dir + "/i.cube"));
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.err, "");
}
