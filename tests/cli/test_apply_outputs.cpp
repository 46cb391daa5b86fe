// SPDX-License-Identifier: Apache-2.0
// Where apply and preview write, and what they never touch (issue 13): inputs are positional,
// the output is -o; an existing output is replaced only with -y; -n skips; - is standard input
// and output; special files are written in place; frame sequences; no command writes over any
// of its inputs, the LUT included; an interrupted batch leaves no partial output.
#include "CliTestSupport.h"
#include "TestPaths.h"

#include "lut/formats/ImageIO.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace lut;
using namespace lut::test;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

using lut::test::shellQuoted;

using lut::test::fileBytes;

// A darkening 2^3 .cube: every output value is half the input (exact in 8 bits for even codes).
std::string writeHalvingCube(const std::string& dir) {
    const std::string path = dir + "/half.cube";
    std::ofstream f(path);
    f << "LUT_3D_SIZE 2\n";
    for (int b = 0; b < 2; ++b)
        for (int g = 0; g < 2; ++g)
            for (int r = 0; r < 2; ++r)
                f << 0.5 * r << " " << 0.5 * g << " " << 0.5 * b << "\n";
    return path;
}

void writePng(const std::string& path, int seed, int w = 16, int h = 8) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c)
                img.pixel(x, y)[c] =
                    static_cast<float>(((x * 16 + y * 2 + c * 40 + seed * 10) % 128) * 2 / 255.0);
    formats::writeImage(path, img, formats::ImageWriteOptions(8, false, false));
}

