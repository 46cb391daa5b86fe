// SPDX-License-Identifier: Apache-2.0
// Exit codes, as documented in the README: 0 success, 1 bad input or failed operation, 2 bad
// usage (any: unknown command or option, bad value, missing argument). For every subcommand: an
// unknown option (2), a missing file (1), a malformed file (1) and a success (0), each with the
// first words of its message.
#include "RobustSupport.h"

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

using namespace lut::robust;
using lut::test::runCli;
using ::testing::HasSubstr;

namespace {

struct Case {
    std::string args; // "@/" stands for the test folder
    int code;
    std::string stderrHas; // "" = stderr must be empty
};

void writePng(const std::string& path, int w, int h) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    std::vector<float> px(static_cast<std::size_t>(w) * h * 3);
    for (std::size_t i = 0; i < px.size(); ++i)
        px[i] = static_cast<float>(i % 7) / 7.0f;
    ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    out->close();
}

std::string expand(std::string s, const std::string& dir) {
    for (std::size_t at; (at = s.find("@/")) != std::string::npos;)
        s.replace(at, 2, "'" + dir + "'/");
    return s;
}

TEST(ExitCodes, EverySubcommand) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/a.cube", neutralCube(2));
    writeBytes(dir + "/bad.cube", "LUT_3D_SIZE 2\n0 0 0\n");
    writeBytes(dir + "/bad.png", "not an image\n");
    writePng(dir + "/img.png", 64, 48);
    writePng(dir + "/big.png", 400, 300);
    const std::string unexpected = "The following argument was not expected: --no-such-option";
    const std::string missingCube =
        "lutkit: error: " + dir + "/missing.cube: cannot open: No such file or directory";
    const std::string missingPng =
        "lutkit: error: " + dir + "/missing.png: cannot open: No such file or directory";
    const std::string badCube =
        "lutkit: error: " + dir +
        "/bad.cube:3:1: expected 8 data rows for LUT_3D_SIZE 2, found 1 before the end of the file";
    const std::string badPng =
        "lutkit: error: " + dir + "/bad.png: cannot read image: Not a PNG file";
    const std::vector<Case> cases = {
        // usage of lutkit itself
        {"", 2, "A subcommand is required"},
        {"--version", 0, ""},
        {"-V", 0, ""},
        {"help", 0, ""},
        {"help convert", 0, ""},
        {"help nosuch", 2, "unknown command 'nosuch'"},
        {"nuetral @/n.cube", 2, "lutkit: unknown command 'nuetral'; did you mean 'neutral'?"},
        {"convert @/a.cube @/x.cube --layuot unreal", 2, "did you mean '--layout'?"},
        {"neutral", 2, "OUT is required"},
        {"neutral @/x.cube --size 1", 2, "--size: Value 1 not in range 2 to 256"},
        {"convert @/a.cube @/x.cube --interp cubic", 2, "--interp: unknown interpolation 'cubic'"},
        // an unknown layout is bad usage like an unknown format (it used to exit 1)
        {"info @/img.png --in-layout diagonal", 2,
         "lutkit info: --in-layout: unknown layout 'diagonal' (expected unreal, unity, smush, "
         "hald, reshade or unity-32; also pilot, godot, lattice, unreal-32)"},
        {"convert @/a.cube @/x.png --layout unrel", 2,
         "lutkit convert: --layout: unknown layout 'unrel'; did you mean 'unreal'?"},
        {"preview @/img.png -o @/p.png --preset lectur", 2, "did you mean 'lecture'?"},
        // --format is the output everywhere: the old input meaning names the new option
        {"info @/a.cube --format cube", 2, "name its format with --in-format"},
        {"validate @/a.cube --format cube", 2, "name their format with --in-format"},
        {"info @/a.cube --layout unreal", 2, "name its layout with --in-layout"},
        {"info @/a.cube --in-format cube", 0, ""},
        // neutral (no input file: a folder that does not exist stands for the missing file)
        {"neutral @/n.cube --no-such-option", 2, unexpected},
        {"neutral @/nowhere/n.cube", 1,
         "lutkit: error: " + dir + "/nowhere/n.cube: folder " + dir + "/nowhere does not exist"},
        {"neutral @/n.cube --size 4", 0, ""},
        // convert
        {"convert @/a.cube @/c.nutexb --no-such-option", 2, unexpected},
        {"convert @/missing.cube @/c.nutexb", 1, missingCube},
        {"convert @/bad.cube @/c.nutexb", 1, badCube},
        {"convert @/a.cube @/c.nutexb", 0, ""},
        // info
        {"info @/a.cube --no-such-option", 2, unexpected},
        {"info @/missing.cube", 1, missingCube},
        {"info @/bad.cube", 1, badCube},
        {"info @/a.cube", 0, ""},
        // validate
        {"validate @/a.cube --no-such-option", 2, unexpected},
        {"validate @/missing.cube", 1, missingCube},
        {"validate @/bad.cube", 1,
         dir + "/bad.cube:3:1: error: expected 8 data rows for LUT_3D_SIZE 2, found 1"},
        {"validate @/a.cube", 0, ""},
        // apply
        {"apply --lut @/a.cube @/img.png -o @/o.png --no-such-option", 2, unexpected},
        {"apply --lut @/a.cube @/missing.png -o @/o.png", 1, missingPng},
        {"apply --lut @/missing.cube @/img.png -o @/o.png", 1, missingCube},
        {"apply --lut @/a.cube @/bad.png -o @/o.png", 1, badPng},
        {"apply --lut @/bad.cube @/img.png -o @/o.png", 1, badCube},
        {"apply --lut @/a.cube @/img.png -o @/o.png", 0, ""},
        // preview
        {"preview @/img.png -o @/p.png --no-such-option", 2, unexpected},
        {"preview @/missing.png -o @/p.png", 1, missingPng},
        {"preview @/bad.png -o @/p.png", 1, badPng},
        // the screenshot/scene decision is said (issue 14)
        {"preview @/img.png -o @/p.png", 0,
         "lutkit: note: " + dir + "/img.png: an in-game screenshot"},
        // embed, then extract from what it wrote
        {"embed @/big.png @/e.png --no-such-option", 2, unexpected},
        {"embed @/missing.png @/e.png", 1, missingPng},
        {"embed @/bad.png @/e.png", 1, badPng},
        {"embed @/big.png @/e.png", 0, "the screenshot is too small for scale 8"},
        {"extract @/e.png @/x.cube --no-such-option", 2, unexpected},
        {"extract @/missing.png @/x.cube", 1, missingPng},
        {"extract @/bad.png @/x.cube", 1, badPng},
        {"extract @/img.png @/x.cube", 1, "no LUT patch found"},
        {"extract @/e.png @/x.cube", 0, ""},
        // fit
        {"fit @/img.png @/img.png @/f.cube --no-such-option", 2, unexpected},
        {"fit @/missing.png @/img.png @/f.cube", 1, missingPng},
        {"fit @/img.png @/bad.png @/f.cube", 1, badPng},
        {"fit @/img.png @/img.png @/f.cube --size 4", 0, "lutkit: warning:"},
        // bench (no files: a tiny run)
        {"bench --no-such-option", 2, unexpected},
        {"bench --width 4", 2, "--width: Value 4 not in range 8 to 16384"},
        {"bench --width 8 --height 1 --reps 1 --sizes 2 --no-ocio", 0, ""},
    };
    for (const auto& c : cases) {
        const std::string args = expand(c.args, dir);
        SCOPED_TRACE(args);
        const auto r = runCli(args);
        EXPECT_EQ(r.exitCode, c.code) << r.err;
        if (c.stderrHas.empty()) {
            EXPECT_EQ(r.err, "");
        } else {
            EXPECT_THAT(r.err, HasSubstr(c.stderrHas));
        }
    }
}

} // namespace
