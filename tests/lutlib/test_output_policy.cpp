// SPDX-License-Identifier: Apache-2.0
// The one output rule (lut/io/OutputPolicy.h) and the writer behind it (lut/io/OutputFile.h):
// existing files are replaced only when asked, special files are written in place, nothing is
// created or touched before the write succeeds.
#include "TestSupport.h"

#include "lut/Error.h"
#include "lut/io/OutputFile.h"
#include "lut/io/OutputPolicy.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

using namespace lut;
namespace fs = std::filesystem;

namespace {

using lut::test::fileBytes;

std::vector<std::string> names(const std::string& dir) {
    std::vector<std::string> n;
    for (const auto& e : fs::directory_iterator(dir))
        n.push_back(e.path().filename().string());
    std::sort(n.begin(), n.end());
    return n;
}

} // namespace

TEST(OutputPolicy, ExistingFilesNeedPermission) {
    const std::string dir = lut::test::tempDir();
    const std::string out = dir + "/out.cube";
    EXPECT_EQ(checkOutput(out, ExistingOutput::Refuse).kind, OutputKind::NewFile);
    std::ofstream(out) << "old";
    try {
        checkOutput(out, ExistingOutput::Refuse);
        ADD_FAILURE() << "an existing output was accepted";
    } catch (const OutputExistsError& e) {
        EXPECT_EQ(e.path(), out);
        EXPECT_EQ(std::string(e.what()), out + ": already exists (not replaced)");
    }
    const OutputTarget keep = checkOutput(out, ExistingOutput::Skip);
    EXPECT_TRUE(keep.skip);
    const OutputTarget replace = checkOutput(out, ExistingOutput::Replace);
    EXPECT_FALSE(replace.skip);
    EXPECT_EQ(replace.kind, OutputKind::ExistingFile);
    EXPECT_EQ(fileBytes(out), "old");
}

TEST(OutputPolicy, FoldersAndMissingFoldersAreRefused) {
    const std::string dir = lut::test::tempDir();
    EXPECT_THROW(checkOutput(dir, ExistingOutput::Replace), Error);
    EXPECT_THROW(checkOutput(dir + "/new/", ExistingOutput::Replace), Error);
    try {
        checkOutput(dir + "/no/such/out.png", ExistingOutput::Replace);
        ADD_FAILURE();
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  dir + "/no/such/out.png: folder " + dir + "/no/such does not exist");
    }
    EXPECT_FALSE(fs::exists(dir + "/no")); // nothing created
}

TEST(OutputPolicy, InputsAreNeverOutputs) {
    const std::string dir = lut::test::tempDir();
    const std::string lut = dir + "/grade.cube";
    std::ofstream(lut) << "LUT_3D_SIZE 2\n";
    fs::create_symlink(lut, dir + "/link.cube");
    fs::create_hard_link(lut, dir + "/hard.cube");
    for (const char* out : {"/grade.cube", "/link.cube", "/hard.cube", "/./grade.cube"})
        EXPECT_THROW(checkOutput(dir + out, ExistingOutput::Replace, {"-", dir + "/grade.cube"}),
                     Error)
            << out;
    EXPECT_EQ(fileBytes(lut), "LUT_3D_SIZE 2\n");
}

TEST(OutputPolicy, SpecialFilesAreWrittenInPlace) {
    EXPECT_EQ(checkOutput("-", ExistingOutput::Refuse).kind, OutputKind::Stdout);
    EXPECT_EQ(checkOutput("/dev/null", ExistingOutput::Refuse).kind, OutputKind::Special);
    EXPECT_EQ(checkOutput("/dev/stdout", ExistingOutput::Refuse).kind, OutputKind::Special);
    const std::string dir = lut::test::tempDir();
    const std::string fifo = dir + "/pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(checkOutput(fifo, ExistingOutput::Refuse).kind, OutputKind::Special);
    {
        OutputFile f(checkOutput("/dev/null", ExistingOutput::Refuse));
        f.write("abc", 3);
        f.commit();
    }
    struct stat st {};
    ASSERT_EQ(::stat("/dev/null", &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode)); // still the device
}

