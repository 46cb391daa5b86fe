// SPDX-License-Identifier: Apache-2.0
// The embed / extract / fit subcommands end to end through the lutkit binary.
#include "RoundtripTestUtil.h"
#include "TestSupport.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/interp/Sampler.h"
#include "lut/roundtrip/Embed.h"
#include "lut/roundtrip/Extract.h"
#include "lut/roundtrip/PatchFinder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace lut;
using namespace lut::rt;
using lut::test::runCli;

namespace {

using lut::test::shellQuoted;

using lut::test::fileBytes;

std::string writeScreenshot(const std::string& dir, int bitDepth) {
    const std::string path = dir + "/shot" + std::to_string(bitDepth) + ".png";
    formats::ImageWriteOptions o;
    o.bitDepth = bitDepth;
    o.alpha = false;
    formats::writeImage(path, syntheticScreenshot(400, 260, bitDepth), o);
    return path;
}

std::string editFile(const std::string& in, const std::string& out, const Edit& f) {
    auto img = formats::readImage(in);
    applyEdit(img.image, f, img.info.bitDepth);
    formats::ImageWriteOptions o;
    o.bitDepth = img.info.bitDepth;
    o.alpha = false;
    formats::writeImage(out, img.image, o);
    return out;
}

} // namespace

TEST(RoundtripCli, LatticeAcceptsGameDisplayAndItsAliasSmash) {
    const std::string dir = rtDir();
    const std::string shot = writeScreenshot(dir, 8);
    std::string bytes[2];
    int k = 0;
    for (const char* name : {"game-display", "smash"}) {
        const std::string out = dir + "/lattice-" + name + ".png";
        const auto r =
            runCli("embed " + shellQuoted(shot) + " " + shellQuoted(out) + " --lattice " + name);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.out.find("12^3 game-display patch for smash"), std::string::npos) << r.out;
        const auto img = formats::readImage(out);
        const FindResult f = findPatch(img.image.view());
        ASSERT_EQ(f.status, FindStatus::Found);
        EXPECT_EQ(f.placement.lattice, PatchLattice::Smash);
        bytes[k++] = fileBytes(out);
    }
    EXPECT_EQ(bytes[0], bytes[1]);
    const auto bad = runCli("embed " + shellQuoted(shot) + " " + shellQuoted(dir + "/x.png") +
                            " --lattice gamedisplay");
    EXPECT_EQ(bad.exitCode, 2) << bad.err;
}

TEST(RoundtripCli, EmbedKeepsTheBitDepthAndTheScreenshot) {
    const std::string dir = rtDir();
    for (int depth : {8, 16}) {
        const std::string shot = writeScreenshot(dir, depth);
        const std::string out = dir + "/embedded" + std::to_string(depth) + ".png";
        const auto r = runCli("embed " + shellQuoted(shot) + " " + shellQuoted(out) +
                              " --corner bottom-right");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.out.find("12^3 game-display patch for smash"), std::string::npos);
        const auto img = formats::readImage(out);
        EXPECT_EQ(img.info.bitDepth, depth);
        const FindResult f = findPatch(img.image.view());
        ASSERT_EQ(f.status, FindStatus::Found);
        EXPECT_EQ(f.placement.bitDepth, depth);
        // in the corner, the patch's first entry moved onto the 16-pixel JPEG grid
        EXPECT_LE(f.placement.frameX + f.placement.frameWidth, 400 - kDefaultPatchMargin);
        EXPECT_GT(f.placement.frameX + f.placement.frameWidth,
                  400 - kDefaultPatchMargin - kJpegGrid);
        EXPECT_EQ(f.placement.patchX() % kJpegGrid, 0);
        EXPECT_EQ(f.placement.patchY() % kJpegGrid, 0);
        // pixels outside the frame are the screenshot's
        const auto orig = formats::readImage(shot);
        EXPECT_EQ(img.image.pixel(5, 5)[0], orig.image.pixel(5, 5)[0]);
    }
    // refuses to overwrite its input, and bad usage is exit 2
    const std::string shot = writeScreenshot(dir, 8);
    EXPECT_EQ(runCli("embed " + shellQuoted(shot) + " " + shellQuoted(shot)).exitCode, 1);
    EXPECT_EQ(runCli("embed " + shellQuoted(shot)).exitCode, 2);
    EXPECT_EQ(runCli("embed " + shellQuoted(shot) + " " + shellQuoted(dir + "/x.png") +
                     " --corner middle")
                  .exitCode,
              2);
    const auto tooBig = runCli("embed " + shellQuoted(shot) + " " + shellQuoted(dir + "/x.png") +
                               " --size 40 --scale 3");
    EXPECT_EQ(tooBig.exitCode, 1);
    EXPECT_NE(tooBig.err.find("needs"), std::string::npos);
}

TEST(RoundtripCli, ExtractRawMatchesTheEdit) {
    const std::string dir = rtDir();
    const std::string shot = writeScreenshot(dir, 8);
    const std::string emb = dir + "/emb.png";
    ASSERT_EQ(
        runCli("embed " + shellQuoted(shot) + " " + shellQuoted(emb) + " --target raw").exitCode,
        0);
    const Edit f = saturationEdit();
    const std::string edited = editFile(emb, dir + "/edited.png", f);
    const std::string cube = dir + "/out.cube";
    const auto r = runCli("extract " + shellQuoted(edited) + " " + shellQuoted(cube));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("expected error"), std::string::npos);
    const Lut3D lut = formats::readLut(cube).toLut3D();
    ASSERT_EQ(lut.size(), 16);
    double worst = 0.0;
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int rr = 0; rr < 16; ++rr) {
                const glm::dvec3 want = f(glm::dvec3(rr, g, b) / 15.0);
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::fabs(lut.at(rr, g, b)[c] - want[c]) * 255.0);
            }
    EXPECT_LE(worst, 0.51);
    // an output size and a strip image work too
    ASSERT_EQ(runCli("extract " + shellQuoted(edited) + " " + shellQuoted(dir + "/out33.cube") +
                     " --size 33")
                  .exitCode,
              0);
    EXPECT_EQ(formats::readLut(dir + "/out33.cube").toLut3D().size(), 33);
}

