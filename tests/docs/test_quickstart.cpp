// SPDX-License-Identifier: Apache-2.0
// The README's quick start, run as it stands: the lines between `<!-- quickstart:NAME -->` and
// `<!-- /quickstart -->` are taken from README.md and run one by one with /bin/sh in an empty
// folder, with the built lutkit first on PATH, on small inputs the test makes where the README
// says the user brings them. Each output is checked against an oracle written here from the
// specs: the strip layout (docs/specs/strip-layouts.md), the game's compensation
// (docs/specs/smash-pipeline.md) in float64, OpenColorIO's reading of the .3dl, an affine grade
// that every interpolation reproduces exactly.
#include "OcioTestUtil.h"
#include "TestPaths.h"
#include "TestSupport.h"

#include "lut/formats/Registry.h"

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace fs = std::filesystem;
namespace OCIO = OCIO_NAMESPACE;

namespace {

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The command lines of one quick-start block: inside the code fence between the markers, every
// line that is not blank and not a comment.
std::vector<std::string> quickstartLines(const std::string& name) {
    const std::string readme = slurp(fs::path(LUTKIT_SOURCE_DIR) / "README.md");
    const std::string open = "<!-- quickstart:" + name + " -->";
    const std::size_t begin = readme.find(open);
    if (begin == std::string::npos)
        return {};
    const std::size_t end = readme.find("<!-- /quickstart -->", begin);
    std::istringstream block(readme.substr(begin + open.size(), end - begin - open.size()));
    std::vector<std::string> lines;
    bool inFence = false;
    for (std::string line; std::getline(block, line);) {
        if (line.rfind("```", 0) == 0) {
            inFence = !inFence;
            continue;
        }
        const auto first = line.find_first_not_of(" \t");
        if (inFence && first != std::string::npos && line[first] != '#')
            lines.push_back(line);
    }
    return lines;
}

struct LineRun {
    int exitCode = -1;
    std::string out, err;
};

// The folder of the lutkit the quick starts run: the built one, or $LUTKIT_QUICKSTART_BIN (the
// package test's extracted /usr/bin).
std::string programFolder() {
    const char* other = std::getenv("LUTKIT_QUICKSTART_BIN");
    return other && *other ? std::string(other) : fs::path(LUTKIT_CLI).parent_path().string();
}

// Runs one README line with /bin/sh in `dir`, lutkit's folder first on PATH.
LineRun runLine(const fs::path& dir, const std::string& line) {
    const fs::path script = dir.parent_path() / "line.sh";
    const fs::path out = dir.parent_path() / "line.out", err = dir.parent_path() / "line.err";
    std::ofstream(script) << "cd '" << dir.string() << "' || exit 99\nPATH='" << programFolder()
                          << "':\"$PATH\"\n"
                          << line << "\n";
    const std::string cmd = "/bin/sh '" + script.string() + "' >'" + out.string() + "' 2>'" +
                            err.string() + "' </dev/null";
    const int status = std::system(cmd.c_str());
    LineRun r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

std::string describe(const std::string& line, const LineRun& r) {
    return "README line: " + line + "\nexit " + std::to_string(r.exitCode) + "\nstdout:\n" + r.out +
           "\nstderr:\n" + r.err;
}

struct Picture {
    int width = 0, height = 0, channels = 0;
    OIIO::TypeDesc type;
    std::vector<float> pixels; // as float, channels interleaved
    OIIO::ImageSpec spec;
};

Picture readPicture(const fs::path& path) {
    Picture p;
    auto in = OIIO::ImageInput::open(path.string());
    if (!in)
        return p;
    p.spec = in->spec();
    p.width = p.spec.width;
    p.height = p.spec.height;
    p.channels = p.spec.nchannels;
    p.type = p.spec.format;
    p.pixels.resize(std::size_t(p.width) * p.height * p.channels);
    if (!in->read_image(0, 0, 0, p.channels, OIIO::TypeDesc::FLOAT, p.pixels.data()))
        p.pixels.clear();
    return p;
}

void writePicture(const fs::path& path, const OIIO::ImageSpec& spec, const std::vector<float>& px) {
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out && out->open(path.string(), spec)) << path;
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data())) << path;
    ASSERT_TRUE(out->close());
}

