// SPDX-License-Identifier: Apache-2.0
// Issue 17: SIGINT/SIGTERM left hidden temporary files (.f003.tmpNNN.png) and said nothing. Now
// the temporary files in flight are removed, what was finished is listed, and lutkit exits with
// 130 (README "Exit codes"). Each test signals at a moment it has seen (an output or a temporary
// file on the disk), not after a guessed delay.
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
#include <random>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace lut::robust;
using ::testing::HasSubstr;
using ::testing::MatchesRegex;

namespace {

struct Running {
    pid_t pid = -1;
    std::string errPath;
};

// Starts lutkit with stderr to a file, signals at their defaults (a test runner may ignore
// SIGINT for its children).
Running start(const std::vector<std::string>& args, const std::string& errPath) {
    std::vector<std::string> store = args;
    store.insert(store.begin(), "lutkit");
    std::vector<char*> argv;
    for (auto& a : store)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    Running r;
    r.errPath = errPath;
    r.pid = ::fork();
    if (r.pid == 0) {
        ::signal(SIGINT, SIG_DFL);
        ::signal(SIGTERM, SIG_DFL);
        const int null = ::open("/dev/null", O_WRONLY);
        const int err = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(null, 1);
        ::dup2(err, 2);
        ::execv(LUTKIT_CLI, argv.data());
        ::_exit(127);
    }
    return r;
}

int finish(const Running& r) {
    int status = 0;
    ::waitpid(r.pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// Waits (up to 60 s) until pred() holds; false if the process ended first or time ran out.
template <class Pred> bool waitFor(pid_t pid, Pred pred) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < end) {
        if (pred())
            return true;
        int status = 0;
        if (::waitpid(pid, &status, WNOHANG) == pid)
            return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
}

bool hasVisibleFile(const std::string& dir) {
    for (const auto& name : listDir(dir))
        if (name[0] != '.')
            return true;
    return false;
}

bool hasHiddenFile(const std::string& dir) {
    for (const auto& name : listDir(dir))
        if (name[0] == '.')
            return true;
    return false;
}

void writeNoisePng(const std::string& path, int w, int h) {
    std::mt19937 rng(3);
    std::vector<unsigned char> px(static_cast<std::size_t>(w) * h * 3);
    for (auto& v : px)
        v = static_cast<unsigned char>(rng() & 0xFF);
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
    out->close();
}

std::vector<unsigned char> pixels(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in)
        return {};
    const auto& spec = in->spec();
    std::vector<unsigned char> px(static_cast<std::size_t>(spec.width) * spec.height *
                                  spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, px.data()))
        return {};
    return px;
}

std::string lastLine(const std::string& text) {
    std::string t = text;
    while (!t.empty() && t.back() == '\n')
        t.pop_back();
    const auto nl = t.find_last_of('\n');
    return nl == std::string::npos ? t : t.substr(nl + 1);
}

TEST(Interrupts, ABatchStopsListsWhatItFinishedAndLeavesNoTemporaryFile) {
    const std::string dir = lut::test::tempDir();
    fs::create_directories(dir + "/in");
    writeNoisePng(dir + "/in/f00.png", 1920, 1080);
    std::vector<std::string> args = {"apply",     "--lut", dir + "/id.cube", "-o", dir + "/out",
                                     "--threads", "2"};
    writeBytes(dir + "/id.cube", neutralCube(2));
    for (int i = 0; i < 24; ++i) {
        char name[16];
        std::snprintf(name, sizeof name, "f%02d.png", i);
        if (i > 0)
            fs::copy_file(dir + "/in/f00.png", dir + "/in/" + name);
        args.push_back(dir + "/in/" + name);
    }
    fs::create_directories(dir + "/out");
    const auto original = pixels(dir + "/in/f00.png");
    ASSERT_FALSE(original.empty());

    for (int sig : {SIGINT, SIGTERM}) {
        SCOPED_TRACE(sig == SIGINT ? "SIGINT" : "SIGTERM");
        fs::remove_all(dir + "/out");
        fs::create_directories(dir + "/out");
        const Running r = start(args, dir + "/err.txt");
        // Signal once one output is complete and another is being written.
        const bool seen = waitFor(
            r.pid, [&] { return hasVisibleFile(dir + "/out") && hasHiddenFile(dir + "/out"); });
        ASSERT_TRUE(seen) << "the batch ended before it could be interrupted";
        ::kill(r.pid, sig);
        EXPECT_EQ(finish(r), 130);
        const std::string err = fileBytes(dir + "/err.txt");
        const std::string last = lastLine(err);
        EXPECT_THAT(last, MatchesRegex(std::string("lutkit: interrupted \\(") +
                                       (sig == SIGINT ? "SIGINT" : "SIGTERM") +
                                       "\\): [0-9]+ of 24 file\\(s\\) finished \\(.*\\); nothing "
                                       "else was written"))
            << err;
        // Every file there is listed as finished and complete; nothing hidden remains.
        const auto names = listDir(dir + "/out");
        EXPECT_FALSE(names.empty());
        EXPECT_LT(names.size(), 24u);
        for (const auto& name : names) {
            SCOPED_TRACE(name);
            EXPECT_NE(name[0], '.') << "a temporary file survived";
            EXPECT_THAT(last, HasSubstr(dir + "/out/" + name));
            EXPECT_EQ(pixels(dir + "/out/" + name), original); // neutral LUT: the same pixels
        }
    }
}

TEST(Interrupts, ASingleWriteIsRemovedAndTheOldFileKept) {
    const std::string dir = lut::test::tempDir();
    const std::string out = dir + "/big.cube";
    const std::string old = neutralCube(2);
    for (int sig : {SIGINT, SIGTERM}) {
        SCOPED_TRACE(sig == SIGINT ? "SIGINT" : "SIGTERM");
        writeBytes(out, old);
        const Running r = start({"neutral", "-y", "--size", "160", out}, dir + "/err.txt");
        const bool writing = waitFor(r.pid, [&] { return hasHiddenFile(dir); });
        ASSERT_TRUE(writing) << "neutral ended before its temporary file was seen";
        ::kill(r.pid, sig);
        const int code = finish(r);
        const std::string err = fileBytes(dir + "/err.txt");
        if (code == 0) {
            // The rename won the race: then the new file is whole.
            const lut::LutFile f = lut::formats::readLut(out);
            ASSERT_TRUE(f.cube);
            EXPECT_EQ(f.cube->size(), 160);
        } else {
            EXPECT_EQ(code, 130) << err;
            EXPECT_EQ(lastLine(err), std::string("lutkit: interrupted (") +
                                         (sig == SIGINT ? "SIGINT" : "SIGTERM") +
                                         "); unfinished outputs removed");
            EXPECT_EQ(fileBytes(out), old);
        }
        EXPECT_EQ(listDir(dir), (std::vector<std::string>{"big.cube", "err.txt"}));
        fs::remove(dir + "/err.txt");
    }
}

} // namespace