// Every 8-bit value of `out` is half the value of `in` (the LUT above, exact on even codes).
void expectHalved(const std::string& in, const std::string& out) {
    const auto a = formats::readImage(in);
    const auto b = formats::readImage(out);
    ASSERT_EQ(a.image.width(), b.image.width());
    for (int y = 0; y < a.image.height(); ++y)
        for (int x = 0; x < a.image.width(); ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(std::lround(b.image.pixel(x, y)[c] * 255.0),
                          std::lround(a.image.pixel(x, y)[c] * 255.0) / 2)
                    << out << " " << x << "," << y;
}

// Runs a shell command line (for pipes and redirections); returns the exit code.
int sh(const std::string& line) {
    const int status = std::system(("cd /tmp && " + line).c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

const std::string kLutkit = std::string("'") + LUTKIT_CLI + "'";

} // namespace

TEST(ApplyOutputs, TwoInputsNeverMeanWriteTheSecond) {
    const std::string dir = workDir();
    const std::string lut = writeHalvingCube(dir);
    writePng(dir + "/a.png", 1);
    writePng(dir + "/b.png", 2);
    const std::string before = fileBytes(dir + "/b.png");
    for (const char* cmd : {"apply --lut ", "preview --lut "}) {
        const RunResult r = runCli(std::string(cmd) + shellQuoted(lut) + " " +
                                   shellQuoted(dir + "/a.png") + " " + shellQuoted(dir + "/b.png"));
        EXPECT_EQ(r.exitCode, 2) << cmd;
        EXPECT_THAT(r.err, HasSubstr("name the output with -o")) << r.err;
        EXPECT_EQ(fileBytes(dir + "/b.png"), before) << cmd << "wrote over its second input";
    }
    // Several inputs and a file name: refused, and no folder named like the file appears.
    const RunResult r =
        runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/a.png") + " " +
               shellQuoted(dir + "/b.png") + " -o " + shellQuoted(dir + "/graded.exr"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("-o DIR/"));
    EXPECT_FALSE(fs::exists(dir + "/graded.exr"));
}

TEST(ApplyOutputs, AnExistingOutputIsReplacedOnlyWithY) {
    const std::string dir = workDir();
    const std::string lut = writeHalvingCube(dir);
    writePng(dir + "/in.png", 3);
    writePng(dir + "/out.png", 4);
    const std::string before = fileBytes(dir + "/out.png");
    for (const char* cmd : {"apply --lut ", "preview --no-bloom --lut "}) {
        RunResult r = runCli(std::string(cmd) + shellQuoted(lut) + " " +
                             shellQuoted(dir + "/in.png") + " -o " + shellQuoted(dir + "/out.png"));
        EXPECT_EQ(r.exitCode, 1) << cmd;
        EXPECT_THAT(r.err, HasSubstr("out.png: already exists; pass -y/--overwrite"));
        EXPECT_EQ(fileBytes(dir + "/out.png"), before);
        r = runCli(std::string(cmd) + shellQuoted(lut) + " " + shellQuoted(dir + "/in.png") +
                   " -o " + shellQuoted(dir + "/out.png") + " -n");
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(fileBytes(dir + "/out.png"), before);
    }
    const RunResult r =
        runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/in.png") + " -o " +
               shellQuoted(dir + "/out.png") + " -y");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    expectHalved(dir + "/in.png", dir + "/out.png");
    // The LUT commands follow the same rule.
    const std::string cube = fileBytes(lut);
    std::ofstream(dir + "/n.cube") << "old";
    EXPECT_EQ(runCli("neutral " + shellQuoted(dir + "/n.cube")).exitCode, 1);
    EXPECT_EQ(fileBytes(dir + "/n.cube"), "old");
    EXPECT_EQ(runCli("convert " + shellQuoted(lut) + " " + shellQuoted(dir + "/n.cube")).exitCode,
              1);
    EXPECT_EQ(fileBytes(dir + "/n.cube"), "old");
    EXPECT_EQ(
        runCli("convert " + shellQuoted(lut) + " " + shellQuoted(dir + "/n.cube") + " -y").exitCode,
        0);
    EXPECT_NE(fileBytes(dir + "/n.cube"), "old");
}

TEST(ApplyOutputs, NoClobberSkipsExistingFilesInABatch) {
    const std::string dir = workDir();
    const std::string lut = writeHalvingCube(dir);
    fs::create_directories(dir + "/in");
    fs::create_directories(dir + "/out");
    for (int i = 0; i < 3; ++i)
        writePng(dir + "/in/f" + std::to_string(i) + ".png", i);
    writePng(dir + "/out/f1.png", 9);
    const std::string kept = fileBytes(dir + "/out/f1.png");
    RunResult r = runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/in") +
                         " -o " + shellQuoted(dir + "/out"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("-n/--no-clobber"));
    EXPECT_FALSE(fs::exists(dir + "/out/f0.png")) << "nothing is written before the check";
    r = runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/in") + " -o " +
               shellQuoted(dir + "/out") + " -n");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(fileBytes(dir + "/out/f1.png"), kept);
    expectHalved(dir + "/in/f0.png", dir + "/out/f0.png");
    expectHalved(dir + "/in/f2.png", dir + "/out/f2.png");
    EXPECT_THAT(r.err, HasSubstr("2 of 3 files written"));
    EXPECT_THAT(r.err, HasSubstr("1 skipped"));
    // An input folder without images is an error, not a silent success.
    fs::create_directories(dir + "/empty");
    r = runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/empty") + " -o " +
               shellQuoted(dir + "/o2/"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("folder holds no image files"));
}

