// SPDX-License-Identifier: Apache-2.0
// Usage errors exit 2 everywhere (issue 17: `--layout bogus` exited 1 while `--format bogus`
// exited 2). For every subcommand of the real lutkit and every option that takes a word or a
// number: an unknown word exits 2 and names it; the files given are real, so a value that got
// past the parser reaches the command itself (values checked there must say "bad usage" too).
// The option list is read from the command line's own tables: a new option is covered.
#include "RobustSupport.h"

#include "CommandLine.h"
#include "OptionTable.h"

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>
#include <set>

using namespace lut::robust;
using lut::test::runCli;
using ::testing::HasSubstr;

namespace {

void writePng(const std::string& path, int w, int h) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    std::vector<unsigned char> px(static_cast<std::size_t>(w) * h * 3, 128);
    ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
    out->close();
}

TEST(UsageErrors, AnUnknownValueExitsTwoInEveryCommand) {
    const std::string dir = lut::test::tempDir();
    writeBytes(dir + "/a.cube", neutralCube(2));
    writePng(dir + "/img.png", 400, 300);
    ASSERT_EQ(runCli("embed '" + dir + "/img.png' '" + dir + "/e.png'").exitCode, 0);
    const std::string d = "'" + dir + "/";
    // A working command line for each subcommand: the bad value is the only fault.
    writeBytes(dir + "/adj.txt", "# lutkit adjustment list 1\nexposure 0.5\n");
    // -y: each line runs again for every option, over the output the first run wrote.
    const std::map<std::string, std::string> base = {
        {"neutral", "neutral -y " + d + "n.cube'"},
        {"convert", "convert -y " + d + "a.cube' " + d + "c.cube'"},
        {"info", "info " + d + "a.cube'"},
        {"validate", "validate " + d + "a.cube'"},
        {"apply", "apply -y --lut " + d + "a.cube' " + d + "img.png' -o " + d + "o.png'"},
        {"preview", "preview -y " + d + "img.png' -o " + d + "p.png'"},
        {"embed", "embed -y " + d + "img.png' " + d + "e2.png'"},
        {"extract", "extract -y " + d + "e.png' " + d + "x.cube'"},
        {"fit", "fit -y " + d + "img.png' " + d + "img.png' " + d + "f.cube' --size 3"},
        {"match", "match -y " + d + "img.png' " + d + "img.png' " + d + "m.cube' --size 3"},
        {"bench", "bench --width 8 --height 1 --reps 1 --sizes 2 --no-ocio"},
        {"bake", "bake -y --inputspace ACEScg --outputspace sRGB --cubesize 5 " + d + "b.cube'"},
        {"diff", "diff " + d + "a.cube' " + d + "a.cube'"},
        {"compose", "compose -y " + d + "a.cube' " + d + "a.cube' " + d + "co.cube'"},
        {"invert", "invert -y " + d + "a.cube' " + d + "inv.cube'"},
        {"resize", "resize -y " + d + "a.cube' " + d + "rs.cube' --size 3"},
        {"smooth", "smooth -y " + d + "a.cube' " + d + "sm.cube'"},
        {"mix", "mix -y " + d + "a.cube' " + d + "a.cube' " + d + "mx.cube' --strength 0.5"},
        {"plot", "plot -y " + d + "a.cube' " + d + "pl.png'"},
        {"adjust", "adjust -y " + d + "a.cube' --adjustments " + d + "adj.txt' " + d + "ad.cube'"},
        {"check", "check " + d + "a.cube'"},
        {"chart", "chart -y grey " + d + "ch.png' --width 16 --height 16"},
        {"atlas", "atlas build -y " + d + "a.cube' -o " + d + "at.png' --size 3 --layout unreal"},
    };
    // Values that are files, folders or free text are not words from a set.
    const std::set<std::string> notWords = {"FILE", "DIR", "TEXT", "PATH", "NAME"};
    const std::set<std::string> colourNames = {"SPACE", "LOOKS", "DISPLAY", "VIEW", "ID"};
    lut::cli::CommandLine cl;
    const auto program = lut::cli::describeProgram(cl.app());
    int checked = 0;
    for (const auto& c : program.commands) {
        if (c.name == "help")
            continue;
        ASSERT_TRUE(base.count(c.name)) << "no command line for " << c.name;
        EXPECT_EQ(runCli(base.at(c.name)).exitCode, 0) << base.at(c.name);
        for (const auto& o : c.options) {
            if (o.valueName.empty() || o.hidden || !o.positional.empty() || o.longNames.empty() ||
                notWords.count(o.valueName))
                continue;
            const std::string line = base.at(c.name) + " " + o.longNames.front() + " zzqq";
            SCOPED_TRACE(line);
            const auto r = runCli(line);
            EXPECT_EQ(r.exitCode, 2) << r.err;
            // Names of an OpenColorIO config are checked when the command runs: alone, --to or
            // --look is refused for what it lacks (--from) before its name is looked up.
            if (!colourNames.count(o.valueName)) {
                EXPECT_THAT(r.err, HasSubstr("zzqq"));
            }
            ++checked;
        }
    }
    EXPECT_GE(checked, 20);
    // Values checked by the commands themselves, after parsing.
    for (const std::string& line :
         {base.at("preview") + " --stage vignette.strength=zzqq",
          base.at("preview") + " --stage zzqq.strength=1", base.at("preview") + " --enable zzqq",
          base.at("convert") + " --in-format zzqq", base.at("info") + " --in-layout zzqq"}) {
        SCOPED_TRACE(line);
        const auto r = runCli(line);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_THAT(r.err, HasSubstr("zzqq"));
    }
}

} // namespace
