// SPDX-License-Identifier: Apache-2.0
// Issue 17, problem 2: no command writes over any of its inputs, through one check
// (lut::checkNotOverwritingInputs): the same path however spelled, a symbolic link, a hard link,
// a path through a linked folder. Before, only the first input was compared with the output:
// extract wrote over its --original-lut and fit over its second image ("after") through a link.
#include "RobustSupport.h"

#include "lut/Error.h"
#include "lut/io/ProtectInputs.h"

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using namespace lut::robust;
using lut::test::runCli;
using ::testing::HasSubstr;

namespace {

using lut::test::shellQuoted;

std::string refusal(const std::function<void()>& fn) {
    try {
        fn();
    } catch (const lut::Error& e) {
        return e.what();
    }
    return "";
}

void writeGreyPng(const std::string& path, int w, int h) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    std::vector<unsigned char> px(static_cast<std::size_t>(w) * h * 3);
    for (std::size_t i = 0; i < px.size(); ++i)
        px[i] = static_cast<unsigned char>(60 + (i * 7) % 120);
    ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
    out->close();
}

TEST(ProtectInputs, EverySpellingOfAnInputIsRefused) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/a.cube", "a");
    writeBytes(dir + "/b.cube", "b");
    fs::create_directories(dir + "/sub");
    fs::create_hard_link(dir + "/b.cube", dir + "/hard.cube");
    fs::create_symlink("b.cube", dir + "/sym.cube");
    fs::create_directory_symlink(dir, dir + "/sub/up");
    const std::vector<std::string> inputs = {dir + "/a.cube", "-", "", dir + "/b.cube"};
    for (const std::string& out :
         {dir + "/b.cube", dir + "/./b.cube", dir + "/sub/../b.cube", dir + "/hard.cube",
          dir + "/sym.cube", dir + "/sub/up/b.cube", dir + "/a.cube"}) {
        SCOPED_TRACE(out);
        const std::string msg = refusal([&] { lut::checkNotOverwritingInputs(out, inputs); });
        EXPECT_THAT(msg, HasSubstr(std::string(out) + ": output is the same file as input "));
        EXPECT_THAT(msg, HasSubstr("refusing to overwrite it"));
    }
    // Not yet existing outputs: only the same path can match.
    EXPECT_EQ(refusal([&] { lut::checkNotOverwritingInputs(dir + "/new.cube", inputs); }), "");
    EXPECT_THAT(
        refusal([&] { lut::checkNotOverwritingInputs(dir + "/sub/../x.cube", {dir + "/x.cube"}); }),
        HasSubstr("output is the same file as input"));
    EXPECT_EQ(refusal([&] { lut::checkNotOverwritingInputs(dir + "/c.cube", {}); }), "");
}

TEST(ProtectInputs, ExtractNeverWritesOverItsOriginalLut) {
    const std::string dir = lut::test::tempDir();
    writeGreyPng(dir + "/shot.png", 400, 300);
    writeBytes(dir + "/orig.cube", neutralCube(3));
    fs::create_hard_link(dir + "/orig.cube", dir + "/orig-hard.cube");
    fs::create_symlink("orig.cube", dir + "/orig-sym.cube");
    const std::string original = fileBytes(dir + "/orig.cube");
    auto r =
        runCli("embed " + shellQuoted(dir + "/shot.png") + " " + shellQuoted(dir + "/edited.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* out : {"orig.cube", "orig-hard.cube", "orig-sym.cube"}) {
        SCOPED_TRACE(out);
        r = runCli("extract " + shellQuoted(dir + "/edited.png") + " " +
                   shellQuoted(dir + "/" + std::string(out)) + " --target smash --original-lut " +
                   shellQuoted(dir + "/orig.cube"));
        EXPECT_EQ(r.exitCode, 1) << r.out;
        EXPECT_THAT(r.err, HasSubstr(std::string(out) + ": output is the same file as input " +
                                     dir + "/orig.cube"));
        EXPECT_EQ(fileBytes(dir + "/orig.cube"), original);
    }
    // And it still works into a new file.
    r = runCli("extract " + shellQuoted(dir + "/edited.png") + " " +
               shellQuoted(dir + "/new.cube") + " --target smash --original-lut " +
               shellQuoted(dir + "/orig.cube"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST(ProtectInputs, FitNeverWritesOverEitherImage) {
    const std::string dir = lut::test::tempDir();
    writeGreyPng(dir + "/before.png", 64, 48);
    writeGreyPng(dir + "/after.png", 64, 48);
    fs::create_hard_link(dir + "/after.png", dir + "/after-hard.png");
    fs::create_symlink("after.png", dir + "/after-sym.png");
    const std::string after = fileBytes(dir + "/after.png");
    for (const char* out : {"before.png", "after.png", "after-hard.png", "after-sym.png"}) {
        SCOPED_TRACE(out);
        const auto r = runCli("fit " + shellQuoted(dir + "/before.png") + " " +
                              shellQuoted(dir + "/after.png") + " " +
                              shellQuoted(dir + "/" + std::string(out)) + " --size 4");
        EXPECT_EQ(r.exitCode, 1);
        EXPECT_THAT(r.err, HasSubstr(std::string(out) + ": output is the same file as input "));
        EXPECT_EQ(fileBytes(dir + "/after.png"), after);
    }
}

TEST(ProtectInputs, ConvertAndEmbedThroughALinkedFolder) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/a.cube", neutralCube(2));
    writeGreyPng(dir + "/shot.png", 400, 300);
    fs::create_directory_symlink(dir, dir + "/link");
    const std::string cube = fileBytes(dir + "/a.cube"), shot = fileBytes(dir + "/shot.png");
    auto r =
        runCli("convert " + shellQuoted(dir + "/a.cube") + " " + shellQuoted(dir + "/link/a.cube"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("output is the same file as input"));
    r = runCli("embed " + shellQuoted(dir + "/shot.png") + " " +
               shellQuoted(dir + "/link/shot.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("output is the same file as input"));
    EXPECT_EQ(fileBytes(dir + "/a.cube"), cube);
    EXPECT_EQ(fileBytes(dir + "/shot.png"), shot);
}

} // namespace
