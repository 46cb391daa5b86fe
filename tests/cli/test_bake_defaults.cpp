// SPDX-License-Identifier: Apache-2.0
// Issue 43: `lutkit bake --format F` with no --cubesize writes the lattice `ociobakelut --format F`
// writes (it wrote 33 where ociobakelut writes 17 for flame, 64 for resolve_cube). Both programs
// bake the same conversion of lutkit's config; the sizes are read from each file's text as its
// format writes them, by the parser here.
#include "TestPaths.h"
#include "TestSupport.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

using namespace lut::test;

namespace {

// LUTKIT_TEST_BINARY runs the same checks on another build.
RunResult lutkit(const std::string& args) {
    const char* other = std::getenv("LUTKIT_TEST_BINARY");
    return runCommand("'" + std::string(other && *other ? other : LUTKIT_CLI) + "' " + args);
}

std::string shippedConfig() {
    return std::string(LUTKIT_BINARY_DIR) + "/share/lutkit/ocio/config.ocio";
}

std::vector<std::string> lines(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> out;
    for (std::string l; std::getline(in, l);)
        out.push_back(l);
    return out;
}

// The 3D lattice's points per axis in a baked file, as its format writes it; -1 when not found.
int latticeSize(const std::string& path, const std::string& ext) {
    const auto text = lines(path);
    std::smatch m;
    for (const auto& l : text) {
        if ((ext == ".cube" || ext == ".itx") &&
            std::regex_search(l, m, std::regex(R"(^LUT_3D_SIZE\s+(\d+))")))
            return std::stoi(m[1]);
        if ((ext == ".clf" || ext == ".ctf") &&
            std::regex_search(l, m, std::regex(R"(<Array dim="(\d+) \d+ \d+ 3")")))
            return std::stoi(m[1]);
        if (ext == ".cub" && std::regex_search(l, m, std::regex(R"(^# width\s+(\d+))")))
            return std::stoi(m[1]);
        if (ext == ".lut" && std::regex_search(l, m, std::regex(R"(^Length\s+(\d+))")))
            return std::stoi(m[1]);
        if (ext == ".csp" && std::regex_match(l, m, std::regex(R"((\d+) (\d+) (\d+)\s*)")))
            return std::stoi(m[1]);
    }
    if (ext == ".3dl") { // one line "r g b" per lattice point, after the input lattice line
        std::size_t triples = 0;
        for (const auto& l : text)
            if (std::regex_match(l, std::regex(R"(\s*\d+\s+\d+\s+\d+\s*)")))
                ++triples;
        return static_cast<int>(std::lround(std::cbrt(static_cast<double>(triples))));
    }
    return -1;
}

} // namespace

TEST(BakeDefaults, LatticeSizesAreOciobakelutsPerFormat) {
    if (!haveProgram("ociobakelut"))
        GTEST_SKIP() << "ociobakelut is not installed";
    const std::string dir = tempDir();
    const std::string cfg = shippedConfig();
    struct Case {
        std::string format, ext;
    };
    const std::vector<Case> cases = {{"flame", ".3dl"},
                                     {"lustre", ".3dl"},
                                     {"iridas_cube", ".cube"},
                                     {"resolve_cube", ".cube"},
                                     {"iridas_itx", ".itx"},
                                     {"cinespace", ".csp"},
                                     {"truelight", ".cub"},
                                     {"houdini", ".lut"},
                                     {"Academy/ASC Common LUT Format", ".clf"},
                                     {"Color Transform Format", ".ctf"}};
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const Case& c = cases[i];
        SCOPED_TRACE(c.format);
        const std::string theirs = dir + "/theirs" + std::to_string(i) + c.ext;
        const std::string ours = dir + "/ours" + std::to_string(i) + c.ext;
        const std::string what =
            " --inputspace ACEScg --outputspace sRGB --format " + shellQuoted(c.format) + " ";
        RunResult r =
            runCommand("ociobakelut --iconfig " + shellQuoted(cfg) + what + shellQuoted(theirs));
        ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
        r = lutkit("bake -y --config " + shellQuoted(cfg) + what + shellQuoted(ours));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const int want = latticeSize(theirs, c.ext);
        ASSERT_GT(want, 1);
        EXPECT_EQ(latticeSize(ours, c.ext), want);
        // The report says the size it wrote.
        EXPECT_THAT(r.out, ::testing::HasSubstr("table    " + std::to_string(want) + "^3"));
    }
}

TEST(BakeDefaults, CubesizeStillWins) {
    const std::string dir = tempDir();
    const RunResult r =
        lutkit("bake -y --config " + shellQuoted(shippedConfig()) +
               " --inputspace ACEScg --outputspace sRGB --format flame --cubesize 9 " +
               shellQuoted(dir + "/a.3dl"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(latticeSize(dir + "/a.3dl", ".3dl"), 9);
}
