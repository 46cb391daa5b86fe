// SPDX-License-Identifier: Apache-2.0
// lutkit preview: output pixels against the float64 reference of docs/specs/smash-pipeline.md
// (shared with the pipeline tests), screenshot regrading, stage switches, batch and usage errors.
#include "CliTestSupport.h"
#include "OklabReference.h"
#include "PipelineTestUtil.h"

#include "lut/formats/ImageIO.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace lut;
using namespace lut::test;

namespace {

Image expectedSmash(const Image& scene, const Lut3D& lut, bool bloom) {
    const RefImg s = toRef(scene);
    RefImg b(scene.width(), scene.height());
    if (bloom)
        b = refSmashBloom(s);
    Image out(scene.width(), scene.height());
    for (int y = 0; y < scene.height(); ++y)
        for (int x = 0; x < scene.width(); ++x) {
            double in[3], o[3];
            for (int c = 0; c < 3; ++c)
                in[c] = s.at(x, y, c) + b.at(x, y, c);
            refSmashGrade(lut, in, s.at(x, y, 3), o);
            for (int c = 0; c < 3; ++c)
                out.pixel(x, y)[c] = static_cast<float>(refSrgbEncode(o[c]));
            out.pixel(x, y)[3] = scene.pixel(x, y)[3];
        }
    return out;
}

double maxDiff(const Image& a, const Image& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i)
        d = std::max(d, relErr(a.pixels()[i], b.pixels()[i]));
    return d;
}

} // namespace

TEST(CliPreview, ExrSceneThroughTheSmashChainMatchesReference) {
    const std::string dir = workDir();
    const Lut3D lut = makeWarmLut(16);
    const std::string cube = writeCube(dir + "/warm.cube", lut);
    const Image scene = makeScene(37, 23, 77);
    formats::writeImage(dir + "/scene.exr", scene, {32, false, true});
    for (bool bloom : {true, false}) {
        const std::string out = dir + (bloom ? "/bloom.exr" : "/nobloom.exr");
        // (the table is the game's LUT: a .cube that does not say is taken as an edit)
        const RunResult r =
            runCli("preview '" + dir + "/scene.exr' -o '" + out + "' --lut-target smash --lut '" +
                   cube + "'" + (bloom ? "" : " --no-bloom"));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const formats::LoadedImage got = formats::readImage(out);
        EXPECT_EQ(got.info.bitDepth, 32);
        EXPECT_LT(maxDiff(got.image, expectedSmash(scene, lut, bloom)), 1e-5) << "bloom " << bloom;
    }
}

TEST(CliPreview, EightBitSceneIsSrgbDecodedAndRoundedToNearest) {
    const std::string dir = workDir();
    Image shot(8, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            float* p = shot.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = static_cast<float>(((x * 29 + y * 53 + c * 17) % 200) / 255.0);
            p[3] = 1.0f;
        }
    formats::writeImage(dir + "/shot.png", shot, {8, false, false});
    // --scene: the 8-bit picture of a scene (not a screenshot, the default for 8-bit files)
    const RunResult r =
        runCli("preview '" + dir + "/shot.png' -o '" + dir + "/out.png' --no-bloom --scene");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("a linear scene (an 8-bit png file"), std::string::npos) << r.err;
    const formats::LoadedImage got = formats::readImage(dir + "/out.png");
    EXPECT_EQ(got.info.bitDepth, 8);
    EXPECT_EQ(got.info.channels, 3);
    const Lut3D neutral = Lut3D::identity(16);
    int checked = 0;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) {
                const double v = shot.pixel(x, y)[c];
                const double lin = v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
                const double in[3] = {lin, lin, lin};
                double o[3];
                refSmashGrade(neutral, in, 1.0, o);
                const double want = std::min(1.0, refSrgbEncode(o[0])) * 255.0;
                // Skip values within 1e-3 of a rounding boundary (float vs double).
                if (std::fabs(want - std::floor(want) - 0.5) < 1e-3)
                    continue;
                EXPECT_EQ(std::lround(got.image.pixel(x, y)[c] * 255.0), std::lround(want))
                    << x << "," << y;
                ++checked;
            }
    EXPECT_GT(checked, 80);
}

