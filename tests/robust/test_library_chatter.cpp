// SPDX-License-Identifier: Apache-2.0
// One line per error: the libraries print nothing of their own. OpenColorIO logs through a global
// function; with OCIO_LOGGING_LEVEL=debug it printed "[OpenColorIO Debug]: ..." lines from
// `lutkit bench` and `info` listed a dozen of them as notes (issue 17: library chatter folded
// into lutkit's one line). Its warnings stay: as notes on the file that caused them. (libpng's own
// "libpng error:" lines are the image readers' to silence.)
#include "RobustSupport.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>

using namespace lut::robust;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {

lut::test::RunResult runWithOcioDebug(const std::string& args) {
    ::setenv("OCIO_LOGGING_LEVEL", "debug", 1);
    auto r = lut::test::runCli(args);
    ::unsetenv("OCIO_LOGGING_LEVEL");
    return r;
}

TEST(LibraryChatter, OpenColorIOPrintsNothingOfItsOwn) {
    const std::string dir = lut::test::tempDir();
    auto r = runWithOcioDebug("bench --width 8 --height 1 --reps 1 --sizes 2");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out + r.err, Not(HasSubstr("[OpenColorIO")));

    r = runWithOcioDebug("info '" + lut::test::dataPath("ocio/affine.3dl") + "'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out + r.err, Not(HasSubstr("[OpenColorIO")));

    // A file OCIO refuses: exactly one line, lutkit's.
    writeBytes(dir + "/bad.itx", "LUT_3D_SIZE 2\n1 2 3\n");
    r = runWithOcioDebug("info '" + dir + "/bad.itx'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_THAT(r.err, HasSubstr("lutkit: error: " + dir + "/bad.itx: OpenColorIO cannot read it"));
}

} // namespace
