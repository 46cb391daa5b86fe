// SPDX-License-Identifier: Apache-2.0
// lutkit bake: side by side with ociobakelut (the installed peer) on the same files and config,
// the report's error checked against an independent measurement, lutkit's own config found
// without $OCIO, $OCIO and --config obeyed, looks and display views equal to OpenColorIO's
// processors, bad names refused as bad usage, and --cccid applying to the files after it.
#include "CliTableSupport.h"
#include "CliTestSupport.h"
#include "OcioTestUtil.h"
#include "TestPaths.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace fs = std::filesystem;
using namespace lut::test;
using ::testing::HasSubstr;

namespace {

using lut::test::shellQuoted;

std::string shippedConfig() {
    return std::string(LUTKIT_BINARY_DIR) + "/share/lutkit/ocio/config.ocio";
}

std::string testConfig() {
    return dataPath("ocio/test_config.ocio");
}

bool haveOciobakelut() {
    return std::system("command -v ociobakelut >/dev/null 2>&1") == 0;
}

int sh(const std::string& cmd) {
    return std::system((cmd + " >/dev/null 2>&1").c_str());
}

// Compares OCIO's evaluation of two files at the n^3 lattice points of [0,1] (the entries of a
// file baked over [0,1] at that size). Returns the largest |a - b| / max(1, |b|).
double worstRelative(const std::string& a, const std::string& b, int n) {
    const auto pa = ocioFileProcessor(a), pb = ocioFileProcessor(b);
    double worst = 0.0;
    for (int bb = 0; bb < n; ++bb)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 x = glm::vec3(r, g, bb) / float(n - 1);
                const glm::vec3 va = ocioEval(pa, x), vb = ocioEval(pb, x);
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::fabs(double(va[c]) - vb[c]) /
                                                std::max(1.0, std::fabs(double(vb[c]))));
            }
    return worst;
}

// A number after "key": in lutkit's JSON.
double jsonNumber(const std::string& text, const std::string& key, std::size_t from = 0) {
    const auto k = text.find("\"" + key + "\": ", from);
    EXPECT_NE(k, std::string::npos) << key << " in " << text;
    return k == std::string::npos ? NAN : std::stod(text.substr(k + key.size() + 4));
}

TEST(Bake, SameAsOciobakelutOnChainsAtTheCubeSizeAskedFor) {
    if (!haveOciobakelut())
        GTEST_SKIP() << "ociobakelut is not installed";
    const std::string dir = workDir();
    // The files: convert --size 33 differed from ociobakelut --cubesize 33 by up to 1.0.
    for (const char* name : {"clf/multiple_ops.clf", "nuke_3d.vf", "clf/lut1d_lut3d_lut1d.clf",
                             "clf/illegal/unknown_elements.clf"}) {
        SCOPED_TRACE(name);
        const std::string src = corpusPath(name);
        const std::string theirs = dir + "/ocio.cube", converted = dir + "/conv.cube",
                          baked = dir + "/bake.cube";
        ASSERT_EQ(sh("ociobakelut --lut " + shellQuoted(src) +
                     " --format resolve_cube --cubesize 33 " + shellQuoted(theirs)),
                  0);
        auto r =
            runCli("convert -y " + shellQuoted(src) + " " + shellQuoted(converted) + " --size 33");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        r = runCli("bake -y --lut " + shellQuoted(src) + " --format resolve_cube --cubesize 33 " +
                   shellQuoted(baked));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        // ociobakelut prints 6 decimals: 5e-7 of rounding.
        EXPECT_LE(worstRelative(converted, theirs, 33), 2e-6);
        EXPECT_LE(worstRelative(baked, theirs, 33), 2e-6);
    }
}

TEST(Bake, SameAsOciobakelutWithAConfig) {
    if (!haveOciobakelut())
        GTEST_SKIP() << "ociobakelut is not installed";
    const std::string dir = workDir();
    const std::string cfg = shippedConfig();
    for (const char* fmt : {"resolve_cube", "flame"}) {
        SCOPED_TRACE(fmt);
        const std::string ext = std::string(fmt) == "flame" ? ".3dl" : ".cube";
        const std::string theirs = dir + "/ocio" + ext, ours = dir + "/ours" + ext;
        ASSERT_EQ(sh("ociobakelut --iconfig " + shellQuoted(cfg) +
                     " --inputspace ACEScct --outputspace Rec.709 --format " + fmt +
                     " --cubesize 17 " + shellQuoted(theirs)),
                  0);
        const auto r = runCli("bake --config " + shellQuoted(cfg) +
                              " --inputspace ACEScct --outputspace Rec.709 --format " + fmt +
                              " --cubesize 17 " + shellQuoted(ours));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        // .3dl: 12-bit integers, rounded alike but for ties: one code at most.
        EXPECT_LE(worstRelative(ours, theirs, 17), ext == ".3dl" ? 1.0 / 4095 + 1e-6 : 2e-6);
    }
}

