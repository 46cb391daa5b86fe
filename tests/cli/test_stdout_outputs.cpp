// SPDX-License-Identifier: Apache-2.0
// `-` as the output of every command that writes (issue 22): the data alone on standard output,
// every note, report, JSON and "wrote" line on standard error. Each row pipes the command into a
// reader that takes standard input -- `lutkit info -` for LUTs (`lutkit convert a.cube - --format
// cube | lutkit info -`), OpenImageIO for pictures -- and checks that the report went to stderr.
#include "CliTestSupport.h"
#include "TestPaths.h"

#include "lut/Image.h"
#include "lut/formats/ImageIO.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace lut;
using namespace lut::test;
using ::testing::HasSubstr;

namespace {

using lut::test::shellQuoted;

using lut::test::fileBytes;

struct Row {
    std::string name;
    std::string args;   // the command, writing to -
    bool image;         // a picture on stdout (else a LUT: lutkit info - --in-format cube)
    std::string report; // a word of the report, expected on stderr
};

std::vector<Row> rows(const CommandInputs& in) {
    const std::string a = shellQuoted(in.a), b = shellQuoted(in.b);
    return {
        {"neutral", "neutral - --format cube --size 5", false, "wrote"},
        {"convert", "convert " + a + " - --format cube", false, "wrote"},
        {"convert-json", "convert " + a + " - --format cube --json", false, "\"output\""},
        {"compose", "compose " + a + " " + b + " - --format cube", false, "wrote"},
        {"invert", "invert " + a + " - --format cube", false, "wrote"},
        {"resize", "resize " + a + " - --size 5 --format cube", false, "wrote"},
        {"smooth", "smooth " + a + " - --format cube", false, "wrote"},
        {"mix", "mix " + a + " " + b + " - --strength 0.5 --format cube", false, "wrote"},
        {"adjust",
         "adjust " + a + " --adjustments " + shellQuoted(in.adjustments) + " - --format cube",
         false, "wrote"},
        {"extract", "extract " + shellQuoted(in.strip) + " - --format cube --target raw", false,
         "wrote"},
        {"fit", "fit " + shellQuoted(in.shot) + " " + shellQuoted(in.shot) + " - --format cube",
         false, "wrote"},
        {"bake", "bake - --lut " + a + " --format resolve_cube --cubesize 9", false, "error"},
        {"bake-json", "bake - --lut " + a + " --format resolve_cube --cubesize 9 --json", false,
         "\"error\""},
        {"plot", "plot " + a + " - --format png", true, "wrote"},
        {"chart", "chart grey - --bit-depth 8", true, "wrote"},
        {"atlas", "atlas build " + a + " " + b + " -o -", true, "wrote"},
        {"embed", "embed " + shellQuoted(in.shot) + " - --format png", true, "embedded"},
        {"diff-heatmap", "diff " + a + " " + b + " --heatmap - --format png", true, "ΔE"},
        {"apply", "apply --lut " + a + " " + shellQuoted(in.shot) + " -o - --format png -v", true,
         "->"},
        {"preview", "preview " + shellQuoted(in.shot) + " -o - --format png --lut " + a + " -v",
         true, "screenshot"},
    };
}

} // namespace

TEST(StdoutOutputs, EveryCommandWritesItsDataAloneOnStdout) {
    const CommandInputs in = makeCommandInputs(workDir());
    for (const Row& row : rows(in)) {
        SCOPED_TRACE(row.name + ": lutkit " + row.args);
        const std::string data = in.dir + "/" + row.name + (row.image ? ".png" : ".cube");
        const std::string err = in.dir + "/" + row.name + ".err";
        const std::string reader = in.dir + "/" + row.name + ".read";
        // The command's stdout piped into the reader, as a user would.
        const std::string cli = std::string("'") + LUTKIT_CLI + "'";
        const std::string cmd = "set -o pipefail; " + cli + " " + row.args + " 2>" +
                                shellQuoted(err) + " </dev/null | tee " + shellQuoted(data) +
                                (row.image ? " >/dev/null"
                                           : " | " + cli + " info - --in-format cube >" +
                                                 shellQuoted(reader) + " 2>&1");
        const int status = std::system(("bash -c " + shellQuoted(cmd)).c_str());
        EXPECT_EQ(status, 0) << fileBytes(err) << fileBytes(reader);
        EXPECT_THAT(fileBytes(err), HasSubstr(row.report)) << "the report on stderr";
        const std::string bytes = fileBytes(data);
        ASSERT_FALSE(bytes.empty());
        if (row.image) {
            ASSERT_GE(bytes.size(), 8u);
            EXPECT_EQ(bytes.substr(1, 3), "PNG") << "PNG bytes first";
            // The whole of stdout is one picture: it ends with PNG's IEND chunk and its CRC.
            EXPECT_EQ(bytes.substr(bytes.size() - 8, 4), "IEND") << "nothing after the picture";
            auto img = OIIO::ImageInput::open(data);
            ASSERT_TRUE(img) << OIIO::geterror();
            std::vector<unsigned char> px(img->spec().image_bytes());
            EXPECT_TRUE(
                img->read_image(0, 0, 0, img->spec().nchannels, OIIO::TypeDesc::UINT8, px.data()));
            EXPECT_EQ(bytes.find("wrote"), std::string::npos);
        } else {
            EXPECT_THAT(fileBytes(reader), HasSubstr("cube")) << "lutkit info - read it";
            EXPECT_EQ(bytes.rfind("LUT_", 0) == 0 || bytes.rfind("TITLE", 0) == 0 ||
                          bytes.rfind("#", 0) == 0,
                      true)
                << bytes.substr(0, 80);
            EXPECT_EQ(bytes.find("wrote"), std::string::npos) << "no report in the data";
            EXPECT_EQ(bytes.find("{"), std::string::npos) << "no JSON in the data";
        }
    }
}

TEST(StdoutOutputs, DevStdoutIsStandardOutputToo) {
    const CommandInputs in = makeCommandInputs(workDir());
    const RunResult r = runCli("convert " + shellQuoted(in.a) + " /dev/stdout --format cube");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find("wrote"), std::string::npos) << r.out.substr(0, 200);
    EXPECT_THAT(r.err, HasSubstr("wrote"));
    EXPECT_EQ(r.out.rfind("LUT_3D_SIZE", 0) == 0 || r.out.rfind("TITLE", 0) == 0 ||
                  r.out.rfind("#", 0) == 0,
              true)
        << r.out.substr(0, 80);
}

TEST(StdoutOutputs, AFileOutputKeepsItsReportOnStdout) {
    const CommandInputs in = makeCommandInputs(workDir());
    const RunResult r =
        runCli("convert " + shellQuoted(in.a) + " " + shellQuoted(in.dir + "/x.cube"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("wrote"));
    EXPECT_EQ(r.err.find("wrote"), std::string::npos);
}
