// SPDX-License-Identifier: Apache-2.0
// Issue 43: the shell completions complete an output path after -o, the active config's colour
// spaces, looks, displays and views (asked of `lutkit --names`, with the line's --config obeyed)
// and atlas's build|split|info. bash's completion function is run as bash runs it (COMP_WORDS,
// COMP_CWORD, _lutkit, COMPREPLY); fish's with `complete -C`; zsh's name helper with compadd
// stubbed (when the shells are installed). The expected names are written here from the configs'
// text (share/ocio/config.ocio, tests/data/ocio/studio_names.ocio), not asked of lutkit.
//
// LUTKIT_TEST_BINARY and LUTKIT_TEST_COMPLETIONS (a folder) run the same checks on another build.
#include "TestPaths.h"
#include "TestSupport.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace lut::test;
using ::testing::HasSubstr;

namespace {

std::string lutkit() {
    const char* other = std::getenv("LUTKIT_TEST_BINARY");
    return other && *other ? other : LUTKIT_CLI;
}

std::string script(const std::string& name) {
    const char* other = std::getenv("LUTKIT_TEST_COMPLETIONS");
    return (other && *other ? std::string(other)
                            : std::string(LUTKIT_BINARY_DIR) + "/cli/completions") +
           "/" + name;
}

std::string studioConfig() {
    return dataPath("ocio/studio_names.ocio");
}

// A folder holding a few files, where the completions run.
std::string filesDir() {
    const std::string dir = tempDir();
    for (const char* f : {"grade.cube", "shot.exr", "notes.txt"})
        std::ofstream(dir + "/" + f) << "x";
    fs::create_directories(dir + "/renders");
    return dir;
}

// bash's candidates for a line: words after the program (the last is the word being completed),
// each on its own line, in the order the completion gives them. $OCIO unset unless ocio is given.
std::string bash(const std::vector<std::string>& words, const std::string& dir,
                 const std::string& ocio = {}) {
    std::string s =
        "source " + shellQuoted(script("lutkit")) + "\nCOMP_WORDS=(" + shellQuoted(lutkit());
    for (const auto& w : words)
        s += " " + shellQuoted(w);
    s += ")\nCOMP_CWORD=" + std::to_string(words.size()) +
         "\n_lutkit\nprintf '%s\\n' \"${COMPREPLY[@]}\"\n";
    const std::string file = dir + "/complete.bash";
    std::ofstream(file) << s;
    const RunResult r =
        runCommand("cd " + shellQuoted(dir) + " && " +
                   (ocio.empty() ? "env -u OCIO" : "env OCIO=" + shellQuoted(ocio)) + " bash " +
                   shellQuoted(file));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return r.out;
}

// fish's candidates for a line (its `complete -C`), without the descriptions, sorted by fish.
std::string fish(const std::string& line, const std::string& dir) {
    const std::string bin = fs::path(lutkit()).parent_path().string();
    const std::string file = dir + "/complete.fish";
    // In fish's single quotes only \' and \\ are escapes: the line is written with them.
    std::string quotedLine = "'";
    for (const char c : line)
        quotedLine += c == '\'' || c == '\\' ? std::string("\\") + c : std::string(1, c);
    std::ofstream(file) << "source '" << script("lutkit.fish") << "'\ncomplete -C " << quotedLine
                        << "'\n";
    const RunResult r =
        runCommand("cd " + shellQuoted(dir) + " && env -u OCIO PATH=" + shellQuoted(bin) +
                   ":\"$PATH\" fish " + shellQuoted(file));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    std::string names; // each line up to its tab (the description)
    std::istringstream in(r.out);
    for (std::string l; std::getline(in, l);)
        names += l.substr(0, l.find('\t')) + "\n";
    return names;
}

} // namespace

TEST(CompletionNames, NamesPrintsTheActiveConfigsNames) {
    // lutkit's own config (share/ocio/config.ocio): its colour spaces, then aliases, then roles.
    RunResult r = runCommand("env -u OCIO '" + lutkit() + "' --names spaces");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("Linear Rec.709 (sRGB)\nsRGB\nRec.709\nACEScg\nACEScct\n"));
    EXPECT_THAT(r.out, HasSubstr("\nlin_ap1\n"));
    EXPECT_THAT(r.out, HasSubstr("\nscene_linear\n"));
    r = runCommand("env OCIO=" + shellQuoted(studioConfig()) + " '" + lutkit() + "' --names looks");
    EXPECT_EQ(r.out, "warm\ncool\n");
    r = runCommand("env OCIO=" + shellQuoted(studioConfig()) + " '" + lutkit() +
                   "' --names 'views:Studio Monitor'");
    EXPECT_EQ(r.out, "Film\nRaw\n");
    // No config: nothing on standard output (the completion offers nothing), exit 1.
    r = runCommand("env OCIO=/nonexistent/config.ocio '" + lutkit() + "' --names spaces");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.out, "");
    r = runCommand("'" + lutkit() + "' --names colours");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("unknown kind of names 'colours'"));
}

TEST(CompletionNames, BashCompletesFilesAfterOutputOptions) {
    const std::string dir = filesDir();
    // -o was completed with nothing at all.
    EXPECT_EQ(bash({"apply", "--lut", "grade.cube", "shot.exr", "-o", "sh"}, dir), "shot.exr\n");
    EXPECT_EQ(bash({"convert", "grade.cube", "--output", "re"}, dir), "renders\n");
    EXPECT_EQ(bash({"atlas", "split", "a.png", "-o", "ren"}, dir), "renders\n");
}