TEST(Bake, ReportedErrorBoundsTheFileAgainstTheProcessor) {
    // The reported maximum bounds |file - processor| over every input of the table's domain:
    // measured here on 100,000 random inputs with OCIO reading the written file and the source.
    const std::string dir = workDir();
    const std::string src = corpusPath("clf/multiple_ops.clf"), out = dir + "/m.cube";
    const auto r =
        runCli("bake --lut " + shellQuoted(src) + " --cubesize 9 --json " + shellQuoted(out));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto e = r.out.find("\"error\": ");
    const double reportedMax = jsonNumber(r.out, "max", e);
    const double reportedMean = jsonNumber(r.out, "mean", e);
    const auto ps = ocioFileProcessor(src), pw = ocioFileProcessor(out);
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    double max = 0.0, sum = 0.0;
    int count = 0;
    for (int i = 0; i < 100000; ++i) {
        const glm::vec3 x(u(rng), u(rng), u(rng));
        const glm::vec3 a = ocioEval(pw, x), want = ocioEval(ps, x);
        for (int c = 0; c < 3; ++c) {
            max = std::max(max, std::fabs(double(a[c]) - want[c]));
            sum += std::fabs(double(a[c]) - want[c]);
            ++count;
        }
    }
    EXPECT_GT(max, 1e-3); // a 9^3 table cannot hold this chain: the check below can fail
    EXPECT_GE(reportedMax, max);
    EXPECT_LE(reportedMax, 1.5 * max);
    EXPECT_NEAR(reportedMean, sum / count, 0.1 * sum / count);
}

TEST(Bake, UsesLutkitsOwnConfigWithoutOcio) {
    const std::string dir = workDir();
    // runCli runs through a shell: unset $OCIO for this one run.
    const std::string out = dir + "/a.cube";
    const std::string cmd = std::string("env -u OCIO '") + LUTKIT_CLI +
                            "' bake --inputspace ACEScg --outputspace sRGB --json " +
                            shellQuoted(out) + " > " + shellQuoted(dir + "/report.json");
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    std::stringstream ss;
    ss << std::ifstream(dir + "/report.json").rdbuf();
    const std::string report = ss.str();
    EXPECT_THAT(report, HasSubstr("share/lutkit/ocio/config.ocio (lutkit's own)"));
    // Scene-linear input into a .cube: a log2 shaper covering 0 .. 2^4.026.
    EXPECT_THAT(report, HasSubstr("\"shaper\": \"log2"));
    EXPECT_NEAR(jsonNumber(report, "shaper_size"), 4096, 0);
    EXPECT_NEAR(jsonNumber(report, "cube_size"), 33, 0);
    // What the file does, by OCIO: ACEScg -> sRGB of lutkit's config, within the reported error
    // (large at the edges of the gamut, where the conversion bends sharply; small on average).
    const double reported = jsonNumber(report, "max", report.find("\"error\""));
    EXPECT_LT(jsonNumber(report, "mean", report.find("\"error\"")), 0.05);
    auto cfg = OCIO::Config::CreateFromFile(shippedConfig().c_str());
    const auto truth = cfg->getProcessor("ACEScg", "sRGB")->getDefaultCPUProcessor();
    const auto file = ocioFileProcessor(out);
    for (float v : {0.0f, 0.01f, 0.18f, 1.0f, 4.0f, 12.0f}) {
        const glm::vec3 x(v, 0.5f * v, 0.25f * v);
        const glm::vec3 a = ocioEval(file, x), b = ocioEval(truth, x);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(a[c], b[c], reported + 1e-6) << v;
    }
}

