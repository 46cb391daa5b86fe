// SPDX-License-Identifier: Apache-2.0
// What a LUT is for, in its file (lut/LutPurpose.h): the LUTKIT_PURPOSE tag written by every
// format that has a place for it and read back; other readers still read the file and ignore the
// tag (OpenColorIO's processor equals the table at its lattice, ffmpeg's lut3d gives the same
// picture as with the untagged file), and other programs see the image description (oiiotool).
#include "OcioTestUtil.h"
#include "TestSupport.h"

#include "lut/Error.h"
#include "lut/LutPurpose.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace OCIO = OCIO_NAMESPACE;
using namespace lut;
using lut::test::haveProgram;
using lut::test::runCommand;

namespace {

std::string workDir() {
    const std::string d = lut::test::tempDir() + "-purpose";
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

using lut::test::fileBytes;

void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

Lut3D warm(int n) {
    Lut3D l = Lut3D::identity(n);
    for (auto& e : l.entries())
        e = glm::vec3(std::min(1.0f, e.x * 1.1f), 0.05f + 0.9f * e.y, 0.8f * e.z);
    return l;
}

LutFile tagged(LutPurpose p, int n = 5) {
    LutFile f;
    f.cube = warm(n);
    f.cube->comments().push_back("graded on a stage screenshot");
    f.purpose = p;
    return f;
}

} // namespace

TEST(PurposeTag, NamesAndTextRoundTrip) {
    for (LutPurpose p : {LutPurpose::Raw, LutPurpose::Smash}) {
        EXPECT_EQ(parseLutPurpose(toString(p)), p);
        EXPECT_EQ(purposeInText(purposeTag(p)), p);
        EXPECT_EQ(purposeInText("made by lutkit\n  " + purposeTag(p) + "  (the game's)\n"), p);
    }
    EXPECT_EQ(purposeInText("no tag here"), std::nullopt);
    EXPECT_EQ(purposeInText("LUTKIT_PURPOSEFUL smash"), std::nullopt);
    EXPECT_THROW((void)purposeInText("LUTKIT_PURPOSE game"), Error);
    EXPECT_THROW((void)purposeInText("LUTKIT_PURPOSE raw\nLUTKIT_PURPOSE smash"), Error);
    // the decision: given, then the file, then the assumption
    EXPECT_EQ(decidePurpose(LutPurpose::Smash, false, std::nullopt).source, PurposeSource::File);
    EXPECT_EQ(decidePurpose(LutPurpose::Smash, true, std::nullopt).source, PurposeSource::Format);
    const PurposeDecision given = decidePurpose(LutPurpose::Smash, false, LutPurpose::Raw);
    EXPECT_EQ(given.purpose, LutPurpose::Raw);
    EXPECT_NE(given.text("--in-target").find("the file says smash"), std::string::npos);
    const PurposeDecision assumed = decidePurpose(std::nullopt, false, std::nullopt);
    EXPECT_EQ(assumed.purpose, LutPurpose::Raw);
    EXPECT_NE(assumed.text("--in-target").find("--in-target smash"), std::string::npos);
}

TEST(PurposeTag, CubeSaysItInACommentAndReadsItBack) {
    const std::string dir = workDir();
    for (LutPurpose p : {LutPurpose::Raw, LutPurpose::Smash}) {
        const std::string path = dir + "/" + toString(p) + ".cube";
        formats::writeLut(path, tagged(p));
        const std::string text = fileBytes(path);
        EXPECT_EQ(text.rfind("# " + purposeTag(p) + "\n", 0), 0u) << text.substr(0, 80);
        const LutFile back = formats::readLut(path);
        EXPECT_EQ(back.purpose, p);
        // the tag is not a comment the next write repeats
        ASSERT_EQ(back.cube->comments().size(), 1u);
        EXPECT_EQ(back.cube->comments()[0], "graded on a stage screenshot");
    }
    LutFile untagged;
    untagged.cube = warm(3);
    formats::writeLut(dir + "/none.cube", untagged);
    EXPECT_EQ(fileBytes(dir + "/none.cube").find("LUTKIT_PURPOSE"), std::string::npos);
    EXPECT_EQ(formats::readLut(dir + "/none.cube").purpose, std::nullopt);
    // A 1D-only file keeps it too (its comments are not kept).
    LutFile oneD;
    oneD.shaper = Lut1D(8);
    for (int i = 0; i < 8; ++i)
        oneD.shaper->entries()[static_cast<std::size_t>(i)] = glm::vec3(i / 7.0f);
    oneD.purpose = LutPurpose::Raw;
    formats::writeLut(dir + "/curve.cube", oneD);
    EXPECT_EQ(formats::readLut(dir + "/curve.cube").purpose, LutPurpose::Raw);
}

TEST(PurposeTag, AMalformedTagIsOneLineNamingThePlace) {
    const std::string dir = workDir();
    writeText(dir + "/bad.cube",
              "# a grade\n# LUTKIT_PURPOSE game\nLUT_3D_SIZE 2\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 "
              "1\n1 0 1\n0 1 1\n1 1 1\n");
    try {
        (void)formats::readLut(dir + "/bad.cube");
        FAIL() << "read";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 2);
        EXPECT_EQ(e.column(), 3);
        EXPECT_NE(std::string(e.what()).find("'game' is not a purpose (expected raw or smash)"),
                  std::string::npos)
            << e.what();
    }
    writeText(dir + "/two.cube",
              "# LUTKIT_PURPOSE raw\n# LUTKIT_PURPOSE smash\nLUT_3D_SIZE 2\n0 0 0\n1 0 0\n0 1 "
              "0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n");
    EXPECT_THROW((void)formats::readLut(dir + "/two.cube"), ParseError);
}