// --- The game (docs/specs/smash-pipeline.md), in float64 -------------------------------------

double srgbEncode(double x) {
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055;
}
double srgbDecode(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// The 8-bit entry of the compensated LUT for a neutral edit at lattice index i of 16 (each
// channel on its own, since a neutral stage LUT and a neutral edit act per channel): the game
// shows srgb(min(1, (1.3703 s)^2.2)) for s = i/15 (the display clips at white); the modder wants
// the edit of that colour, here the colour itself; the entry L that makes the game's grading give
// it is
//     L = (decode(wanted)^(1/2.2) / 1.3703 - s) / 0.99961 + s,
// and where wanted is white, every entry from L up shows white: the neutral stage's own s when it
// does (the one rule above white, lut/smash/SmashAuthoring.h). Rounded to nearest: L = s, the
// neutral nutexb (17 i).
int compensatedNeutralEntry(int i) {
    const double s = i / 15.0;
    const double wanted = srgbEncode(std::min(1.0, std::pow(1.3703 * s, 2.2)));
    double L = (std::pow(srgbDecode(wanted), 1 / 2.2) / 1.3703 - s) / 0.99961 + s;
    if (wanted >= 1.0 - 1e-6)
        L = std::max(L, s);
    return int(std::lround(255 * std::clamp(L, 0.0, 1.0)));
}

// --- The colourist's grade: affine, so any lattice size and interpolation reproduce it --------

struct Rgb {
    double r, g, b;
};
Rgb look(double r, double g, double b) {
    return {0.05 + 0.8 * r + 0.1 * g, 0.9 * g + 0.05 * b, 0.1 + 0.6 * b + 0.2 * r};
}

void writeLookCube(const fs::path& path, int n) {
    std::ofstream f(path);
    f << "TITLE \"look\"\nLUT_3D_SIZE " << n << "\n";
    char line[96];
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const Rgb o = look(r / double(n - 1), g / double(n - 1), b / double(n - 1));
                std::snprintf(line, sizeof line, "%.9f %.9f %.9f\n", o.r, o.g, o.b);
                f << line;
            }
}

fs::path workDir() {
    const fs::path dir = fs::path(lut::test::tempDir()) / "work";
    fs::create_directories(dir);
    return dir;
}

bool startsWith(const std::string& s, const std::string& prefix) {
    return s.rfind(prefix, 0) == 0;
}
bool mentions(const std::string& s, const std::string& word) {
    return s.find(word) != std::string::npos;
}

} // namespace

TEST(QuickStart, BlocksHoldTheCommands) {
    const auto modder = quickstartLines("modder");
    ASSERT_EQ(modder.size(), 3u) << "README.md: the modder's quick start is three commands";
    EXPECT_TRUE(startsWith(modder[0], "lutkit neutral ") && mentions(modder[0], "neutral.png"))
        << modder[0];
    EXPECT_TRUE(startsWith(modder[1], "lutkit convert ") && mentions(modder[1], "graded.png") &&
                mentions(modder[1], "color_grading_lut.nutexb"))
        << modder[1];
    EXPECT_TRUE(startsWith(modder[2], "lutkit preview ") && mentions(modder[2], "screenshot.png") &&
                mentions(modder[2], "in_game.png") &&
                mentions(modder[2], "color_grading_lut.nutexb"))
        << modder[2];

    const auto colourist = quickstartLines("colourist");
    ASSERT_EQ(colourist.size(), 2u) << "README.md: the colourist's quick start is two commands";
    EXPECT_TRUE(startsWith(colourist[0], "lutkit convert ") &&
                mentions(colourist[0], "look.cube") && mentions(colourist[0], "look.3dl"))
        << colourist[0];
    EXPECT_TRUE(startsWith(colourist[1], "lutkit apply ") && mentions(colourist[1], "look.cube") &&
                mentions(colourist[1], "plate.%04d.exr") &&
                mentions(colourist[1], "graded.%04d.exr"))
        << colourist[1];
}