TEST(CliPreview, AScreenshotGetsNoSecondBloomByDefault) {
    // The screenshot has the game's bloom in it: the default preview adds none (as the editor
    // shows it); before, the default added the bloom a second time. --enable bloom asks for it.
    const std::string dir = workDir();
    Image shot(64, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) {
            float* p = shot.pixel(x, y);
            const bool bright = x > 24 && x < 40 && y > 8 && y < 24;
            for (int c = 0; c < 3; ++c)
                p[c] = bright ? 1.0f : static_cast<float>(((x * 5 + y * 3 + c * 11) % 90) / 255.0);
            p[3] = 1.0f;
        }
    formats::writeImage(dir + "/shot.png", shot, {8, false, false});
    const std::string in = "preview '" + dir + "/shot.png' -o '" + dir;
    const RunResult byDefault = runCli(in + "/default.png'");
    ASSERT_EQ(byDefault.exitCode, 0) << byDefault.err;
    EXPECT_NE(byDefault.err.find("no bloom added"), std::string::npos) << byDefault.err;
    ASSERT_EQ(runCli(in + "/nobloom.png' --no-bloom").exitCode, 0);
    ASSERT_EQ(runCli(in + "/bloom.png' --enable bloom").exitCode, 0);
    const Image a = formats::readImage(dir + "/default.png").image;
    const Image b = formats::readImage(dir + "/nobloom.png").image;
    const Image c = formats::readImage(dir + "/bloom.png").image;
    EXPECT_EQ(a.pixels(), b.pixels());
    EXPECT_NE(a.pixels(), c.pixels()); // the bloom does change this picture when asked for
}

TEST(CliPreview, AnEightBitFileIsAScreenshotByDefaultAndSaysSo) {
    // With the neutral LUT the game's picture of the game's picture is the picture: undoing the
    // grading and grading again gives the screenshot back (the issue: treated as a scene it came
    // out ~53 steps washed out).
    const std::string dir = workDir();
    Image shot(16, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) {
            float* p = shot.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = static_cast<float>(((x * 13 + y * 31 + c * 7) % 230) / 255.0);
            p[3] = 1.0f;
        }
    formats::writeImage(dir + "/shot.png", shot, {8, false, false});
    const RunResult r =
        runCli("preview '" + dir + "/shot.png' -o '" + dir + "/out.png' --no-bloom");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("an in-game screenshot (an 8-bit png file"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--scene"), std::string::npos) << r.err;
    const formats::LoadedImage got = formats::readImage(dir + "/out.png");
    double worst = 0.0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst,
                                 std::fabs(got.image.pixel(x, y)[c] - shot.pixel(x, y)[c]) * 255.0);
    EXPECT_LE(worst, 1.0);
    // -q says nothing; --from-screenshot and --scene together are bad usage
    const RunResult quiet =
        runCli("preview '" + dir + "/shot.png' -o '" + dir + "/q.png' --no-bloom -q");
    EXPECT_EQ(quiet.err, "");
    EXPECT_EQ(
        runCli("preview '" + dir + "/shot.png' -o '" + dir + "/x.png' --from-screenshot --scene")
            .exitCode,
        2);
}

