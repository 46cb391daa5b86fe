// SPDX-License-Identifier: Apache-2.0
// A .cube declaring a table over the limits (LUT_3D_SIZE 257) is refused at its header line
// before the rest of the file is read: a tiny file holding only the header gets the message with
// its line and column, and a 448 MB file (sparse: the header, then zeros) is refused in a child
// process whose address space could not hold the file -- reading it whole first, as the reader
// used to, fails there with an allocation error instead of the header's line.
#include "TestSupport.h"

#include "lut/Error.h"
#include "lut/formats/Registry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {

std::string workDir() {
    const std::string d = lut::test::tempDir() + "-header";
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::string messageOf(const std::string& path) {
    try {
        (void)lut::formats::readLut(path);
    } catch (const lut::Error& e) {
        return e.what();
    } catch (const std::bad_alloc&) {
        return "bad_alloc";
    }
    return "read";
}

// The virtual memory this process maps now, in bytes (/proc/self/statm, first field in pages).
std::uint64_t mappedBytes() {
    std::ifstream f("/proc/self/statm");
    std::uint64_t pages = 0;
    f >> pages;
    return pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

} // namespace

TEST(CubeHeaderLimit, TinyFileWithOnlyTheHeader) {
    const std::string dir = workDir();
    const std::string path = dir + "/big.cube";
    std::ofstream(path) << "TITLE \"too big\"\nLUT_3D_SIZE 257\n";
    const std::string m = messageOf(path);
    EXPECT_THAT(m, HasSubstr(path + ":2:13:"));
    EXPECT_THAT(m, HasSubstr("LUT_3D_SIZE 257 is over the limit of 256"));
}

TEST(CubeHeaderLimit, RefusedBeforeTheRestOfA448MegabyteFileIsRead) {
    const std::string dir = workDir();
    const std::string path = dir + "/huge.cube";
    {
        std::ofstream f(path);
        f << "# made by a test\nLUT_3D_SIZE 257\n0 0 0\n";
    }
    fs::resize_file(path, 448ull << 20); // sparse: no disk space taken
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    const std::uint64_t limit = mappedBytes() + (160ull << 20);
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        ::close(fds[0]);
        const rlimit rl{limit, limit};
        ::setrlimit(RLIMIT_AS, &rl);
        const std::string m = messageOf(path);
        (void)!::write(fds[1], m.data(), m.size());
        ::_exit(0);
    }
    ::close(fds[1]);
    std::string m;
    char buf[512];
    for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;)
        m.append(buf, static_cast<std::size_t>(n));
    ::close(fds[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFEXITED(status));
    EXPECT_THAT(m, HasSubstr(path + ":2:13:"));
    EXPECT_THAT(m, HasSubstr("over the limit of 256"));
    fs::remove(path);
}
