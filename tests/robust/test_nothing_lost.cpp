// SPDX-License-Identifier: Apache-2.0
// Nothing lost: a failed command leaves an existing output untouched and no temporary files; no
// command overwrites its own input (same path, symlink or hard link); a kill -9 in the middle of
// a write leaves the target either as it was or complete.
#include "RobustSupport.h"
#include "TestPaths.h"

#include "lut/Error.h"
#include "lut/formats/Registry.h"

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace lut::robust;
using lut::test::runCli;
using ::testing::HasSubstr;

namespace {

using lut::test::shellQuoted;

void writePng(const std::string& path, int w, int h, float r, float g, float b) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    std::vector<float> px(static_cast<std::size_t>(w) * h * 3);
    for (std::size_t i = 0; i < px.size(); i += 3) {
        px[i] = r;
        px[i + 1] = g;
        px[i + 2] = b;
    }
    ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    out->close();
}

const std::string kGood = neutralCube(2);
const std::string kDarkening = "LUT_3D_SIZE 2\n" + std::string("0 0 0\n") +
                               "0.5 0 0\n0 0.5 0\n0.5 0.5 0\n0 0 0.5\n"
                               "0.5 0 0.5\n0 0.5 0.5\n0.5 0.5 0.5\n";

TEST(NothingLost, ReadErrorLeavesExistingOutputUntouchedAndNoTempFiles) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/bad.cube", "LUT_3D_SIZE 2\n0 0 0\n");
    writeBytes(dir + "/out.cube", kGood);
    const auto r = runCli("convert " + shellQuoted(dir + "/bad.cube") + " " +
                          shellQuoted(dir + "/out.cube") + " -y");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("bad.cube:3:1: expected 8 data rows for LUT_3D_SIZE 2, found 1"));
    EXPECT_EQ(fileBytes(dir + "/out.cube"), kGood);
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"bad.cube", "out.cube"}));
}

TEST(NothingLost, WriteErrorLeavesExistingOutputUntouchedAndNoTempFiles) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/in.cube", kDarkening);
    writePng(dir + "/out.png", 64, 8, 0.25f, 0.5f, 0.75f);
    const std::string before = fileBytes(dir + "/out.png");
    // PNG cannot hold float: refused by the writer, after the output was chosen.
    auto r = runCli("convert " + shellQuoted(dir + "/in.cube") + " " +
                    shellQuoted(dir + "/out.png") + " --bit-depth 32 -y");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("out.png: PNG stores 8 or 16 bits per channel, not float"));
    EXPECT_EQ(fileBytes(dir + "/out.png"), before);
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"in.cube", "out.png"}));

    // A folder is never replaced by a file, even with -y: refused before anything is written.
    fs::create_directories(dir + "/taken.cube/inside");
    r = runCli("convert " + shellQuoted(dir + "/in.cube") + " " + shellQuoted(dir + "/taken.cube") +
               " -y");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("taken.cube: is a folder, not a file"));
    EXPECT_TRUE(fs::is_directory(dir + "/taken.cube/inside"));
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"in.cube", "out.png", "taken.cube"}));

    // The library path: a writer error through the registry keeps the folder as it was.
    lut::LutFile empty;
    EXPECT_THROW(lut::formats::writeLut(dir + "/out.png", empty), lut::Error);
    EXPECT_EQ(fileBytes(dir + "/out.png"), before);
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"in.cube", "out.png", "taken.cube"}));
}

TEST(NothingLost, ConvertRefusesToOverwriteItsInput) {
    const std::string dir = lut::test::tempDir();
    const std::string in = dir + "/a.cube";
    writeBytes(in, kDarkening);
    fs::create_hard_link(in, dir + "/hard.cube");
    fs::create_symlink("a.cube", dir + "/sym.cube");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {in, "a.cube: output is the same file as input "},
        {dir + "/./a.cube", "a.cube: output is the same file as input "},
        {dir + "/hard.cube", "hard.cube: output is the same file as input "},
        {dir + "/sym.cube", "sym.cube: output is the same file as input "},
    };
    for (const auto& [out, message] : cases) {
        SCOPED_TRACE(out);
        const auto r = runCli("convert " + shellQuoted(in) + " " + shellQuoted(out));
        EXPECT_EQ(r.exitCode, 1);
        EXPECT_THAT(r.err, HasSubstr(message));
        EXPECT_THAT(r.err, HasSubstr("refusing to overwrite it"));
        EXPECT_EQ(fileBytes(in), kDarkening);
    }
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"a.cube", "hard.cube", "sym.cube"}));
}

