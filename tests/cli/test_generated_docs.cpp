// SPDX-License-Identifier: Apache-2.0
// The man page and the shell completions the build generates (cli/CMakeLists.txt runs
// `lutkit --generate KIND`): they exist, name every command and option of the option tables (read
// through lutkit_cli, not a copied list), render (man -l) or parse (bash -n, zsh -n, fish -n when
// the shell is installed), and the bash completion completes.
#include "CliTableSupport.h"
#include "TestPaths.h"

#include "TestSupport.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {

std::string generated(const std::string& name) {
    return std::string(LUTKIT_BINARY_DIR) + "/cli/" + name;
}

using lut::test::fileBytes;

struct Shell {
    int exitCode = -1;
    std::string out;
};

// Runs a /bin/sh command line, stdout captured (stderr joins it when the line says 2>&1).
Shell sh(const std::string& command) {
    Shell r;
    FILE* p = ::popen(command.c_str(), "r");
    if (!p)
        return r;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;)
        r.out.append(buf, n);
    const int status = ::pclose(p);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

bool have(const std::string& program) {
    return sh("command -v " + program + " >/dev/null 2>&1").exitCode == 0;
}

// In roff, '-' is written "\-".
std::string roffName(const std::string& option) {
    std::string s;
    for (const char c : option)
        s += c == '-' ? std::string("\\-") : std::string(1, c);
    return s;
}

// fish names a long option "-l name".
std::string fishName(const std::string& option) {
    return "-l " + option.substr(2);
}

// Every command and every visible option name of the table appears in text (names transformed
// by spell, e.g. for roff).
void expectMentionsEverything(const std::string& text,
                              std::string (*spell)(const std::string&) = nullptr,
                              std::string (*spellValue)(const std::string&) = nullptr) {
    const auto p = lut::test::programTable();
    for (const auto& c : p.commands) {
        EXPECT_NE(text.find(c.name), std::string::npos) << c.name;
        for (const auto& o : c.options) {
            if (o.hidden || !o.positional.empty())
                continue;
            for (const auto& n : o.longNames)
                EXPECT_NE(text.find(spell ? spell(n) : n), std::string::npos) << c.name << " " << n;
            for (const auto& v : o.values)
                EXPECT_NE(text.find(spellValue ? spellValue(v) : v), std::string::npos)
                    << c.name << " " << o.longNames.front() << " " << v;
        }
    }
}

std::string complete(const std::string& words, int cword) {
    const std::string script = "source '" + generated("completions/lutkit") + "'; COMP_WORDS=(" +
                               words + "); COMP_CWORD=" + std::to_string(cword) +
                               "; _lutkit; echo \"${COMPREPLY[*]}\"";
    const Shell r = sh("bash -c '" + [&] {
        std::string q;
        for (const char c : script)
            q += c == '\'' ? std::string("'\\''") : std::string(1, c);
        return q;
    }() + "'");
    EXPECT_EQ(r.exitCode, 0) << r.out;
    return r.out;
}

} // namespace

TEST(GeneratedDocs, ManPageNamesEveryCommandAndOptionAndRenders) {
    const std::string path = generated("lutkit.1");
    ASSERT_TRUE(fs::exists(path)) << path;
    const std::string man = fileBytes(path);
    EXPECT_EQ(man.rfind(".\\\"", 0), 0u) << "starts with a roff comment";
    EXPECT_THAT(man, HasSubstr(".TH LUTKIT 1"));
    EXPECT_THAT(man, HasSubstr("EXIT STATUS"));
    expectMentionsEverything(man, roffName, roffName);
    // The file is what lutkit generates now (the build is up to date).
    EXPECT_EQ(lut::test::runCli("--generate man").out, man);
    if (!have("man"))
        GTEST_SKIP() << "man is not installed";
    const Shell r = sh("MANWIDTH=100 man -l '" + path + "' 2>&1 >/dev/null");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out, "") << "warnings from man/groff";
    const Shell text = sh("MANWIDTH=100 man -l '" + path + "' 2>/dev/null");
    EXPECT_THAT(text.out, HasSubstr("lutkit convert [OPTIONS] IN [OUT]"));
}