// neutral strip -> (the user grades it; here: no change) -> color_grading_lut.nutexb -> what the
// game shows on a screenshot.
TEST(QuickStart, Modder) {
    const auto lines = quickstartLines("modder");
    ASSERT_EQ(lines.size(), 3u);
    const fs::path dir = workDir();
    // The user's in-game screenshot: 8-bit sRGB, display values up to 230. Those all reach the
    // game's LUT below its lattice point 10/15, where the compensated neutral LUT is exactly
    // neutral; brighter ones fall between point 10 and the points compensated to clip to white,
    // where the game's trilinear blend shows them up to a step darker than the screenshot
    // (measured on a full-range gradient: what the game does, not an error of the preview).
    const int w = 64, h = 48;
    std::vector<float> shot(std::size_t(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = &shot[(std::size_t(y) * w + x) * 3];
            p[0] = std::round(230.0f * x / (w - 1)) / 255;
            p[1] = std::round(230.0f * y / (h - 1)) / 255;
            p[2] = std::round(115.0f + 115.0f * std::sin(0.3f * x + 0.2f * y)) / 255;
        }
    writePicture(dir / "screenshot.png", OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8), shot);

    // 1. The neutral strip: 256x16, 8-bit, the Unreal layout (x = r + 16 b, y = g), 17 i.
    LineRun r = runLine(dir, lines[0]);
    ASSERT_EQ(r.exitCode, 0) << describe(lines[0], r);
    const Picture strip = readPicture(dir / "neutral.png");
    ASSERT_EQ(strip.width, 256);
    ASSERT_EQ(strip.height, 16);
    ASSERT_GE(strip.channels, 3);
    EXPECT_EQ(strip.type, OIIO::TypeDesc::UINT8);
    int wrong = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 256; ++x) {
            const float* p = &strip.pixels[(std::size_t(y) * 256 + x) * strip.channels];
            const int want[3] = {17 * (x % 16), 17 * y, 17 * (x / 16)};
            for (int c = 0; c < 3; ++c)
                wrong += std::lround(p[c] * 255) != want[c];
        }
    EXPECT_EQ(wrong, 0) << "neutral.png: channel values off the Unreal layout's neutral";

    // The user's grade; here the neutral edit, whose game LUT the spec gives exactly.
    fs::copy_file(dir / "neutral.png", dir / "graded.png");

    // 2. The game's file: a 16^3 nutexb compensated for the brighten pass.
    r = runLine(dir, lines[1]);
    ASSERT_EQ(r.exitCode, 0) << describe(lines[1], r);
    const lut::LutFile nutexb = lut::formats::readLut((dir / "color_grading_lut.nutexb").string());
    EXPECT_EQ(nutexb.format, "nutexb");
    ASSERT_TRUE(nutexb.cube);
    ASSERT_EQ(nutexb.cube->size(), 16);
    {
        int off = 0;
        std::string first;
        for (int b = 0; b < 16; ++b)
            for (int g = 0; g < 16; ++g)
                for (int rr = 0; rr < 16; ++rr) {
                    const glm::vec3 e = nutexb.cube->at(rr, g, b);
                    const int idx[3] = {rr, g, b};
                    for (int c = 0; c < 3; ++c) {
                        const int want = compensatedNeutralEntry(idx[c]);
                        if (std::abs(e[c] * 255 - want) > 1e-3) {
                            if (!off++)
                                first = "entry (" + std::to_string(rr) + "," + std::to_string(g) +
                                        "," + std::to_string(b) + ") channel " + std::to_string(c) +
                                        ": " + std::to_string(e[c] * 255) + ", expected " +
                                        std::to_string(want);
                        }
                    }
                }
        EXPECT_EQ(off, 0) << "the nutexb is not the compensated neutral; first: " << first;
    }

    // 3. What the game shows: with the compensated neutral, the screenshot itself (8-bit, same
    // size), within one step.
    r = runLine(dir, lines[2]);
    {
        ASSERT_EQ(r.exitCode, 0) << describe(lines[2], r);
        ASSERT_TRUE(fs::is_regular_file(dir / "in_game.png")) << describe(lines[2], r);
        const Picture seen = readPicture(dir / "in_game.png");
        ASSERT_EQ(seen.width, w);
        ASSERT_EQ(seen.height, h);
        ASSERT_EQ(seen.channels, 3);
        EXPECT_EQ(seen.type, OIIO::TypeDesc::UINT8);
        double worst = 0;
        for (std::size_t i = 0; i < shot.size(); ++i)
            worst = std::max(worst, std::abs(double(seen.pixels[i]) - shot[i]) * 255);
        EXPECT_LE(worst, 1.0) << "in_game.png differs from the screenshot by " << worst << " steps";
    }
}