TEST(ApplyOutputs, TheLutAndEveryInputAreProtected) {
    const std::string dir = workDir();
    const std::string lut = writeHalvingCube(dir);
    const std::string cube = fileBytes(lut);
    writePng(dir + "/img.png", 5);
    fs::create_symlink("half.cube", dir + "/link.cube");
    fs::create_hard_link(lut, dir + "/hard.cube");
    for (const char* out : {"/half.cube", "/link.cube", "/hard.cube"})
        for (const char* cmd : {"apply --lut ", "preview --lut "}) {
            SCOPED_TRACE(std::string(cmd) + out);
            const RunResult r =
                runCli(std::string(cmd) + shellQuoted(lut) + " " + shellQuoted(dir + "/img.png") +
                       " -o " + shellQuoted(dir + out) + " -y --format png");
            EXPECT_EQ(r.exitCode, 1);
            EXPECT_THAT(r.err, HasSubstr("output is the same file as input"));
            EXPECT_EQ(fileBytes(lut), cube);
        }
    // --original-lut too, and in batch mode (the LUT's folder as the output folder).
    RunResult r =
        runCli("preview --from-screenshot --original-lut " + shellQuoted(lut) + " " +
               shellQuoted(dir + "/img.png") + " -o " + shellQuoted(dir + "/half.cube") + " -y");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(fileBytes(lut), cube);
    fs::create_directories(dir + "/batch");
    writePng(dir + "/batch/x.png", 6);
    fs::copy_file(dir + "/batch/x.png", dir + "/batch/half.png");
    ASSERT_EQ(runCli("neutral " + shellQuoted(dir + "/half.png")).exitCode, 0); // a LUT strip
    const std::string strip = fileBytes(dir + "/half.png");
    r = runCli("apply --lut " + shellQuoted(dir + "/half.png") + " " + shellQuoted(dir + "/batch") +
               " -o " + shellQuoted(dir + "/") + " -y");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("output is the same file as input"));
    EXPECT_EQ(fileBytes(dir + "/half.png"), strip);
    EXPECT_TRUE(fs::exists(dir + "/x.png")) << "the other file of the batch is written";
}

TEST(ApplyOutputs, StandardInputAndOutput) {
    const std::string dir = workDir();
    const std::string lut = writeHalvingCube(dir);
    writePng(dir + "/in.png", 7);
    ASSERT_EQ(sh(kLutkit + " apply --lut " + shellQuoted(lut) + " - -o - < " +
                 shellQuoted(dir + "/in.png") + " > " + shellQuoted(dir + "/piped.png")),
              0);
    expectHalved(dir + "/in.png", dir + "/piped.png");
    // Another format on the way out, and a LUT from standard input.
    ASSERT_EQ(sh(kLutkit + " apply --lut - " + shellQuoted(dir + "/in.png") +
                 " -o - --format ppm < " + shellQuoted(lut) + " > " +
                 shellQuoted(dir + "/piped.ppm")),
              0);
    expectHalved(dir + "/in.png", dir + "/piped.ppm");
    EXPECT_EQ(fileBytes(dir + "/piped.ppm").substr(0, 2), "P6");
    // /dev/stdout is written in place: a redirect still receives the image.
    ASSERT_EQ(sh(kLutkit + " apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/in.png") +
                 " -o /dev/stdout --format png > " + shellQuoted(dir + "/devstdout.png")),
              0);
    expectHalved(dir + "/in.png", dir + "/devstdout.png");
    // LUTs: convert to and from standard output.
    ASSERT_EQ(sh(kLutkit + " convert " + shellQuoted(lut) + " - --format cube > " +
                 shellQuoted(dir + "/c.cube") + " 2>/dev/null"),
              0);
    EXPECT_THAT(fileBytes(dir + "/c.cube"), HasSubstr("LUT_3D_SIZE 2"));
}

TEST(ApplyOutputs, SpecialFilesAreWrittenInPlace) {
    const std::string dir = workDir();
    const std::string lut = writeHalvingCube(dir);
    writePng(dir + "/in.png", 8);
    RunResult r = runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/in.png") +
                         " -o /dev/null");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    struct stat st {};
    ASSERT_EQ(::stat("/dev/null", &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode)) << "/dev/null was replaced";
    // A FIFO: read by another process while lutkit writes into it, and still a FIFO after.
    const std::string fifo = dir + "/pipe.png";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::thread reader(
        [&] { sh("cat " + shellQuoted(fifo) + " > " + shellQuoted(dir + "/from_fifo.png")); });
    r = runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/in.png") + " -o " +
               shellQuoted(fifo));
    reader.join();
    EXPECT_EQ(r.exitCode, 0) << r.err;
    ASSERT_EQ(::stat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode));
    expectHalved(dir + "/in.png", dir + "/from_fifo.png");
    // A FIFO as an image input is refused at once (no hang), "-" is the way to stream one in.
    r = runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(fifo) + " -o " +
               shellQuoted(dir + "/x.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("is a FIFO, not a regular file"));
}