// The man page's ENVIRONMENT names every variable lutkit reads (each std::getenv("NAME") in the
// sources of the libraries and the CLI, found here by reading them), EXIT STATUS every code, and
// SEE ALSO only pages man finds (issue 43: it named a missing lutkit-editor(1)).
TEST(GeneratedDocs, ManPageEnvironmentExitCodesAndSeeAlso) {
    const std::string man = fileBytes(generated("lutkit.1"));
    const auto env = man.find(".SH ENVIRONMENT\n");
    ASSERT_NE(env, std::string::npos);
    const std::string environment = man.substr(env, man.find(".SH ", env + 1) - env);
    std::set<std::string> read;
    for (const char* dir : {"lutlib/src", "formats/src", "cli"})
        for (const auto& f :
             fs::recursive_directory_iterator(std::string(LUTKIT_SOURCE_DIR) + "/" + dir)) {
            if (f.path().extension() != ".cpp" ||
                f.path().string().find("/os/windows/") != std::string::npos)
                continue;
            const std::string text = fileBytes(f.path().string());
            for (std::size_t at = 0; (at = text.find("getenv(\"", at)) != std::string::npos;) {
                at += 8;
                read.insert(text.substr(at, text.find('"', at) - at));
            }
        }
    EXPECT_TRUE(read.count("OCIO") && read.count("LUTKIT_SIMD") &&
                read.count("LUTKIT_IMAGEIO_MODULE"))
        << "the scan found what the sources read";
    for (const std::string& name : read)
        EXPECT_THAT(environment, HasSubstr(".B " + name + "\n")) << name;
    EXPECT_THAT(environment, HasSubstr(".B TMPDIR\n")); // std::filesystem's temp_directory_path

    const auto exit = man.find(".SH EXIT STATUS\n");
    ASSERT_NE(exit, std::string::npos);
    for (const char* code : {"0", "1", "2", "130"})
        EXPECT_THAT(man.substr(exit), HasSubstr(".TP\n" + std::string(code) + "\n")) << code;

    const auto see = man.find(".SH SEE ALSO\n");
    ASSERT_NE(see, std::string::npos);
    const std::string seeAlso = man.substr(see);
    EXPECT_EQ(seeAlso.find("lutkit\\-editor"), std::string::npos);
    if (!have("man"))
        GTEST_SKIP() << "man is not installed";
    int pages = 0;
    for (std::size_t at = 0; (at = seeAlso.find(".BR ", at)) != std::string::npos; ++pages) {
        at += 4;
        const std::string page = seeAlso.substr(at, seeAlso.find(' ', at) - at);
        EXPECT_EQ(sh("man -w '" + page + "' >/dev/null 2>&1").exitCode, 0) << page << "(1)";
    }
    EXPECT_GT(pages, 0);
}

TEST(GeneratedDocs, CompletionScriptsNameEveryCommandAndOption) {
    for (const char* name : {"completions/lutkit", "completions/_lutkit"}) {
        SCOPED_TRACE(name);
        ASSERT_TRUE(fs::exists(generated(name)));
        expectMentionsEverything(fileBytes(generated(name)), nullptr);
    }
    ASSERT_TRUE(fs::exists(generated("completions/lutkit.fish")));
    expectMentionsEverything(fileBytes(generated("completions/lutkit.fish")), fishName);
    EXPECT_EQ(sh("bash -n '" + generated("completions/lutkit") + "'").exitCode, 0);
    if (have("zsh")) {
        EXPECT_EQ(sh("zsh -n '" + generated("completions/_lutkit") + "' 2>&1").exitCode, 0);
    }
    if (have("fish")) {
        EXPECT_EQ(sh("fish -n '" + generated("completions/lutkit.fish") + "' 2>&1").exitCode, 0);
    }
}

TEST(GeneratedDocs, BashCompletesCommandsOptionsAndValues) {
    ASSERT_TRUE(fs::exists(generated("completions/lutkit")));
    EXPECT_EQ(complete("lutkit conv", 1), "convert\n");
    EXPECT_EQ(complete("lutkit convert --lay", 2), "--layout\n");
    EXPECT_EQ(complete("lutkit convert a.cube --in-l", 3), "--in-layout\n");
    EXPECT_EQ(complete("lutkit convert a.cube b.png --layout ''", 5),
              "unreal unity smush hald reshade unity-32\n");
    EXPECT_EQ(complete("lutkit preview a.png b.png --preset f", 5), "filmic\n");
    EXPECT_EQ(complete("lutkit help pre", 2), "preview\n");
    EXPECT_EQ(complete("lutkit -", 1), "-V --version -h --help\n");
}