TEST(Bake, OcioEnvironmentAndConfigOption) {
    const std::string dir = workDir();
    // $OCIO names the config when --config does not.
    std::string cmd = "OCIO=" + shellQuoted(testConfig()) + " '" + LUTKIT_CLI +
                      "' bake --inputspace log --outputspace gamma22 --json " +
                      shellQuoted(dir + "/a.cube") + " > " + shellQuoted(dir + "/r.json");
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    std::stringstream ss;
    ss << std::ifstream(dir + "/r.json").rdbuf();
    EXPECT_THAT(ss.str(), HasSubstr("test_config.ocio ($OCIO)"));
    // --config wins over $OCIO.
    cmd = "OCIO=/nonexistent.ocio '" + std::string(LUTKIT_CLI) + "' bake --config " +
          shellQuoted(testConfig()) + " --inputspace log --outputspace gamma22 " +
          shellQuoted(dir + "/b.cube") + " >/dev/null";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    // A missing config is bad input (1) naming the file.
    const auto r = runCli("bake --config /nonexistent.ocio --inputspace a --outputspace b " +
                          shellQuoted(dir + "/c.cube"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("/nonexistent.ocio"));
}

TEST(Bake, LooksAndDisplayViewsAreOcios) {
    const std::string dir = workDir();
    auto cfg = OCIO::Config::CreateFromFile(testConfig().c_str());
    // A look.
    auto lt = OCIO::LookTransform::Create();
    lt->setSrc("log");
    lt->setDst("gamma22");
    lt->setLooks("warm");
    const auto look = cfg->getProcessor(lt)->getDefaultCPUProcessor();
    auto r = runCli("bake --config " + shellQuoted(testConfig()) +
                    " --inputspace log --outputspace gamma22 --look warm --cubesize 17 " +
                    shellQuoted(dir + "/look.cube"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // A display's view.
    auto dv = OCIO::DisplayViewTransform::Create();
    dv->setSrc("log");
    dv->setDisplay("Monitor");
    dv->setView("Gamma");
    const auto view = cfg->getProcessor(dv)->getDefaultCPUProcessor();
    r = runCli("bake --config " + shellQuoted(testConfig()) +
               " --inputspace log --display Monitor --view Gamma --cubesize 17 " +
               shellQuoted(dir + "/view.cube"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const auto& [file, truth] :
         {std::make_pair(dir + "/look.cube", look), std::make_pair(dir + "/view.cube", view)}) {
        const auto p = ocioFileProcessor(file);
        for (int i = 0; i < 17 * 17 * 17; i += 7) {
            const glm::vec3 x = glm::vec3(i % 17, (i / 17) % 17, i / 289) / 16.0f;
            const glm::vec3 a = ocioEval(p, x), b = ocioEval(truth, x);
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(a[c], b[c], 1e-5) << file << " at " << i;
        }
    }
}

TEST(Bake, UnknownNamesAreBadUsageWithASuggestion) {
    const std::string dir = workDir();
    const std::string cfg = " --config " + shellQuoted(testConfig());
    auto r = runCli("bake" + cfg + " --inputspace lgo --outputspace gamma22 " +
                    shellQuoted(dir + "/a.cube"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("unknown colour space 'lgo'"));
    EXPECT_THAT(r.err, HasSubstr("did you mean 'log'?"));
    r = runCli("bake" + cfg + " --inputspace log --outputspace lin --look wram " +
               shellQuoted(dir + "/a.cube"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("did you mean 'warm'?"));
    r = runCli("bake" + cfg + " --inputspace log --display Monitor --view Gama " +
               shellQuoted(dir + "/a.cube"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("did you mean 'Gamma'?"));
    r = runCli("bake" + cfg + " --inputspace log --outputspace lin --display Monitor " +
               shellQuoted(dir + "/a.cube"));
    EXPECT_EQ(r.exitCode, 2);
    r = runCli("bake " + shellQuoted(dir + "/a.cube"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("nothing to bake"));
    r = runCli("bake --format nosuch --lut x.cube " + shellQuoted(dir + "/a.cube"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_FALSE(fs::exists(dir + "/a.cube"));
}

TEST(Bake, CccIdAppliesToTheFilesAfterIt) {
    lut::cli::RunHooks h = stubHooks();
    lut::cli::BakeCommandOptions seen;
    h.bake = [&seen](const lut::cli::BakeCommandOptions& o) {
        seen = o;
        return 0;
    };
    const auto r = runInProcess(
        "bake --lut a.ccc --cccid shot2 --lut b.ccc --invlut c.cdl --cccid 0 --lut d.cc out.cube",
        h);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_EQ(seen.bake.files.size(), 4u);
    EXPECT_EQ(seen.bake.files[0].path, "a.ccc");
    EXPECT_EQ(seen.bake.files[0].cccid, "");
    EXPECT_EQ(seen.bake.files[1].cccid, "shot2");
    EXPECT_FALSE(seen.bake.files[1].inverse);
    EXPECT_EQ(seen.bake.files[2].path, "c.cdl");
    EXPECT_EQ(seen.bake.files[2].cccid, "shot2");
    EXPECT_TRUE(seen.bake.files[2].inverse);
    EXPECT_EQ(seen.bake.files[3].cccid, "0");
}

TEST(Bake, CccFileNeedsAnIdAndGetsTheRightOne) {
    const std::string dir = workDir();
    const std::string src = corpusPath("cdl_test1.ccc");
    auto r = runCli("bake --lut " + shellQuoted(src) + " " + shellQuoted(dir + "/a.cube"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("--cccid"));
    r = runCli("bake --cccid cc0001 --lut " + shellQuoted(src) + " --cubesize 9 " +
               shellQuoted(dir + "/a.cube"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto truth = ocioFileProcessor(src, "cc0001"), file = ocioFileProcessor(dir + "/a.cube");
    for (int i = 0; i < 729; i += 5) {
        const glm::vec3 x = glm::vec3(i % 9, (i / 9) % 9, i / 81) / 8.0f;
        const glm::vec3 a = ocioEval(file, x), b = ocioEval(truth, x);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(a[c], b[c], 1e-5);
    }
}

} // namespace