TEST(NothingLost, ImageCommandsRefuseToOverwriteTheirInput) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/dark.cube", kDarkening);
    writePng(dir + "/img.png", 64, 48, 0.5f, 0.4f, 0.3f);
    writePng(dir + "/other.png", 64, 48, 0.2f, 0.4f, 0.3f);
    fs::create_hard_link(dir + "/img.png", dir + "/hard.png");
    const std::string img = fileBytes(dir + "/img.png");
    const std::string d = shellQuoted(dir) + "/";
    const std::vector<std::string> commands = {
        "apply --lut " + d + "dark.cube " + d + "img.png -o " + d + "img.png -y",
        "apply --lut " + d + "dark.cube " + d + "img.png -o " + d + "hard.png -y",
        "apply --lut " + d + "dark.cube " + d + "img.png -o " + d + ". -y",
        "preview --lut " + d + "dark.cube " + d + "img.png -o " + d + "img.png -y",
        "fit " + d + "img.png " + d + "other.png " + d + "img.png",
        "fit " + d + "other.png " + d + "img.png " + d + "hard.png",
        "extract " + d + "img.png " + d + "img.png",
        "embed " + d + "img.png " + d + "img.png",
        "embed " + d + "img.png " + d + "hard.png",
    };
    for (const auto& c : commands) {
        SCOPED_TRACE(c);
        const auto r = runCli(c);
        EXPECT_EQ(r.exitCode, 1);
        EXPECT_THAT(r.err, HasSubstr("output is the same file as input"));
        EXPECT_EQ(fileBytes(dir + "/img.png"), img);
    }
}

// Starts `lutkit args...` with output to /dev/null; returns its pid.
pid_t spawnCli(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    std::vector<std::string> store = args;
    store.insert(store.begin(), "lutkit");
    for (auto& a : store)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int null = ::open("/dev/null", O_WRONLY);
        ::dup2(null, 1);
        ::dup2(null, 2);
        ::execv(LUTKIT_CLI, argv.data());
        ::_exit(127);
    }
    return pid;
}

TEST(NothingLost, KillDuringAWriteLeavesTheOldOrTheCompleteFile) {
    const std::string dir = lut::test::tempDir();
    const std::string target = dir + "/big.cube";
    writeBytes(target, kGood);
    int oldSeen = 0, newSeen = 0;
    // Kill at growing delays: early ones land while the table is built, later ones during the
    // write of ~40 MB of text, the last ones may let it finish.
    for (int delayMs : {1, 5, 20, 50, 100, 200, 350, 500, 800, 1200}) {
        SCOPED_TRACE(delayMs);
        const pid_t pid = spawnCli({"neutral", "--size", "128", "-y", target});
        ASSERT_GT(pid, 0);
        std::this_thread::sleep_for(std::chrono::milliseconds(delayMs));
        ::kill(pid, SIGKILL);
        int status = 0;
        ::waitpid(pid, &status, 0);
        ASSERT_TRUE(fs::exists(target)) << "the old file vanished";
        if (fileBytes(target) == kGood) {
            ++oldSeen;
            continue;
        }
        // Not the old file: then it must be the whole new one.
        const lut::LutFile f = lut::formats::readLut(target);
        ASSERT_TRUE(f.cube);
        EXPECT_EQ(f.cube->size(), 128);
        EXPECT_TRUE(f.cube->isIdentity(1e-6f));
        ++newSeen;
        writeBytes(target, kGood); // start the next round from the old file again
    }
    EXPECT_EQ(oldSeen + newSeen, 10);
    // Only hidden temporary files of killed writers may remain besides the target, never a
    // visible partial file.
    for (const auto& name : listDir(dir)) {
        if (name != "big.cube") {
            EXPECT_EQ(name.rfind(".big.tmp", 0), 0u) << name;
        }
    }
    fs::remove_all(dir);
}

} // namespace