TEST(ApplyOutputs, FrameSequencesWithGaps) {
    const std::string dir = workDir();
    const std::string lut = writeHalvingCube(dir);
    for (int f : {1, 2, 3, 5})
        writePng(dir + "/shot.000" + std::to_string(f) + ".png", f);
    RunResult r =
        runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/shot.%04d.png") +
               " -o " + shellQuoted(dir + "/out.####.png"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr("frames 4 of"));
    for (int f : {1, 2, 3, 5})
        expectHalved(dir + "/shot.000" + std::to_string(f) + ".png",
                     dir + "/out.000" + std::to_string(f) + ".png");
    EXPECT_FALSE(fs::exists(dir + "/out.0004.png"));
    // --frames asks for frame 4: it is a failure, the others are written.
    r = runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/shot.#.png") +
               " --frames 2-5 -o " + shellQuoted(dir + "/o2.%04d.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("frame 4 is missing"));
    EXPECT_TRUE(fs::exists(dir + "/o2.0005.png"));
    EXPECT_FALSE(fs::exists(dir + "/o2.0001.png"));
    // A folder of frames into a pattern: numbered from 1 in name order.
    fs::create_directories(dir + "/plates");
    writePng(dir + "/plates/a.png", 1);
    writePng(dir + "/plates/b.png", 2);
    r = runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/plates") + " -o " +
               shellQuoted(dir + "/seq_%02d.png"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    expectHalved(dir + "/plates/b.png", dir + "/seq_02.png");
    EXPECT_EQ(runCli("apply --lut " + shellQuoted(lut) + " " + shellQuoted(dir + "/shot.0001.png") +
                     " --frames 1-3 -o " + shellQuoted(dir + "/x.png"))
                  .exitCode,
              2);
}

TEST(ApplyOutputs, AnInterruptedBatchLeavesNoPartialOutput) {
    const std::string dir = workDir();
    const std::string lut = writeHalvingCube(dir);
    fs::create_directories(dir + "/in");
    for (int i = 0; i < 24; ++i)
        writePng(dir + "/in/f" + std::to_string(100 + i) + ".png", i, 512, 256);
    for (int delayMs : {30, 80, 160}) {
        fs::remove_all(dir + "/out");
        const pid_t pid = ::fork();
        if (pid == 0) {
            const int null = ::open("/dev/null", O_WRONLY);
            ::dup2(null, 1);
            ::dup2(null, 2);
            ::execl(LUTKIT_CLI, "lutkit", "apply", "--lut", lut.c_str(), (dir + "/in").c_str(),
                    "-o", (dir + "/out/").c_str(), "--threads", "2", static_cast<char*>(nullptr));
            ::_exit(127);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(delayMs));
        ::kill(pid, SIGINT);
        int status = 0;
        ::waitpid(pid, &status, 0);
        // Every visible file is a whole graded frame; half-written ones were never visible, and
        // the temporary files in flight were removed. (A slow start, e.g. under a sanitizer, may
        // be interrupted before the folder exists: then nothing was written.)
        if (!fs::exists(dir + "/out"))
            continue;
        for (const auto& e : fs::directory_iterator(dir + "/out")) {
            const std::string name = e.path().filename().string();
            EXPECT_NE(name[0], '.') << "a temporary file was left: " << name;
            if (name[0] != '.')
                expectHalved(dir + "/in/" + name, e.path().string());
        }
    }
}
