// SPDX-License-Identifier: Apache-2.0
// Issue 17, problem 1: a full disk never destroys an output. For every writer in the format
// registry (convert) and every image format apply, preview and embed write, on a disk with no
// room and on one with a little room (the writer gets part of the file out): exit 1, one line
// naming the output and "No space left on device", the existing output's bytes unchanged, no
// temporary file left. Before the fix, PNG, BMP, TGA, WebP, GIF (and EXR on an empty disk)
// exited 0 over a 0-byte or truncated file, and TIFF quoted the hidden temporary name.
#include "FullDisk.h"

#include "lut/formats/Registry.h"

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>
#include <sstream>

using namespace lut::robust;
using ::testing::HasSubstr;

namespace {

using lut::test::shellQuoted;

// A 33^3 LUT of random values: no writer can compress it into a few KiB.
std::string randomCube() {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::ostringstream s;
    s << "LUT_3D_SIZE 33\n";
    for (int i = 0; i < 33 * 33 * 33; ++i)
        s << u(rng) << " " << u(rng) << " " << u(rng) << "\n";
    return s.str();
}

// A noisy 8-bit RGB picture, 640x360 (embed needs room for its patch).
void writeNoisePng(const std::string& path) {
    const int w = 640, h = 360;
    std::mt19937 rng(7);
    std::vector<unsigned char> px(static_cast<std::size_t>(w) * h * 3);
    for (auto& v : px)
        v = static_cast<unsigned char>(rng() & 0xFF);
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
    out->close();
}

// The lines of stderr that are not notes ("lutkit: note: ...", e.g. what a LUT that does not say
// what it is for was taken for): the error is one of them, alone.
std::vector<std::string> errorLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);)
        if (!l.empty() && l.rfind("lutkit: note: ", 0) != 0)
            lines.push_back(l);
    return lines;
}

struct Case {
    std::string label;   // test name suffix
    std::string command; // "convert IN OUT --format x": IN/OUT/LUT are replaced
    std::string ext;     // of OUT
};

void PrintTo(const Case& c, std::ostream* os) {
    *os << c.command << " (OUT" << c.ext << ")";
}

std::string fill(std::string text, const std::string& key, const std::string& value) {
    for (std::size_t at; (at = text.find(key)) != std::string::npos;)
        text.replace(at, key.size(), value);
    return text;
}

// Runs one case on an empty disk and on one with 8 KiB left.
void checkFullDisk(const Case& c) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/in.cube", randomCube());
    writeNoisePng(dir + "/in.png");
    // Tagged sRGB: OpenImageIO's TIFF writer then writes an Exif directory, by name (issue 41).
    ASSERT_EQ(lut::test::runCommand("oiiotool " + shellQuoted(dir + "/in.png") +
                                    " --attrib oiio:ColorSpace sRGB -o " +
                                    shellQuoted(dir + "/in-srgb.png"))
                  .exitCode,
              0);
    FullDisk disk(dir + "/disk");
    if (disk.kind() == FullDisk::Kind::None)
        GTEST_SKIP() << "no small file system can be mounted here and no ENOSPC shim: "
                     << disk.whyNone();
    const std::string name = "out" + c.ext;
    const std::string out = disk.dir() + "/" + name;
    const std::string old = "the user's old file, which must survive\n";
    for (int freeKiB : {0, 8}) {
        SCOPED_TRACE(std::string(disk.kindName()) + ", " + std::to_string(freeKiB) +
                     " KiB free: " + c.command);
        writeBytes(out, old);
        disk.fill(freeKiB);
        std::string args = fill(c.command, "OUT", shellQuoted(out));
        args = fill(args, "IN.cube", shellQuoted(dir + "/in.cube"));
        args = fill(args, "IN-srgb.png", shellQuoted(dir + "/in-srgb.png"));
        args = fill(args, "IN.png", shellQuoted(dir + "/in.png"));
        const auto r = disk.run(args);
        EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
        const auto lines = errorLines(r.err);
        ASSERT_EQ(lines.size(), 1u) << r.err;
        EXPECT_THAT(lines[0], HasSubstr(out + ": cannot write: No space left on device"));
        // The path once (an OpenEXR write said "OUT: cannot write: OUT: cannot write: ...").
        EXPECT_EQ(lines[0].find(out), lines[0].rfind(out)) << lines[0];
        EXPECT_THAT(lines[0], ::testing::Not(HasSubstr(".tmp"))); // never the hidden name
        EXPECT_EQ(fileBytes(out), old);
        EXPECT_EQ(disk.listing(), std::vector<std::string>{name});
    }
}

// Every format the registry writes, each of its extensions (hald: --format on .png).
std::vector<Case> registryCases() {
    lut::formats::registerBuiltinFormats();
    std::vector<Case> cases;
    for (const lut::Format* f : lut::FormatRegistry::instance().all()) {
        if (!f->canWrite())
            continue;
        auto exts = f->extensions();
        if (exts.empty())
            exts = {".png", ".tif", ".exr"};
        for (const auto& e : exts)
            cases.push_back(
                {f->name() + "_" + e.substr(1), "convert -y IN.cube OUT --format " + f->name(), e});
    }
    return cases;
}

std::vector<Case> imageCases() {
    std::vector<Case> cases;
    for (const char* e :
         {".png", ".jpg", ".tif", ".exr", ".bmp", ".tga", ".hdr", ".webp", ".dpx", ".gif"})
        cases.push_back(
            {std::string("apply_") + (e + 1), "apply -y --lut IN.cube IN.png -o OUT", e});
    cases.push_back({"apply_srgb_tif", "apply -y --lut IN.cube IN-srgb.png -o OUT", ".tif"});
    cases.push_back({"preview_png", "preview -y --lut IN.cube IN.png -o OUT", ".png"});
    cases.push_back({"preview_tif", "preview -y IN.png -o OUT", ".tif"});
    cases.push_back({"embed_png", "embed -y IN.png OUT", ".png"});
    cases.push_back({"embed_bmp", "embed -y IN.png OUT", ".bmp"});
    return cases;
}

class FullDiskWrite : public ::testing::TestWithParam<Case> {};

TEST_P(FullDiskWrite, KeepsTheOldOutputAndSaysWhy) {
    const Case& c = GetParam();
    if (c.ext == ".jpg")
        GTEST_SKIP() << "needs P1's IOProxy writer: libjpeg's error handler calls exit()";
    checkFullDisk(c);
}

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
    return info.param.label;
}

INSTANTIATE_TEST_SUITE_P(Registry, FullDiskWrite, ::testing::ValuesIn(registryCases()), caseName);
INSTANTIATE_TEST_SUITE_P(Images, FullDiskWrite, ::testing::ValuesIn(imageCases()), caseName);

} // namespace