TEST(CompletionNames, BashCompletesColourSpacesLooksDisplaysAndViews) {
    const std::string dir = filesDir();
    EXPECT_EQ(bash({"apply", "--from", "ACES"}, dir), "ACEScg\nACEScct\nACES2065-1\n");
    EXPECT_EQ(bash({"preview", "x.png", "--to", "lin_"}, dir),
              "lin_rec709\nlin_srgb\nlin_ap1\nlin_ap0\n");
    // A name with blanks comes back escaped for the shell.
    EXPECT_EQ(bash({"apply", "--lut-space", "Linear"}, dir), "Linear\\ Rec.709\\ \\(sRGB\\)\n");
    EXPECT_EQ(bash({"bake", "--display", ""}, dir), "sRGB\nRec.709\n");
    EXPECT_EQ(bash({"bake", "--inputspace", "ACEScg", "--outputspace", "r"}, dir),
              "rec709\nreference\nrendering\n");
    // --config on the line is the config asked, before $OCIO.
    const std::string cfg = studioConfig();
    EXPECT_EQ(bash({"apply", "--config", cfg, "--from", "fl"}, dir), "flog\n");
    EXPECT_EQ(bash({"apply", "--config", cfg, "--from", "f"}, dir), "film\\ log\nflog\n");
    EXPECT_EQ(bash({"bake", "--iconfig", cfg, "--looks", ""}, dir), "warm\ncool\n");
    EXPECT_EQ(bash({"apply", "--config", cfg, "--look", "warm,+c"}, dir), "warm\\,+cool\n");
    EXPECT_EQ(bash({"apply", "--config", cfg, "--display", "St"}, dir), "Studio\\ Monitor\n");
    EXPECT_EQ(bash({"apply", "--config", cfg, "--display", "Phone", "--view", ""}, dir),
              "Bright\n");
    EXPECT_EQ(bash({"apply", "--config", cfg, "--view", ""}, dir), "Film\nRaw\nBright\n");
    // $OCIO when the line names no config; --opt=value split at '=' by bash.
    EXPECT_EQ(bash({"apply", "--look", "c"}, dir, cfg), "cool\n");
    EXPECT_EQ(bash({"apply", "--from", "=", "wi"}, dir, cfg), "wide\\ lin\n");
}

TEST(CompletionNames, BashCompletesAtlasActions) {
    const std::string dir = filesDir();
    EXPECT_EQ(bash({"atlas", ""}, dir), "build\nsplit\ninfo\n");
    EXPECT_EQ(bash({"atlas", "-o", "atlas.png", "--layout", "reshade", "b"}, dir), "build\n");
    EXPECT_EQ(bash({"chart", "sk"}, dir), "skin\n");
    // After the action: the files.
    EXPECT_EQ(bash({"atlas", "build", "gr"}, dir), "grade.cube\n");
}

TEST(CompletionNames, FishCompletesTheSame) {
    if (!haveProgram("fish"))
        GTEST_SKIP() << "fish is not installed";
    const std::string dir = filesDir();
    EXPECT_EQ(fish("lutkit apply --lut grade.cube shot.exr -o sh", dir), "shot.exr\n");
    EXPECT_EQ(fish("lutkit apply --from ACES", dir), "ACES2065-1\nACEScct\nACEScg\n");
    EXPECT_EQ(fish("lutkit apply --config " + studioConfig() + " --look w", dir), "warm\n");
    EXPECT_EQ(fish("lutkit apply --config " + studioConfig() + " --display Phone --view ", dir),
              "Bright\n");
    const std::string actions = fish("lutkit atlas ", dir);
    EXPECT_THAT(actions, HasSubstr("build\n"));
    EXPECT_THAT(actions, HasSubstr("split\n"));
    EXPECT_THAT(actions, HasSubstr("info\n"));
    EXPECT_THAT(fish("lutkit atlas split ", dir), ::testing::Not(HasSubstr("build\n")));
}

TEST(CompletionNames, ZshCompletesTheSame) {
    const std::string file = script("_lutkit");
    const std::string text = fileBytes(file);
    // The specs: -o completes files, --from the config's spaces, atlas its actions.
    EXPECT_THAT(text, HasSubstr("{-o+,--output=,--output-dir=}'[output\\: a file (one input)"));
    EXPECT_THAT(text, HasSubstr(":PATH:_files'"));
    EXPECT_THAT(text, HasSubstr(":SPACE:_lutkit_names spaces'"));
    EXPECT_THAT(text, HasSubstr(":LOOKS:_lutkit_names looks'"));
    EXPECT_THAT(text, HasSubstr(":VIEW:_lutkit_names views'"));
    EXPECT_THAT(text, HasSubstr("':ACTION:(build split info)'"));
    if (!haveProgram("zsh"))
        GTEST_SKIP() << "zsh is not installed";
    EXPECT_EQ(runCommand("zsh -n " + shellQuoted(file)).exitCode, 0);
    // The name helper as _arguments runs it (words: the command's words), compadd stubbed.
    const std::string run = tempDir() + "/names.zsh";
    std::ofstream(run) << "eval \"$(sed -n '/^_lutkit_names() {/,/^}/p' " << shellQuoted(file)
                       << ")\"\ncompset() { return 1 }\ncompadd() { print -l -- ${(P)2} }\n"
                       << "_lutkit_prog=" << shellQuoted(lutkit()) << "\nwords=(apply --config "
                       << shellQuoted(studioConfig()) << " --display Phone --view '')\n"
                       << "_lutkit_names views\n_lutkit_names looks\n"
                       << "words=(apply --from '')\n_lutkit_names spaces\n";
    const RunResult r = runCommand("env -u OCIO zsh -f " + shellQuoted(run));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("Bright\nwarm\ncool\nLinear Rec.709 (sRGB)\nsRGB\n"));
}