TEST(RoundtripCli, ExtractSmashWritesTheCompensatedNutexb) {
    const std::string dir = rtDir();
    const std::string shot = writeScreenshot(dir, 8);
    const std::string emb = dir + "/emb.png";
    ASSERT_EQ(runCli("embed " + shellQuoted(shot) + " " + shellQuoted(emb)).exitCode, 0);
    const std::string edited = editFile(emb, dir + "/edited.png", curvesEdit());
    const std::string nutexb = dir + "/color_grading_lut.nutexb";
    const auto r =
        runCli("extract " + shellQuoted(edited) + " " + shellQuoted(nutexb) + " --target smash");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("expected error"), std::string::npos);
    const Lut3D shipped = formats::readLut(nutexb).toLut3D();
    ASSERT_EQ(shipped.size(), 16);
    // the same as the library's answer, rounded to the nutexb's 8 bits
    ExtractOptions o;
    o.target = LutPurpose::Smash;
    const ExtractResult lib = extractLut(formats::readImage(edited).image.view(), o);
    for (std::size_t i = 0; i < shipped.entryCount(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(toUnorm8(shipped.entries()[i][c]), toUnorm8(lib.lut.entries()[i][c])) << i;
    // --original-lut: a neutral original changes nothing
    const std::string neutral = dir + "/neutral.cube";
    LutFile nf;
    nf.cube = Lut3D::identity(16);
    formats::writeLut(neutral, nf);
    const std::string withOrig = dir + "/with_original.cube";
    ASSERT_EQ(runCli("extract " + shellQuoted(edited) + " " + shellQuoted(withOrig) +
                     " --target smash --original-lut " + shellQuoted(neutral))
                  .exitCode,
              0);
    const Lut3D w = formats::readLut(withOrig).toLut3D();
    for (std::size_t i = 0; i < w.entryCount(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(w.entries()[i][c], lib.lut.entries()[i][c], 1e-5);
}

TEST(RoundtripCli, ExtractFailsAndWarnsClearly) {
    const std::string dir = rtDir();
    const std::string shot = writeScreenshot(dir, 8);
    const auto none = runCli("extract " + shellQuoted(shot) + " " + shellQuoted(dir + "/x.cube"));
    EXPECT_EQ(none.exitCode, 1);
    EXPECT_NE(none.err.find("no LUT patch found"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir + "/x.cube"));
    EXPECT_EQ(runCli("extract " + shellQuoted(shot) + " " + shellQuoted(dir + "/x.cube") +
                     " --target game")
                  .exitCode,
              2);
    // a clipping edit: the LUT is written, with a warning on stderr
    const std::string emb = dir + "/emb.png";
    ASSERT_EQ(runCli("embed " + shellQuoted(shot) + " " + shellQuoted(emb)).exitCode, 0);
    const std::string edited =
        editFile(emb, dir + "/clipped.png", levelsEdit(0.3, 0.6, 1.0, 0.0, 1.0));
    const auto r =
        runCli("extract " + shellQuoted(edited) + " " + shellQuoted(dir + "/clipped.cube"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("warning: "), std::string::npos);
    EXPECT_NE(r.err.find("clipped"), std::string::npos);
    EXPECT_TRUE(std::filesystem::exists(dir + "/clipped.cube"));
}

TEST(RoundtripCli, FitWritesTheLutAndReportsTheError) {
    const std::string dir = rtDir();
    const std::string before = writeScreenshot(dir, 8);
    const Edit f = levelsEdit();
    const std::string after = editFile(before, dir + "/after.png", f);
    const std::string out = dir + "/fit.cube";
    const auto r = runCli("fit " + shellQuoted(before) + " " + shellQuoted(after) + " " +
                          shellQuoted(out) + " --size 17");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("error over those pixels rms"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("held out on colours it was not fitted to"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("extrapolated"), std::string::npos);
    EXPECT_NE(r.err.find("cover only"),
              std::string::npos); // a screenshot covers little of the cube
    const Lut3D lut = formats::readLut(out).toLut3D();
    ASSERT_EQ(lut.size(), 17);
    // where the screenshot has pixels, the fit follows the edit
    const auto img = formats::readImage(before);
    const auto s = makeSampler(lut, Interpolation::Trilinear);
    double worst = 0.0;
    for (int y = 0; y < img.image.height(); y += 7)
        for (int x = 0; x < img.image.width(); x += 7) {
            const float* p = img.image.pixel(x, y);
            const glm::vec3 got = s->sample(glm::vec3(p[0], p[1], p[2]));
            const glm::dvec3 want = f(glm::dvec3(p[0], p[1], p[2]));
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::fabs(got[c] - want[c]) * 255.0);
        }
    EXPECT_LE(worst, 3.0);
    // mismatched sizes are bad input
    const std::string small = dir + "/small.png";
    formats::ImageWriteOptions o;
    formats::writeImage(small, syntheticScreenshot(100, 50), o);
    EXPECT_EQ(runCli("fit " + shellQuoted(before) + " " + shellQuoted(small) + " " +
                     shellQuoted(dir + "/y.cube"))
                  .exitCode,
              1);
    EXPECT_EQ(runCli("fit " + shellQuoted(before) + " " + shellQuoted(after)).exitCode, 2);
}