TEST(CliPreview, RegradingAScreenshotMatchesGradingTheScene) {
    const std::string dir = workDir();
    const std::string l0 = writeCube(dir + "/l0.cube", makeWarmLut(16, 1.0));
    const std::string l1 = writeCube(dir + "/l1.cube", makeWarmLut(16, -1.5));
    Image scene(24, 16);
    Rng rng(8);
    for (auto& v : scene.pixels())
        v = static_cast<float>(0.4 * rng.uniform());
    for (std::size_t i = 3; i < scene.pixels().size(); i += 4)
        scene.pixels()[i] = 1.0f;
    formats::writeImage(dir + "/scene.exr", scene, {32, false, true});
    ASSERT_EQ(runCli("preview '" + dir + "/scene.exr' -o '" + dir +
                     "/shot.exr' --no-bloom --lut-target smash --lut '" + l0 + "'")
                  .exitCode,
              0);
    const RunResult r = runCli("preview '" + dir + "/shot.exr' -o '" + dir +
                               "/regraded.exr' --no-bloom --lut-target smash --lut '" + l1 +
                               "' --from-screenshot --original-lut '" + l0 + "'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("bloom cannot be undone"), std::string::npos);
    ASSERT_EQ(runCli("preview '" + dir + "/scene.exr' -o '" + dir +
                     "/direct.exr' --no-bloom --lut-target smash --lut '" + l1 + "'")
                  .exitCode,
              0);
    const Image a = formats::readImage(dir + "/regraded.exr").image;
    const Image b = formats::readImage(dir + "/direct.exr").image;
    EXPECT_LT(maxDiff(a, b), 3e-5);
}

TEST(CliPreview, StageSwitchesVerboseAndErrors) {
    const std::string dir = workDir();
    Image scene = makeScene(32, 24, 3);
    formats::writeImage(dir + "/s.exr", scene, {32, false, true});
    RunResult r = runCli("preview '" + dir + "/s.exr' -o '" + dir +
                         "/o.exr' --verbose --enable vignette --stage "
                         "vignette.strength=0.5 --stage bloom.strength=0");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("vignette"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("smash-bloom            skipped"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("ms"), std::string::npos);
    // bloom strength 0 == --no-bloom: bit-identical files.
    ASSERT_EQ(runCli("preview '" + dir + "/s.exr' -o '" + dir +
                     "/p.exr' --no-bloom --enable vignette --stage "
                     "vignette.strength=0.5")
                  .exitCode,
              0);
    EXPECT_EQ(formats::readImage(dir + "/o.exr").image.pixels(),
              formats::readImage(dir + "/p.exr").image.pixels());
    // Vignette darkens the corner relative to the plain chain.
    ASSERT_EQ(runCli("preview '" + dir + "/s.exr' -o '" + dir + "/q.exr' --no-bloom").exitCode, 0);
    EXPECT_LT(formats::readImage(dir + "/o.exr").image.pixel(0, 0)[1],
              formats::readImage(dir + "/q.exr").image.pixel(0, 0)[1]);

    EXPECT_EQ(
        runCli("preview '" + dir + "/s.exr' -o '" + dir + "/x.exr' --stage nosuch.a=1").exitCode,
        2);
    EXPECT_EQ(
        runCli("preview '" + dir + "/s.exr' -o '" + dir + "/x.exr' --stage vignette.strength=7")
            .exitCode,
        2);
    EXPECT_EQ(runCli("preview '" + dir + "/s.exr' -o '" + dir + "/x.exr' --preset bogus").exitCode,
              2);
    EXPECT_EQ(runCli("preview '" + dir + "/s.exr'").exitCode, 2);
    r = runCli("preview --list-stages --preset lecture");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("grain.seed"), std::string::npos);
    EXPECT_NE(r.out.find("SSAO"), std::string::npos);
}

TEST(CliPreview, BatchWritesEveryGoodFileAndFailsOnBadOnes) {
    const std::string dir = workDir();
    std::filesystem::create_directories(dir + "/in");
    const Image scene = makeScene(16, 12, 5);
    formats::writeImage(dir + "/in/one.exr", scene, {32, false, true});
    formats::writeImage(dir + "/in/two.png", Image(6, 6, 0.5f), {8, false, true});
    { std::ofstream(dir + "/in/bad.exr") << "garbage"; }
    const RunResult r = runCli("preview '" + dir + "/in' -o '" + dir + "/out/' --no-bloom");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("bad.exr"), std::string::npos) << r.err;
    const formats::LoadedImage one = formats::readImage(dir + "/out/one.exr");
    EXPECT_LT(maxDiff(one.image, expectedSmash(scene, Lut3D::identity(16), false)), 1e-5);
    EXPECT_EQ(formats::readImage(dir + "/out/two.png").info.bitDepth, 8);
}

TEST(CliPreview, StrengthBlendsTheLutWithNeutralFirst) {
    // --strength: the preview grades with the LUT blended with neutral in Oklab (a game LUT,
    // --lut-target smash: used by the game's chain as it is, blended as it is); the oracle is
    // the float64 reference chain with a LUT blended by the float64 Oklab of
    // tests/support/OklabReference.h.
    const std::string dir = workDir();
    const Lut3D lut = makeWarmLut(16);
    const std::string cube = writeCube(dir + "/warm.cube", lut);
    const Image scene = makeScene(37, 23, 77);
    formats::writeImage(dir + "/scene.exr", scene, {32, false, true});
    Lut3D blended(16);
    for (int b = 0; b < 16; ++b)
        for (int g = 0; g < 16; ++g)
            for (int r = 0; r < 16; ++r)
                blended.at(r, g, b) = glm::vec3(strengthBlend(
                    glm::dvec3(lut.latticeInput(r, g, b)), glm::dvec3(lut.at(r, g, b)), 0.4, 0.8));
    const std::string out = dir + "/out.exr";
    const RunResult r = runCli("preview '" + dir + "/scene.exr' -o '" + out + "' --lut '" + cube +
                               "' --lut-target smash --luma-strength 0.4 --chroma-strength 0.8");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Image got = formats::readImage(out).image;
    EXPECT_LT(maxDiff(got, expectedSmash(scene, blended, true)), 1e-5);
    // ... and not the full LUT (the blend changes the picture).
    EXPECT_GT(maxDiff(got, expectedSmash(scene, lut, true)), 1e-3);
    // Without --lut there is nothing to blend: bad usage.
    EXPECT_EQ(
        runCli("preview '" + dir + "/scene.exr' -o '" + dir + "/x.exr' --strength 0.5").exitCode,
        2);
}

