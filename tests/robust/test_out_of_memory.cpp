// SPDX-License-Identifier: Apache-2.0
// Issue 17: under a memory limit the message was a raw "std::bad_alloc" (or "out of memory" with
// nothing else). Now one line names the command's files and the size that could not be had. The
// limit is injected (the fault shim's malloc refuses requests over 100 MB), so the test means
// the same on any machine.
#include "RobustSupport.h"
#include "TestPaths.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>

using namespace lut::robust;
using ::testing::MatchesRegex;

namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

lut::test::RunResult runWithMallocLimit(const std::string& args) {
#ifdef LUTKIT_FAULT_SHIM
    ::setenv("LD_PRELOAD", LUTKIT_FAULT_SHIM, 1);
    ::setenv("LUTKIT_FAIL_MALLOC_ABOVE", "100000000", 1);
#endif
    auto r = lut::test::runCli(args);
    ::unsetenv("LD_PRELOAD");
    ::unsetenv("LUTKIT_FAIL_MALLOC_ABOVE");
    return r;
}

// The size in "an allocation of N bytes", or 0.
unsigned long long sizeIn(const std::string& message) {
    std::smatch m;
    if (std::regex_search(message, m, std::regex("an allocation of ([0-9]+) bytes")))
        return std::stoull(m[1]);
    return 0;
}

TEST(OutOfMemory, OneLineNamingTheFilesAndTheSize) {
    if (kSanitized)
        GTEST_SKIP() << "sanitizer build: its allocator stands in for malloc and operator new";
#ifndef LUTKIT_FAULT_SHIM
    GTEST_SKIP() << "the fault shim was not built";
#endif
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/in.cube", neutralCube(2));
    struct Case {
        std::string args, files;
    };
    const std::vector<Case> cases = {
        {"neutral --size 256 '" + dir + "/n.cube'", dir + "/n.cube"},
        {"convert '" + dir + "/in.cube' '" + dir + "/c.cube' --size 256",
         dir + "/in.cube, " + dir + "/c.cube"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.args);
        const auto r = runWithMallocLimit(c.args);
        EXPECT_EQ(r.exitCode, 1);
        EXPECT_THAT(r.err,
                    MatchesRegex(
                        "lutkit: error: " +
                        std::regex_replace(c.files, std::regex("[.^$|()\\[\\]{}*+?\\\\]"), "\\$&") +
                        ": out of memory: an allocation of [0-9]+ bytes "
                        "\\([0-9.]+ MiB\\) failed\n"));
        // A request the limit refuses: over 100 MB, at most the whole table as text.
        EXPECT_GT(sizeIn(r.err), 100000000ull);
        EXPECT_FALSE(std::filesystem::exists(dir + "/n.cube"));
        EXPECT_EQ(listDir(dir), std::vector<std::string>{"in.cube"});
    }
}

} // namespace