// A .cube to .3dl, then the .cube applied to a three-frame half-float EXR sequence.
TEST(QuickStart, Colourist) {
    const auto lines = quickstartLines("colourist");
    ASSERT_EQ(lines.size(), 2u);
    const fs::path dir = workDir();

    // The user's LUT and frames.
    writeLookCube(dir / "look.cube", 17);
    const int w = 32, h = 16, frames = 3;
    for (int f = 1; f <= frames; ++f) {
        OIIO::ImageSpec spec(w, h, 4, OIIO::TypeDesc::HALF);
        spec.attribute("lutkit:shot", "sh010"); // metadata the user expects kept
        std::vector<float> px(std::size_t(w) * h * 4);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                float* p = &px[(std::size_t(y) * w + x) * 4];
                p[0] = float(x) / (w - 1);
                p[1] = float(y) / (h - 1);
                p[2] = 0.25f * f - 0.1f * float(x % 3);
                p[3] = (x + y) % 2 ? 1.0f : 0.5f;
            }
        char name[32];
        std::snprintf(name, sizeof name, "plate.%04d.exr", f);
        writePicture(dir / name, spec, px);
    }

    // 1. The .3dl, read by OpenColorIO: the affine grade within the 12-bit storage.
    LineRun r = runLine(dir, lines[0]);
    ASSERT_EQ(r.exitCode, 0) << describe(lines[0], r);
    EXPECT_TRUE(mentions(r.out, "max")) << "convert printed no error figure:\n" << r.out;
    OCIO::ConstCPUProcessorRcPtr cpu = lut::test::ocioFileProcessor((dir / "look.3dl").string());
    double worst = 0;
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j)
            for (int k = 0; k <= 10; ++k) {
                float rgb[3] = {i / 10.0f, j / 10.0f, k / 10.0f};
                cpu->applyRGB(rgb);
                const Rgb want = look(i / 10.0, j / 10.0, k / 10.0);
                worst = std::max({worst, std::abs(rgb[0] - want.r), std::abs(rgb[1] - want.g),
                                  std::abs(rgb[2] - want.b)});
            }
    EXPECT_LE(worst, 0.5 / 4095 + 1e-6) << "look.3dl as OpenColorIO reads it, vs the grade";

    // 2. The sequence: graded.0001..0003.exr, half with alpha and metadata, the grade applied.
    r = runLine(dir, lines[1]);
    ASSERT_EQ(r.exitCode, 0) << describe(lines[1], r);
    EXPECT_FALSE(fs::exists(dir / "graded.0004.exr"));
    for (int f = 1; f <= frames; ++f) {
        char in[32], out[32];
        std::snprintf(in, sizeof in, "plate.%04d.exr", f);
        std::snprintf(out, sizeof out, "graded.%04d.exr", f);
        const Picture plate = readPicture(dir / in), graded = readPicture(dir / out);
        ASSERT_EQ(graded.width, w) << out;
        ASSERT_EQ(graded.height, h) << out;
        ASSERT_EQ(graded.channels, 4) << out;
        EXPECT_EQ(graded.type, OIIO::TypeDesc::HALF) << out << ": the frames' pixel type";
        EXPECT_EQ(graded.spec.get_string_attribute("lutkit:shot"), "sh010") << out;
        double err = 0, alphaErr = 0;
        for (std::size_t i = 0; i < std::size_t(w) * h; ++i) {
            const float* p = &plate.pixels[i * 4];
            const float* q = &graded.pixels[i * 4];
            const Rgb want = look(p[0], p[1], p[2]);
            err = std::max(
                {err, std::abs(q[0] - want.r), std::abs(q[1] - want.g), std::abs(q[2] - want.b)});
            alphaErr = std::max(alphaErr, double(std::abs(q[3] - p[3])));
        }
        // Half keeps 11 significant bits: values below 1 are stored within 2^-12.
        EXPECT_LE(err, 1.0 / 4096 + 1e-6) << out << ": the grade applied";
        EXPECT_EQ(alphaErr, 0.0) << out << ": alpha kept";
    }
}