TEST(OutputFile, RegularFilesAppearOnlyWhenCommitted) {
    const std::string dir = lut::test::tempDir();
    const std::string out = dir + "/out.bin";
    std::ofstream(out) << "old bytes";
    {
        OutputFile f(checkOutput(out, ExistingOutput::Replace));
        f.write("new", 3);
        f.pwrite("N", 1, 0);
        EXPECT_EQ(fileBytes(out), "old bytes");
        EXPECT_EQ(fileBytes(f.tempPath()), "New");
    } // not committed
    EXPECT_EQ(fileBytes(out), "old bytes");
    EXPECT_EQ(names(dir), std::vector<std::string>{"out.bin"});
    {
        OutputFile f(checkOutput(out, ExistingOutput::Replace));
        f.write("new", 3);
        EXPECT_THROW(f.commit([](const std::string&) { throw Error("bad header"); }), Error);
    }
    EXPECT_EQ(fileBytes(out), "old bytes");
    EXPECT_EQ(names(dir), std::vector<std::string>{"out.bin"});
    OutputFile f(checkOutput(out, ExistingOutput::Replace));
    f.write("new", 3);
    f.commit([](const std::string& temp) { EXPECT_EQ(fileBytes(temp), "new"); });
    EXPECT_EQ(fileBytes(out), "new");
}

TEST(OutputFile, ALinkIsWrittenThrough) {
    const std::string dir = lut::test::tempDir();
    std::ofstream(dir + "/real.bin") << "old";
    fs::create_symlink("real.bin", dir + "/link.bin");
    writeOutputBytes(checkOutput(dir + "/link.bin", ExistingOutput::Replace), "new");
    EXPECT_TRUE(fs::is_symlink(dir + "/link.bin"));
    EXPECT_EQ(fileBytes(dir + "/real.bin"), "new");
}

TEST(OutputFile, AFullDeviceIsAnErrorNamingThePath) {
    if (::access("/dev/full", W_OK) != 0)
        GTEST_SKIP() << "no /dev/full";
    try {
        writeOutputBytes(checkOutput("/dev/full", ExistingOutput::Refuse), "bytes");
        ADD_FAILURE() << "a write to /dev/full succeeded";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "/dev/full: cannot write: No space left on device");
    }
}

// An in-memory output: seekable like a file, the caller's string given the bytes only at commit
// (as a file appears only then), empty output refused as AtomicFile refuses an empty file, and
// no file created anywhere (the current folder and the temporary folder are not touched: the
// name is only a name).
TEST(OutputFile, MemoryOutputsFillTheCallersStringAtCommit) {
    const std::string dir = lut::test::tempDir();
    const std::string name = dir + "/mem.bin";
    std::string bytes = "old";
    {
        OutputFile f(memoryOutput(name, bytes));
        EXPECT_TRUE(f.seekable());
        EXPECT_EQ(f.tempPath(), "");
        f.write("new", 3);
        f.pwrite("N", 1, 0);
        f.pwrite("!", 1, 4); // past the end: the gap is zeros, as in a file
        EXPECT_EQ(f.size(), 5u);
        EXPECT_EQ(bytes, "old");
    } // not committed
    EXPECT_EQ(bytes, "old");
    {
        OutputFile f(memoryOutput(name, bytes));
        f.write("new", 3);
        f.pwrite("N", 1, 0);
        bool called = false;
        f.commit([&](const std::string&) { called = true; });
        EXPECT_FALSE(called) << "there is no file to verify";
        EXPECT_THROW(f.write("x", 1), Error);
    }
    EXPECT_EQ(bytes, "New");
    {
        OutputFile f(memoryOutput(name, bytes));
        try {
            f.commit();
            ADD_FAILURE() << "an empty output was committed";
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()), name + ": cannot write: the writer produced no bytes");
        }
    }
    EXPECT_EQ(bytes, "New");
    EXPECT_TRUE(names(dir).empty());
}
