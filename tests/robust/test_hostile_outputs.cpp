// SPDX-License-Identifier: Apache-2.0
// What lutkit writes that is not a file (issue 29): reports on standard output are checked like
// any write; a new output is created exclusively, so a second writer of the same new file fails
// naming it instead of replacing the first one's result.
#include "HostileSupport.h"
#include "TestPaths.h"

#include "lut/Error.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/OutputPolicy.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <filesystem>

using namespace lut::robust;
using ::testing::HasSubstr;

namespace {

// `info --json`, `diff --json`, `convert --json`, `bake --json` and `validate` redirected to a
// full disk exited 0 with an empty file: the report is output the user asked for.
TEST(HostileOutputs, ReportsOnStandardOutputToAFullDiskAreAFailedWrite) {
    if (!std::filesystem::exists("/dev/full"))
        GTEST_SKIP() << "no /dev/full";
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/a.cube", neutralCube(3));
    writeBytes(dir + "/b.cube", neutralCube(4));
    const std::string a = shellQuoted(dir + "/a.cube"), b = shellQuoted(dir + "/b.cube");
    for (const std::string& args :
         {"info " + a + " --json", "diff " + a + " " + b + " --json",
          "convert " + a + " " + shellQuoted(dir + "/c.cube") + " --json", "validate " + a,
          "bake " + shellQuoted(dir + "/baked.cube") + " --lut " + a + " --json", "info " + a}) {
        const std::string err = dir + "/err.txt";
        const int status = std::system(
            (shellQuoted(LUTKIT_CLI) + " " + args + " >/dev/full 2>" + shellQuoted(err)).c_str());
        SCOPED_TRACE(args);
        EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 1);
        EXPECT_EQ(fileBytes(err).substr(fileBytes(err).find("lutkit: error: -:")),
                  "lutkit: error: -: cannot write standard output: No space left on device\n");
    }
}

// Two `lutkit convert` writing one new file: each checked that it did not exist, then wrote it.
// Both succeeded, the second replacing the first's result without -y. Standard input holds each
// process after its check (it reads the LUT after checking the output), so the order is certain.
TEST(HostileOutputs, SecondWriterOfANewFileFailsNamingIt) {
    const std::string dir = lut::test::tempDir();
    const std::string out = dir + "/new.cube";
    const std::string cmd = shellQuoted(LUTKIT_CLI) + " convert - " + shellQuoted(out) +
                            " --in-format cube -q 2>" + shellQuoted(dir + "/err");
    std::signal(SIGPIPE, SIG_IGN);
    FILE* first = ::popen((cmd + "1").c_str(), "w");
    FILE* second = ::popen((cmd + "2").c_str(), "w");
    ASSERT_TRUE(first && second);
    ::usleep(300000); // both started and checked the output (absent)
    const std::string one = neutralCube(2, "TITLE \"first\"\n");
    const std::string two = neutralCube(2, "TITLE \"second\"\n");
    std::fwrite(one.data(), 1, one.size(), first);
    const int s1 = ::pclose(first);
    std::fwrite(two.data(), 1, two.size(), second);
    const int s2 = ::pclose(second);
    EXPECT_EQ(WEXITSTATUS(s1), 0) << fileBytes(dir + "/err1");
    EXPECT_EQ(WEXITSTATUS(s2), 1);
    EXPECT_EQ(stripDir(fileBytes(dir + "/err2"), dir),
              "lutkit: error: new.cube: already exists: another program created it while lutkit "
              "was writing it; not replaced\n");
    EXPECT_THAT(fileBytes(out), HasSubstr("TITLE \"first\""));
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"err1", "err2", "new.cube"}));
}

// The same in the library: an output checked absent under Refuse is renamed into place only if
// still absent; a file that appeared meanwhile is kept.
TEST(HostileOutputs, ExclusiveOutputKeepsAFileThatAppearedMeanwhile) {
    const std::string dir = lut::test::tempDir();
    const std::string out = dir + "/x.cube";
    const lut::OutputTarget t = lut::checkOutput(out, lut::ExistingOutput::Refuse);
    EXPECT_EQ(t.kind, lut::OutputKind::NewFile);
    writeBytes(out, "theirs");
    try {
        lut::writeFileAtomically(out, "ours");
        FAIL() << "replaced a file another program created";
    } catch (const lut::Error& e) {
        EXPECT_EQ(stripDir(e.what(), dir),
                  "x.cube: already exists: another program created it while lutkit was writing "
                  "it; not replaced");
    }
    EXPECT_EQ(fileBytes(out), "theirs");
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"x.cube"}));

    // With -y (Replace) a file there when the write begins is the user's to replace.
    const std::string other = dir + "/y.cube";
    writeBytes(other, "old");
    EXPECT_EQ(lut::checkOutput(other, lut::ExistingOutput::Replace).kind,
              lut::OutputKind::ExistingFile);
    lut::writeFileAtomically(other, "ours");
    EXPECT_EQ(fileBytes(other), "ours");
}

} // namespace