// OpenColorIO reads the tagged file as the table it holds: its processor at every lattice point
// gives the entry (the tag is a comment to it).
TEST(PurposeTag, OpenColorIOReadsTheTaggedCube) {
    const std::string dir = workDir();
    const std::string path = dir + "/smash.cube";
    const LutFile f = tagged(LutPurpose::Smash, 5);
    formats::writeLut(path, f);
    const auto cpu = test::ocioFileProcessor(path);
    double worst = 0.0;
    for (int b = 0; b < 5; ++b)
        for (int g = 0; g < 5; ++g)
            for (int r = 0; r < 5; ++r) {
                float px[3] = {r / 4.0f, g / 4.0f, b / 4.0f};
                cpu->applyRGB(px);
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::fabs(double(px[c]) - f.cube->at(r, g, b)[c]));
            }
    EXPECT_LT(worst, 1e-6);
}

// ffmpeg's lut3d filter reads the tagged file and gives the picture it gives with the same table
// untagged (and not the picture unchanged).
TEST(PurposeTag, FfmpegReadsTheTaggedCube) {
    if (!haveProgram("ffmpeg"))
        GTEST_SKIP() << "ffmpeg is not installed";
    const std::string dir = workDir();
    LutFile f = tagged(LutPurpose::Smash, 9);
    formats::writeLut(dir + "/tagged.cube", f);
    f.purpose.reset();
    formats::writeLut(dir + "/plain.cube", f);
    ASSERT_NE(fileBytes(dir + "/tagged.cube"), fileBytes(dir + "/plain.cube"));
    auto run = [&](const std::string& lut, const std::string& out) {
        return runCommand("ffmpeg -v error -y -f lavfi -i testsrc2=size=64x48:rate=1 -frames:v 1 "
                          "-vf \"format=rgb24,lut3d=file='" +
                          lut + "'\" -f rawvideo -pix_fmt rgb24 '" + out + "'");
    };
    const auto a = run(dir + "/tagged.cube", dir + "/tagged.rgb");
    ASSERT_EQ(a.exitCode, 0) << a.err;
    const auto b = run(dir + "/plain.cube", dir + "/plain.rgb");
    ASSERT_EQ(b.exitCode, 0) << b.err;
    const auto c = runCommand("ffmpeg -v error -y -f lavfi -i testsrc2=size=64x48:rate=1 "
                              "-frames:v 1 -vf format=rgb24 -f rawvideo -pix_fmt rgb24 '" +
                              dir + "/none.rgb'");
    ASSERT_EQ(c.exitCode, 0) << c.err;
    EXPECT_EQ(fileBytes(dir + "/tagged.rgb").size(), 64u * 48u * 3u);
    EXPECT_EQ(fileBytes(dir + "/tagged.rgb"), fileBytes(dir + "/plain.rgb"));
    EXPECT_NE(fileBytes(dir + "/tagged.rgb"), fileBytes(dir + "/none.rgb"));
}

