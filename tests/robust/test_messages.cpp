// SPDX-License-Identifier: Apache-2.0
// Issue 41's "Messages": each of them a line that said something wrong or unclear, now one clear
// line with its exit code. (The OpenColorIO messages: test_malformed_table.cpp; the EXR write
// error that named its path twice: test_full_disk.cpp; two-size pages to OpenEXR and TIFF MIP
// levels: WriteMatrix.*/structure; check --report pictures: DistinctOutputs.*.)
#include "RobustSupport.h"
#include "TestPaths.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

using namespace lut::robust;
using lut::test::runCli;
using lut::test::runCommand;
using lut::test::shellQuoted;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {

std::string png(const std::string& dir) {
    const std::string path = dir + "/in.png";
    EXPECT_EQ(runCommand("oiiotool --pattern constant:color=0.2,0.4,0.6 8x8 3 -d uint8 -o " +
                         shellQuoted(path))
                  .exitCode,
              0);
    return path;
}

// --max-memory 1e3 was taken as 1000 bytes and the run failed "needs 0 MiB, over the limit of
// 0 MiB" (exit 1); 1e30G exited 1.
TEST(Messages, MaxMemoryWithoutAUnitOrPastAnyMachineIsBadUsage) {
    const std::string dir = lut::test::tempDir();
    const std::string in = png(dir);
    const auto run = [&](const std::string& size) {
        return runCli("apply -y --lut builtin:neutral " + shellQuoted(in) + " -o " +
                      shellQuoted(dir + "/out.png") + " --max-memory " + size);
    };
    auto r = run("1e3");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_THAT(r.err, HasSubstr("1e3 is 1000 bytes, less than any picture needs: give a unit "
                                 "(1e3M, 1e3G)"));
    r = run("500K");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_THAT(r.err, HasSubstr("500K is 500.0 KiB, less than any picture needs (at least 1M)"));
    r = run("1e30G");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_THAT(r.err, HasSubstr("1e30G is more than any machine has"));
    EXPECT_EQ(run("64M").exitCode, 0);
    EXPECT_EQ(run("2000000000").exitCode, 0); // a number alone is bytes
}

// A newline or ESC in a file name was printed raw: a message broken in two, or the terminal
// driven by the name.
TEST(Messages, ControlCharactersInANameAreEscaped) {
    const std::string dir = lut::test::tempDir();
    const std::string name = dir + "/bad\nname\x1b[31m.cube";
    auto r = runCli("info " + shellQuoted(name));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err, "lutkit: error: " + dir +
                         "/bad\\nname\\x1b[31m.cube: cannot open: No such "
                         "file or directory\n");
    // A batch's lines too: a folder entry that is skipped.
    std::filesystem::create_directories(dir + "/in");
    writeBytes(dir + "/in/a.cube", neutralCube(2));
    std::filesystem::create_symlink("/dev/zero", dir + "/in/z\tero\n.cube");
    r = runCli("convert " + shellQuoted(dir + "/in/") + " -o " + shellQuoted(dir + "/out/") +
               " --format 3dl");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr("lutkit: warning: " + dir +
                                 "/in/z\\tero\\n.cube: is a character device, not a regular file; "
                                 "skipped\n"));
    EXPECT_THAT(r.err, Not(HasSubstr("\x1b")));
}

// `info -zz.cube` said "IN is required".
TEST(Messages, AFileNamedLikeAnOptionIsSaidSo) {
    const std::string dir = lut::test::tempDir();
    const auto r = runCli("info -zz.cube");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("lutkit info: -zz.cube: no such option; a file whose name starts "
                                 "with '-' is ./-zz.cube (or put -- before it)"));
    EXPECT_THAT(r.err, Not(HasSubstr("IN is required")));
}

// `/dev/stdin` as a name said "no format reads '' files": it is standard input, as "-" is.
TEST(Messages, DevStdinIsStandardInput) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/a.cube", neutralCube(3));
    // runCommand's shell gives the command /dev/null as standard input: an inner shell pipes.
    const auto sh = [](const std::string& inner) { return runCommand("sh -c '" + inner + "'"); };
    const std::string cli = "\"" + std::string(LUTKIT_CLI) + "\"";
    auto r = sh(cli + " info /dev/stdin < \"" + dir + "/a.cube\"");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("3^3"));
    r = sh("cat \"" + dir + "/a.cube\" | " + cli + " info /dev/fd/0");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const std::string in = png(dir);
    r = sh(cli + " apply --lut builtin:neutral /dev/stdin -o - --format png < \"" + in + "\"");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.substr(1, 3), "PNG");
    // A file without an extension says how to name its format.
    writeBytes(dir + "/noext", neutralCube(2));
    r = runCli("info " + shellQuoted(dir + "/noext"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr(dir + "/noext: has no extension to tell its format: name it "
                                       "with --in-format"));
}

// A 2^3 cube with +-1e30 entries: "every lattice line monotone" beside its own finding that R
// "jumps from 65504 to -65504": the line falls end to end (monotone, an inverting table), and
// the checks take +-1e30 as +-65504. Both are said now.
TEST(Messages, CheckSaysWhereATableFallsAndWhatItClamps) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/huge.cube",
               "LUT_3D_SIZE 2\n1e30 0 0\n-1e30 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n");
    const auto r = runCli("check " + shellQuoted(dir + "/huge.cube"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.out, HasSubstr("every lattice line monotone (8% of them falling end to end: the "
                                 "table inverts there)"));
    EXPECT_THAT(r.out, HasSubstr("output -1e+30..1e+30 (the checks take values beyond +-65504 as "
                                 "+-65504, half-float's range)"));
}

// OpenColorIO's config errors: one line, the file's line and column first.
TEST(Messages, OcioConfigErrorNamesItsLine) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/bad.ocio", "ocio_profile_version: 2\nroles:\n  default: raw\ncolorspaces:\n"
                                  "  - !<ColorSpace>\n    name: raw\n    bogus_key: [1\n");
    const std::string in = png(dir);
    const auto r = runCli("apply --config " + shellQuoted(dir + "/bad.ocio") +
                          " --from raw --lut builtin:neutral " + shellQuoted(in) + " -o " +
                          shellQuoted(dir + "/out.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err, "lutkit: error: " + dir +
                         "/bad.ocio:8:1: OpenColorIO cannot read the config: yaml-cpp: end of "
                         "sequence flow not found\n");
}

} // namespace
