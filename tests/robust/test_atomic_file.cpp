// SPDX-License-Identifier: Apache-2.0
// Verified writes (lut/io/AtomicFile.h), at the library level: a verifier's refusal, a writer's
// failure and a rename failure keep the old file and name the output (never the hidden temporary
// name); temporary names fit NAME_MAX for output names of up to 255 bytes (issue 17: they failed
// from ~232 on); the interrupt registry removes temporary files in flight.
#include "RobustSupport.h"

#include "lut/Error.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/InputFile.h"
#include "lut/io/TempFiles.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <climits>
#include <csignal>
#include <filesystem>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace lut::robust;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {

std::string messageOf(const std::function<void()>& fn) {
    try {
        fn();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(AtomicFile, CommitWithoutChecksReplacesTheFile) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/a.txt", "old");
    {
        lut::AtomicFile f(dir + "/a.txt");
        EXPECT_TRUE(fs::exists(f.tempPath())); // created at once, so its name is ours
        f.write("new bytes");
        f.commit();
    }
    EXPECT_EQ(fileBytes(dir + "/a.txt"), "new bytes");
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, AVerifierThatRefusesKeepsTheOldFileAndNamesTheOutput) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/a.png", "old");
    std::string temp;
    const std::string msg = messageOf([&] {
        lut::AtomicFile f(dir + "/a.png");
        temp = f.tempPath();
        f.write("garbage");
        f.commit([](const std::string& t) { throw lut::Error("\"" + t + "\" is not a PNG\n"); });
    });
    EXPECT_EQ(msg, dir + "/a.png: cannot write: \"" + dir + "/a.png\" is not a PNG");
    EXPECT_EQ(fileBytes(dir + "/a.png"), "old");
    EXPECT_FALSE(fs::exists(temp));
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"a.png"});
}

TEST(AtomicFile, AnEmptyOrShortFileIsRefused) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/a.cube", "old");
    EXPECT_EQ(messageOf([&] {
                  lut::AtomicFile f(dir + "/a.cube");
                  f.commit(); // the writer wrote nothing
              }),
              dir + "/a.cube: cannot write: the writer left an empty file");
    EXPECT_EQ(messageOf([&] {
                  lut::AtomicFile f(dir + "/a.cube");
                  f.write("12345");
                  f.commit({std::uint64_t{10}, {}});
              }),
              dir + "/a.cube: cannot write: only 5 of 10 bytes reached the file");
    EXPECT_EQ(fileBytes(dir + "/a.cube"), "old");
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"a.cube"});
}

TEST(AtomicFile, AWriterFailureNamesTheOutputNotTheTemporaryFile) {
    const std::string dir = lut::test::tempDir();
    std::string temp;
    const std::string msg = messageOf([&] {
        lut::AtomicFile f(dir + "/b.tif");
        temp = f.tempPath();
        f.fail("Could not open \"" + f.tempPath() + "\"");
    });
    EXPECT_EQ(msg, dir + "/b.tif: cannot write: Could not open \"" + dir + "/b.tif\"");
    EXPECT_THAT(msg, Not(HasSubstr(".tmp")));
    EXPECT_FALSE(fs::exists(temp));
}

TEST(AtomicFile, NoSuchFolderIsSaidAtOnce) {
    const std::string dir = lut::test::tempDir();
    EXPECT_EQ(messageOf([&] { lut::AtomicFile f(dir + "/missing/x.cube"); }),
              dir + "/missing/x.cube: cannot write: No such file or directory");
}

// What the system refuses is an I/O error (lut::IoError: lutkit's exit code 1, the editor's "could
// not write"), not a bad file nor a bad request: the folder's absence is the system's answer
// (ENOENT), as is an input that cannot be opened.
TEST(AtomicFile, WhatTheSystemRefusesIsAnIoError) {
    const std::string dir = lut::test::tempDir();
    EXPECT_THROW(lut::AtomicFile f(dir + "/missing/x.cube"), lut::IoError);
    EXPECT_THROW((void)lut::readFileBytes(dir + "/missing.cube", 1 << 20, "LUT file"),
                 lut::IoError);
    writeBytes(dir + "/bad.cube", "LUT_3D_SIZE 2\nnot a number\n");
    try {
        (void)lut::readFileBytes(dir + "/bad.cube", 1 << 20, "LUT file");
    } catch (const lut::IoError& e) {
        FAIL() << "a readable file is no I/O error: " << e.what();
    }
}