// LUT images say it in their description: PNG (8 and 16-bit, a tEXt "Description"), TIFF
// (ImageDescription), OpenEXR (its comments attribute); oiiotool, another reader, sees it.
TEST(PurposeTag, LutImagesSayItInTheirDescription) {
    const std::string dir = workDir();
    struct Case {
        const char* name;
        int bits;
    };
    for (const Case& c :
         {Case{"s8.png", 8}, Case{"s16.png", 16}, Case{"s.tif", 16}, Case{"s.exr", 32}}) {
        SCOPED_TRACE(c.name);
        const std::string path = dir + "/" + c.name;
        FormatOptions o;
        o.bitDepth = c.bits;
        LutFile f = tagged(LutPurpose::Smash, 4);
        formats::writeLut(path, f, o);
        const LutFile back = formats::readLut(path);
        EXPECT_EQ(back.purpose, LutPurpose::Smash);
        EXPECT_EQ(back.format, "strip");
        if (haveProgram("oiiotool")) {
            const auto info = runCommand("oiiotool --info -v '" + path + "'");
            EXPECT_NE(info.out.find("LUTKIT_PURPOSE smash"), std::string::npos) << info.out;
        }
        f.purpose = LutPurpose::Raw;
        formats::writeLut(path, f, o);
        EXPECT_EQ(formats::readLut(path).purpose, LutPurpose::Raw);
    }
    // Hald images too; an untagged image says nothing.
    FormatOptions hald;
    hald.layout = LutLayout::Hald;
    formats::writeLut(dir + "/h.png", tagged(LutPurpose::Raw, 4), hald);
    EXPECT_EQ(formats::readLut(dir + "/h.png").purpose, LutPurpose::Raw);
    LutFile plain;
    plain.cube = warm(4);
    formats::writeLut(dir + "/plain.png", plain);
    EXPECT_EQ(formats::readLut(dir + "/plain.png").purpose, std::nullopt);
}

// A .nutexb is the game's LUT by its format; the formats OpenColorIO writes with a description
// (.clf, .ctf) or a metadata block (.csp) keep the tag, read back through OpenColorIO.
TEST(PurposeTag, NutexbIsTheGamesAndOcioFormatsKeepTheTag) {
    const std::string dir = workDir();
    LutFile f;
    f.cube = warm(16);
    formats::writeLut(dir + "/g.nutexb", f);
    EXPECT_EQ(formats::readLut(dir + "/g.nutexb").purpose, LutPurpose::Smash);
    for (const char* ext : {".clf", ".ctf", ".csp"}) {
        SCOPED_TRACE(ext);
        const std::string path = dir + "/g" + ext;
        formats::writeLut(path, tagged(LutPurpose::Smash, 5));
        EXPECT_NE(fileBytes(path).find("LUTKIT_PURPOSE smash"), std::string::npos);
        EXPECT_EQ(formats::readLut(path).purpose, LutPurpose::Smash);
    }
}
