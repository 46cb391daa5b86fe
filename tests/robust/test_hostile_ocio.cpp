// SPDX-License-Identifier: Apache-2.0
// Files OpenColorIO opens on lutkit's behalf (issue 29): a config's FileTransforms and the files
// a CTF references are held to the rules of a file on the command line (no device or FIFO, even
// through a symbolic link), and transforms that refer to each other in a cycle are refused
// naming the cycle instead of exhausting OCIO's stack.
#include "HostileSupport.h"
#include "TestPaths.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

using namespace lut::robust;
using ::testing::HasSubstr;

namespace {

std::string config(const std::string& colourSpaces) {
    return "ocio_profile_version: 2\nsearch_path: .\nroles:\n  default: raw\n  scene_linear: raw\n"
           "displays:\n  sRGB:\n    - !<View> {name: Raw, colorspace: raw}\n"
           "colorspaces:\n  - !<ColorSpace>\n    name: raw\n    isdata: true\n" +
           colourSpaces;
}

// `bake` died with SIGSEGV (exit 139): colour space a's transform names b, b's names a.
TEST(HostileOcio, TransformsReferringToEachOtherAreRefusedNamingTheCycle) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/cycle.ocio",
               config("  - !<ColorSpace>\n    name: a\n    from_scene_reference: "
                      "!<ColorSpaceTransform> {src: raw, dst: b}\n"
                      "  - !<ColorSpace>\n    name: b\n    from_scene_reference: "
                      "!<ColorSpaceTransform> {src: raw, dst: a}\n"));
    for (const std::string& args :
         {"bake " + shellQuoted(dir + "/out.cube") + " --config " +
              shellQuoted(dir + "/cycle.ocio") + " --inputspace raw --outputspace a",
          "apply --lut " + shellQuoted(lut::test::dataPath("cube/adobe_3d_domain.cube")) + " " +
              shellQuoted(lut::test::dataPath("strip/neutral4_pilot.png")) + " -o " +
              shellQuoted(dir + "/o.png") + " --config " + shellQuoted(dir + "/cycle.ocio") +
              " --from a"}) {
        const auto r = lut::test::runCli(args);
        SCOPED_TRACE(args);
        EXPECT_EQ(r.exitCode, 1);
        EXPECT_THAT(stripDir(r.err, dir),
                    HasSubstr("lutkit: error: cycle.ocio: colour space 'a' -> colour space 'b' -> "
                              "colour space 'a': these transforms refer to each other in a cycle"));
    }
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.cube"));
}

// A look whose transform applies the look itself: the same cycle through a look.
TEST(HostileOcio, LookApplyingItselfIsRefused) {
    const std::string dir = lut::test::tempDir();
    std::string text = config("");
    text += "looks:\n  - !<Look>\n    name: loop\n    process_space: raw\n    transform: "
            "!<LookTransform> {src: raw, dst: raw, looks: loop}\n";
    writeBytes(dir + "/look.ocio", text);
    const auto r = lut::test::runCli("bake " + shellQuoted(dir + "/out.cube") + " --config " +
                                     shellQuoted(dir + "/look.ocio") +
                                     " --inputspace raw --outputspace raw --looks loop");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(stripDir(r.err, dir),
                HasSubstr("look.ocio: look 'loop' -> look 'loop': these transforms refer to each "
                          "other in a cycle"));
}

// A FileTransform reaching /dev/zero through a symbolic link read without end; a FIFO blocked.
// Both are refused when the config is loaded, like a FIFO or device on the command line.
TEST(HostileOcio, FileTransformOnADeviceOrFifoIsRefused) {
    const std::string dir = lut::test::tempDir();
    ASSERT_EQ(::symlink("/dev/zero", (dir + "/zero.cube").c_str()), 0);
    ASSERT_EQ(::mkfifo((dir + "/fifo.cube").c_str(), 0600), 0);
    for (const std::string name : {"zero", "fifo"}) {
        writeBytes(dir + "/" + name + ".ocio",
                   config("  - !<ColorSpace>\n    name: lut\n    from_scene_reference: "
                          "!<FileTransform> {src: " +
                          name + ".cube}\n"));
        const auto r =
            lut::test::runCli("--version >/dev/null; cd " + shellQuoted(dir) + " && timeout 60 " +
                              shellQuoted(LUTKIT_CLI) + " bake out.cube --config " + name +
                              ".ocio --inputspace raw --outputspace lut");
        SCOPED_TRACE(name);
        EXPECT_EQ(r.exitCode, 1);
        EXPECT_THAT(stripDir(r.err, dir),
                    HasSubstr("lutkit: error: " + name + ".ocio: colour space 'lut' reads " + name +
                              ".cube: "));
        EXPECT_THAT(r.err, HasSubstr(name == "zero" ? "is a character device, not a regular file"
                                                    : "is a FIFO, not a regular file"));
    }
}

// A CTF that references itself (OCIO opens every <Reference path=...>): refused as a cycle.
TEST(HostileOcio, CtfReferencingItselfIsRefused) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/self.ctf",
               "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<ProcessList id=\"a\" version=\"2\">\n"
               "  <Reference inBitDepth=\"32f\" outBitDepth=\"32f\" path=\"self.ctf\"/>\n"
               "</ProcessList>\n");
    const auto r = lut::test::runCli("info " + shellQuoted(dir + "/self.ctf"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(stripDir(r.err, dir),
                HasSubstr("self.ctf: references itself through 1 file(s) (a cycle OpenColorIO "
                          "would follow without end)"));
}

} // namespace

namespace {

std::string manySpaces(int n) {
    std::string s;
    for (int i = 0; i < n; ++i)
        s += "  - !<ColorSpace>\n    name: s" + std::to_string(i) + "\n    isdata: true\n";
    return s;
}

} // namespace

// OpenColorIO 2.1's load is quadratic in the colour spaces (20,000 in a 2.1 MB config: over 15
// minutes): past the limit of 1,000 the config is refused before OpenColorIO parses it, in one
// line naming the file and the count; at the limit it loads and works.
TEST(HostileOcio, ConfigWithTooManyColourSpacesIsRefusedBeforeLoading) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/many.ocio", config(manySpaces(20000)));
    writeBytes(dir + "/limit.ocio", config(manySpaces(999))); // + raw: 1,000
    const auto refused =
        lut::test::runCli("bake " + shellQuoted(dir + "/a.cube") + " --config " +
                          shellQuoted(dir + "/many.ocio") + " --inputspace raw --outputspace s1");
    EXPECT_EQ(refused.exitCode, 1) << refused.err;
    EXPECT_THAT(stripDir(refused.err, dir),
                HasSubstr("many.ocio: the OpenColorIO config defines 20001 colour spaces, named "
                          "transforms and looks, over the limit of 1000"));
    EXPECT_FALSE(std::filesystem::exists(dir + "/a.cube"));
    const auto loaded = lut::test::runCli("bake " + shellQuoted(dir + "/b.cube") + " --config " +
                                          shellQuoted(dir + "/limit.ocio") +
                                          " --inputspace raw --outputspace s998");
    EXPECT_EQ(loaded.exitCode, 0) << loaded.err;
    EXPECT_TRUE(std::filesystem::exists(dir + "/b.cube"));
}