TEST(AtomicFile, WriteFileAtomicallyKeepsThePermissionsOfTheFileItReplaces) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/p.cube", "old");
    fs::permissions(dir + "/p.cube", fs::perms::owner_read | fs::perms::owner_write |
                                         fs::perms::group_read | fs::perms::group_write);
    lut::writeFileAtomically(dir + "/p.cube", "new");
    EXPECT_EQ(fileBytes(dir + "/p.cube"), "new");
    EXPECT_EQ(fs::status(dir + "/p.cube").permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                  fs::perms::group_write);
}

// Output names of 232..255 bytes failed: the temporary name ".NAME.tmpNNNNNNNNNNNNNNN.EXT" was
// longer than NAME_MAX. The stem is shortened now, never the extension, never inside a UTF-8
// character.
TEST(AtomicFile, LongOutputNamesWork) {
    const std::string dir = lut::test::tempDir();
    for (std::size_t len : {200u, 232u, 240u, 250u, 255u}) {
        SCOPED_TRACE(len);
        const std::string name = std::string(len - 5, 'n') + ".cube";
        lut::writeFileAtomically(dir + "/" + name, "bytes");
        EXPECT_EQ(fileBytes(dir + "/" + name), "bytes");
        lut::AtomicFile f(dir + "/" + name);
        const std::string tempName = fs::path(f.tempPath()).filename().string();
        EXPECT_LE(tempName.size(), 255u);
        EXPECT_EQ(fs::path(tempName).extension(), ".cube");
        EXPECT_EQ(tempName.rfind(".nnn", 0), 0u) << tempName;
    }
    // "é" is two bytes: a cut between them would leave an invalid name.
    std::string accents;
    while (accents.size() < 250)
        accents += "\xC3\xA9";
    const std::string name = accents + ".png"; // 254 bytes
    lut::AtomicFile f(dir + "/" + name);
    const std::string stem = fs::path(f.tempPath()).filename().string();
    const std::size_t cut = stem.find(".tmp");
    ASSERT_NE(cut, std::string::npos);
    EXPECT_EQ((cut - 1) % 2, 0u) << "a character was cut: " << stem;
}

TEST(AtomicFile, LongOutputNamesWorkFromTheCommandLine) {
    const std::string dir = lut::test::tempDir();
    const std::string name = std::string(245, 'x') + ".cube"; // 250 bytes
    const auto r = lut::test::runCli("neutral --size 5 '" + dir + "/" + name + "'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(listDir(dir), std::vector<std::string>{name});
}

// The interrupt registry: what a SIGINT handler calls removes every temporary file in flight,
// and once interrupted nothing is committed. Run in a child: the interrupted state is for good.
TEST(AtomicFileInterrupt, TemporaryFilesInFlightAreRemovedAndNothingCommits) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/kept.cube", "old");
    EXPECT_EXIT(
        {
            lut::AtomicFile a(dir + "/kept.cube");
            lut::AtomicFile b(dir + "/new.cube");
            a.write("half");
            lut::removeTempFilesInFlight(); // what the handler does
            lut::markInterrupted(SIGINT);
            const bool gone = !fs::exists(a.tempPath()) && !fs::exists(b.tempPath());
            bool refused = false;
            try {
                a.commit();
            } catch (const lut::InterruptedError&) {
                refused = true;
            }
            bool refusedNew = false;
            try {
                lut::AtomicFile c(dir + "/c.cube");
            } catch (const lut::InterruptedError&) {
                refusedNew = true;
            }
            ::_exit(gone && refused && refusedNew && lut::interruptSignal() == SIGINT ? 0 : 3);
        },
        ::testing::ExitedWithCode(0), "");
    EXPECT_EQ(fileBytes(dir + "/kept.cube"), "old");
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"kept.cube"});
}

} // namespace