TEST(CliPreview, AStreamedPreviewIsTheFramePathBitForBit) {
    // A picture whose chain works pixel by pixel (a screenshot: no bloom) is streamed through the
    // apply path, never held as a frame; it must write the very file the frame path writes. A
    // vignette of strength 0 changes no pixel but needs the frame, so it forces the frame path.
    // 8 and 16-bit PNG, 8-bit PPM, a JPEG and a 16-bit TIFF (written as PNG), an odd width,
    // several chains and stage LUTs; the float64 reference of the other tests checks the pixels.
    const std::string dir = workDir();
    const std::string warm = writeCube(dir + "/warm.cube", makeWarmLut(17));
    Image shot(37, 19);
    Rng rng(21);
    for (auto& v : shot.pixels())
        v = static_cast<float>(rng.uniform());
    for (std::size_t i = 3; i < shot.pixels().size(); i += 4)
        shot.pixels()[i] = 1.0f;
    formats::writeImage(dir + "/s8.png", shot, {8, false, false});
    formats::writeImage(dir + "/s16.png", shot, {16, false, false});
    formats::writeImage(dir + "/s8.ppm", shot, {8, false, false});
    formats::writeImage(dir + "/s8.jpg", shot, {8, false, false});
    formats::writeImage(dir + "/s16.tif", shot, {16, false, false});
    const char* const options[] = {
        "",
        " --lut 'WARM'",
        " --lut 'WARM' --original-lut builtin:smash-default",
        " --scene --lut 'WARM'",
        " --preset filmic --lut 'WARM' --interp tetrahedral",
        " --lut 'WARM' --enable lut --enable exposure --stage exposure.stops=0.3",
    };
    const auto bytesOf = [](const std::string& path) {
        std::ifstream f(path, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(f)), {});
    };
    int compared = 0;
    for (const char* in : {"s8.png", "s16.png", "s8.ppm", "s8.jpg", "s16.tif"}) {
        const std::string ext = std::string(in).find(".ppm") != std::string::npos ? ".ppm" : ".png";
        // (OpenImageIO's formats, each run loading it: two chains are enough there)
        const bool oiio = ext == ".png" && std::string(in).find(".png") == std::string::npos;
        for (std::size_t k = 0; k < (oiio ? 2 : std::size(options)); ++k) {
            std::string opt = options[k];
            const auto at = opt.find("WARM");
            if (at != std::string::npos)
                opt.replace(at, 4, warm);
            const std::string base = "preview -v '" + dir + "/" + in + "' -y" + opt + " -o '" + dir;
            const RunResult streamed = runCli(base + "/streamed" + ext + "'");
            ASSERT_EQ(streamed.exitCode, 0) << opt << ": " << streamed.err;
            EXPECT_NE(streamed.out.find("streamed"), std::string::npos) << in << opt;
            const RunResult frame =
                runCli(base + "/frame" + ext + "' --enable vignette --stage vignette.strength=0");
            ASSERT_EQ(frame.exitCode, 0) << opt << ": " << frame.err;
            EXPECT_EQ(frame.out.find("streamed"), std::string::npos) << in << opt;
            const std::string a = bytesOf(dir + "/streamed" + ext);
            EXPECT_GT(a.size(), 100u) << in << opt;
            EXPECT_TRUE(a == bytesOf(dir + "/frame" + ext)) << in << opt;
            ++compared;
        }
    }
    EXPECT_EQ(compared, 3 * 6 + 2 * 2);
    // What needs the frame is not streamed: an added bloom, an output format with its own
    // compression choices.
    for (const std::string& args :
         {" --enable bloom -o '" + dir + "/bloom.png'", " -o '" + dir + "/out.tif'"}) {
        const RunResult r = runCli("preview -v '" + dir + "/s8.png' -y" + args);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.out.find("streamed"), std::string::npos) << args;
    }
}
