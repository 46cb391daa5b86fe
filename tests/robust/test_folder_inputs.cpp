// SPDX-License-Identifier: Apache-2.0
// Issue 41: `apply DIR/` and `convert DIR/` skipped a FIFO, a symbolic link loop and a link to
// /dev/zero among the folder's files without a word (exit 0). Each entry named like an input
// that is no regular file is now said, one line each: which file and why; the regular files are
// still written, and a folder left with nothing to read says why.
#include "RobustSupport.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <sys/stat.h>

namespace fs = std::filesystem;
using namespace lut::robust;
using lut::test::runCli;
using lut::test::shellQuoted;
using ::testing::HasSubstr;

namespace {

// DIR/a.EXT (a copy of `file`) and the entries that are no regular file, named *.EXT.
void populate(const std::string& dir, const std::string& ext, const std::string& bytes) {
    fs::create_directories(dir);
    writeBytes(dir + "/a" + ext, bytes);
    ASSERT_EQ(::mkfifo((dir + "/fifo" + ext).c_str(), 0600), 0);
    fs::create_symlink("loop" + ext, dir + "/loop" + ext);
    fs::create_symlink("/dev/zero", dir + "/zero" + ext);
    fs::create_symlink("missing" + ext, dir + "/dangling" + ext);
    fs::create_directories(dir + "/sub" + ext);
}

void expectOneLineEach(const std::string& err, const std::string& dir, const std::string& ext) {
    for (const auto& [name, why] : std::vector<std::pair<std::string, std::string>>{
             {"fifo", "is a FIFO, not a regular file; skipped"},
             {"loop", "cannot open: Too many levels of symbolic links; skipped"},
             {"zero", "is a character device, not a regular file; skipped"},
             {"dangling", "cannot open: No such file or directory; skipped"},
             {"sub", "is a directory, not a regular file; skipped"}}) {
        const std::string line = "lutkit: warning: " + dir + "/" + name + ext + ": " + why + "\n";
        EXPECT_THAT(err, HasSubstr(line));
        EXPECT_EQ(err.find(line), err.rfind(line)) << "said twice: " << line;
    }
}

TEST(FolderInputs, ApplySaysWhichEntriesItSkipsAndWhy) {
    const std::string dir = lut::test::tempDir();
    ASSERT_EQ(lut::test::runCommand("oiiotool --pattern constant:color=0.2,0.4,0.6 8x8 3 -d uint8 "
                                    "-o " +
                                    shellQuoted(dir + "/a.png"))
                  .exitCode,
              0);
    populate(dir + "/in", ".png", fileBytes(dir + "/a.png"));
    const auto r = runCli("apply --lut builtin:neutral " + shellQuoted(dir + "/in/") + " -o " +
                          shellQuoted(dir + "/out/"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(listDir(dir + "/out"), std::vector<std::string>{"a.png"});
    expectOneLineEach(r.err, dir + "/in", ".png");
}

TEST(FolderInputs, ConvertSaysWhichEntriesItSkipsAndWhy) {
    const std::string dir = lut::test::tempDir();
    populate(dir + "/in", ".cube", neutralCube(2));
    const auto r = runCli("convert " + shellQuoted(dir + "/in/") + " -o " +
                          shellQuoted(dir + "/out/") + " --format 3dl");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(listDir(dir + "/out"), std::vector<std::string>{"a.3dl"});
    expectOneLineEach(r.err, dir + "/in", ".cube");
}

TEST(FolderInputs, AFolderOfNothingReadableSaysWhy) {
    const std::string dir = lut::test::tempDir();
    fs::create_directories(dir + "/in");
    ASSERT_EQ(::mkfifo((dir + "/in/only.png").c_str(), 0600), 0);
    const auto r = runCli("apply --lut builtin:neutral " + shellQuoted(dir + "/in/") + " -o " +
                          shellQuoted(dir + "/out/"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("folder holds no image files (.png .jpg .tif .exr .dpx ...) to "
                                 "read (" +
                                 dir + "/in/only.png: is a FIFO, not a regular file; skipped)"));
}

} // namespace
