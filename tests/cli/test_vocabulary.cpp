// SPDX-License-Identifier: Apache-2.0
// One vocabulary across lutkit (issue 18), checked on every subcommand's option table as lutkit_cli
// builds it: an option name means the same thing everywhere, the names the issue fixes mean what
// it says, every value from a fixed set is validated, any bad value is bad usage (exit 2), and
// the examples in every --help parse.
#include "CliTableSupport.h"

#include "Vocabulary.h"

#include "lut/Version.h"
#include "lut/io/Layout.h"
#include "lut/pipeline/Pipeline.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>
#include <set>

using lut::cli::CommandEntry;
using lut::cli::OptionEntry;
using lut::test::programTable;
using lut::test::runInProcess;
using ::testing::HasSubstr;

namespace {

// What an option name stands for, apart from its help text.
struct Meaning {
    std::vector<std::string> shortNames;
    std::vector<std::string> longNames;
    std::string valueName;         // "" = a flag
    std::set<std::string> choices; // "choices:*" validators
    bool operator==(const Meaning& o) const {
        return shortNames == o.shortNames && longNames == o.longNames && valueName == o.valueName &&
               choices == o.choices;
    }
};

// --format / --in-format are the output / input format everywhere; the commands that write or
// read images (apply, preview) take image format names (png, exr ...) where the LUT commands take
// LUT format names: one meaning, two lists of names.
std::string sameMeaning(const OptionEntry& o, const std::string& validator) {
    if (validator != "choices:image-format" || o.longNames.empty())
        return validator;
    if (o.longNames.front() == "--format")
        return "choices:format";
    if (o.longNames.front() == "--in-format")
        return "choices:in-format";
    return validator;
}

Meaning meaningOf(const OptionEntry& o) {
    Meaning m{o.shortNames, o.longNames, o.valueName, {}};
    for (const auto& v : o.validators)
        if (v.rfind(lut::cli::kChoicesValidatorPrefix, 0) == 0)
            m.choices.insert(sameMeaning(o, v));
    return m;
}

std::string str(const Meaning& m) {
    std::string s;
    for (const auto& n : m.shortNames)
        s += n + " ";
    for (const auto& n : m.longNames)
        s += n + " ";
    s += "<" + m.valueName + ">";
    for (const auto& c : m.choices)
        s += " " + c;
    return s;
}

// Visible named options of a command, --help excluded.
std::vector<OptionEntry> namedOptions(const CommandEntry& c) {
    std::vector<OptionEntry> out;
    for (const auto& o : c.options)
        if (o.positional.empty() && !o.hidden &&
            std::find(o.longNames.begin(), o.longNames.end(), "--help") == o.longNames.end())
            out.push_back(o);
    return out;
}

const OptionEntry* findOption(const CommandEntry& c, const std::string& name) {
    for (const auto& o : c.options) {
        if (std::find(o.longNames.begin(), o.longNames.end(), name) != o.longNames.end() ||
            std::find(o.shortNames.begin(), o.shortNames.end(), name) != o.shortNames.end())
            return &o;
    }
    return nullptr;
}

// A command line that satisfies every required argument of c (a name from the fixed set where
// it has one), with `extra` appended.
std::string minimalLine(const CommandEntry& c, const std::string& extra) {
    std::string line = c.name;
    for (const auto& o : c.options)
        if (o.required) {
            const bool number =
                o.valueName == "INT" || o.valueName == "UINT" || o.valueName == "FLOAT";
            // a value from the fixed set where there is one (atlas ACTION)
            line += (o.positional.empty() ? " " + o.longNames.front() : std::string()) +
                    (!o.values.empty() ? " " + o.values.front()
                     : number          ? " 2"
                                       : " x");
        }
    return line + " " + extra;
}

} // namespace

TEST(Vocabulary, EveryCommandIsInTheTable) {
    const auto p = programTable();
    std::vector<std::string> names;
    for (const auto& c : p.commands)
        names.push_back(c.name);
    EXPECT_EQ(names, (std::vector<std::string>{
                         "neutral", "convert", "info",   "validate", "apply",  "preview",
                         "embed",   "extract", "fit",    "match",    "bench",  "bake",
                         "diff",    "compose", "invert", "resize",   "smooth", "mix",
                         "plot",    "adjust",  "check",  "chart",    "atlas",  "help"}));
}

TEST(Vocabulary, AnOptionNameMeansTheSameEverywhere) {
    const auto p = programTable();
    std::map<std::string, std::pair<std::string, Meaning>> seen; // name -> (command, meaning)
    for (const auto& c : p.commands)
        for (const auto& o : namedOptions(c)) {
            const Meaning m = meaningOf(o);
            std::vector<std::string> all = o.shortNames;
            all.insert(all.end(), o.longNames.begin(), o.longNames.end());
            for (const auto& name : all) {
                const auto [it, fresh] = seen.emplace(name, std::make_pair(c.name, m));
                EXPECT_TRUE(fresh || it->second.second == m)
                    << name << " in " << c.name << " is " << str(m) << " but in "
                    << it->second.first << " it is " << str(it->second.second);
            }
        }
    EXPECT_GT(seen.size(), 30u);
}

TEST(Vocabulary, TheNamesIssue18Fixes) {
    const auto p = programTable();
    // option -> the choices validator it must have (cli/Vocabulary.h)
    const std::map<std::string, std::string> named = {
        {"--format", "choices:format"},     {"--in-format", "choices:in-format"},
        {"--layout", "choices:layout"},     {"--in-layout", "choices:layout"},
        {"--lut-layout", "choices:layout"}, {"--interp", "choices:interp"},
        {"--preset", "choices:preset"},     {"--bit-depth", "choices:bit-depth"},
    };
    std::map<std::string, int> uses;
    for (const auto& c : p.commands) {
        for (const auto& [name, kind] : named)
            if (const OptionEntry* o = findOption(c, name); o && !o->hidden) {
                ++uses[name];
                std::vector<std::string> kinds;
                for (const auto& v : o->validators)
                    kinds.push_back(sameMeaning(*o, v));
                EXPECT_NE(std::find(kinds.begin(), kinds.end(), kind), kinds.end())
                    << c.name << " " << name << " lacks " << kind;
            }
        // Short names: one meaning each, everywhere.
        const std::map<std::string, std::string> shorts = {
            {"-v", "--verbose"},   {"-q", "--quiet"},      {"-o", "--output"},
            {"-y", "--overwrite"}, {"-n", "--no-clobber"}, {"-h", "--help"}};
        for (const auto& o : c.options)
            for (const auto& s : o.shortNames) {
                ASSERT_TRUE(shorts.count(s))
                    << c.name << " uses " << s << ", not in the vocabulary";
                EXPECT_EQ(o.longNames.front(), shorts.at(s)) << c.name << " " << s;
                EXPECT_NE(s, "-V") << c.name << ": -V is --version, lutkit's own";
            }
        // --interpolation exists only as the old spelling of --interp.
        if (const OptionEntry* o = findOption(c, "--interpolation")) {
            EXPECT_EQ(o->longNames.front(), "--interp") << c.name;
        }
    }
    for (const auto& [name, kind] : named)
        EXPECT_GT(uses[name], 0) << name << " is used by no command";

    // The commands that only read a LUT name it with --in-*; --format/--layout (the output) is
    // not theirs.
    for (const auto& c : p.commands)
        if (c.name == "info" || c.name == "validate") {
            ASSERT_NE(findOption(c, "--in-format"), nullptr) << c.name;
            ASSERT_NE(findOption(c, "--in-layout"), nullptr) << c.name;
            const OptionEntry* f = findOption(c, "--format");
            EXPECT_TRUE(!f || f->hidden) << c.name;
        }
    // lutkit's own: -V/--version and -h/--help.
    bool version = false;
    for (const auto& o : p.options)
        version = version || (o.shortNames == std::vector<std::string>{"-V"} &&
                              o.longNames == std::vector<std::string>{"--version"});
    EXPECT_TRUE(version);
}

TEST(Vocabulary, EveryValueFromAFixedSetIsValidated) {
    const auto p = programTable();
    // Value names of options whose values are free: files, folders, paths (-o: a file, a folder
    // or a frame pattern), numbers (CLI11 converts and ranges check them), frame ranges and
    // memory sizes (their own validators) and two pieces of text.
    // SPACE, LOOKS, DISPLAY, VIEW (colour management) and ID (a CCC id) name things of an
    // OpenColorIO config or file that the command line may name after them: checked when the
    // command runs, against the config's own lists (lut::formats::ColorOptionError, exit 2).
    const std::set<std::string> free = {"FILE",  "DIR",     "PATH",  "INT",  "UINT",
                                        "FLOAT", "TEXT",    "RANGE", "SIZE", "SPACE",
                                        "LOOKS", "DISPLAY", "VIEW",  "ID"};
    const std::set<std::string> freeText = {"--name", "--title", "--stage"};
    for (const auto& c : p.commands)
        for (const auto& o : c.options) {
            if (o.valueName.empty() || o.hidden)
                continue;
            const std::string name = o.displayName();
            if (free.count(o.valueName)) {
                if (o.valueName == "TEXT") {
                    EXPECT_TRUE(freeText.count(o.longNames.empty() ? "" : o.longNames.front()))
                        << c.name << " " << name << " takes free text: give it a value name "
                        << "(FILE, DIR) or a validator";
                }
                continue;
            }
            bool choices = false;
            for (const auto& v : o.validators)
                choices = choices || v.rfind(lut::cli::kChoicesValidatorPrefix, 0) == 0;
            EXPECT_TRUE(choices) << c.name << " " << name << " <" << o.valueName << ">";
            EXPECT_FALSE(o.values.empty()) << c.name << " " << name;
        }
    // The validators list what the library names (not a copy typed in the CLI).
    const auto layouts = findOption(p.commands[1], "--layout");
    ASSERT_NE(layouts, nullptr);
    std::vector<std::string> libraryLayouts;
    for (const auto l : lut::allLayouts())
        libraryLayouts.push_back(lut::toString(l));
    EXPECT_EQ(layouts->values, libraryLayouts);
    const auto* presets = findOption(p.commands[5], "--preset");
    ASSERT_NE(presets, nullptr);
    std::vector<std::string> libraryPresets;
    for (const auto pr : lut::allPresets())
        libraryPresets.push_back(lut::toString(pr));
    EXPECT_EQ(presets->values, libraryPresets);
    const auto* stages = findOption(p.commands[5], "--enable");
    ASSERT_NE(stages, nullptr);
    EXPECT_EQ(stages->values, lut::stageNames());
}

TEST(Vocabulary, AnyBadValueIsBadUsage) {
    const auto p = programTable();
    int checked = 0;
    for (const auto& c : p.commands)
        for (const auto& o : c.options) {
            if (o.values.empty() || o.hidden || !o.positional.empty())
                continue;
            const std::string line = minimalLine(c, o.longNames.front() + " zzqq");
            SCOPED_TRACE(line);
            const auto r = runInProcess(line);
            EXPECT_EQ(r.exitCode, 2) << r.err;
            EXPECT_THAT(r.err, HasSubstr("'zzqq'"));
            ++checked;
        }
    EXPECT_GT(checked, 15);
    // Missing values and unknown options too.
    EXPECT_EQ(runInProcess("convert a.cube b.cube --size").exitCode, 2);
    EXPECT_EQ(runInProcess("convert a.cube b.cube --size x").exitCode, 2);
    EXPECT_EQ(runInProcess("convert a.cube").exitCode, 2);
    EXPECT_EQ(runInProcess("info a.cube --nope").exitCode, 2);
    EXPECT_EQ(runInProcess("preview a.png b.png --stage vignette.strengh=1").exitCode, 2);
    EXPECT_EQ(runInProcess("preview a.png b.png --disable nosuch").exitCode, 2);
    EXPECT_EQ(runInProcess("nosuch").exitCode, 2);
}

// CLI11 reads "nan" and "inf" as numbers and its range checks let NaN through: `lutkit mix A B
// o.cube --strength nan` wrote a LUT of NaN, exit 0 (issue 29). Every FLOAT option of every
// command refuses them as bad usage, the stage settings of preview too.
TEST(Vocabulary, NotANumberAndInfinityAreBadUsageForEveryNumberOption) {
    const auto p = programTable();
    int checked = 0;
    for (const auto& c : p.commands)
        for (const auto& o : c.options) {
            if (o.valueName != "FLOAT" || o.hidden || !o.positional.empty())
                continue;
            for (const char* value : {"nan", "NaN", "inf", "-inf", "infinity"}) {
                const std::string line = minimalLine(c, o.longNames.front() + " " + value);
                SCOPED_TRACE(line);
                const auto r = runInProcess(line);
                EXPECT_EQ(r.exitCode, 2) << r.err;
                // A range check says so first for the infinities; NaN passes every range.
                const bool nan = std::string(value) == "nan" || std::string(value) == "NaN";
                if (nan || r.err.find("not in range") == std::string::npos) {
                    EXPECT_THAT(r.err, HasSubstr("value " + std::string(value) +
                                                 " is not a finite number"));
                }
            }
            ++checked;
        }
    EXPECT_GE(checked, 4); // mix --strength, smooth --sigma, fit --smoothness, diff --max-delta-e
    EXPECT_EQ(runInProcess("preview a.png b.png --stage vignette.strength=nan").exitCode, 2);
    EXPECT_EQ(runInProcess("mix a.cube b.cube o.cube --strength 0.25").exitCode, 0);
}

TEST(Vocabulary, OldNamesAndSpellingsStillWork) {
    lut::cli::RunHooks h = lut::test::stubHooks();
    lut::cli::PreviewOptions seen;
    h.preview = [&seen](const lut::cli::PreviewOptions& o) {
        seen = o;
        return 0;
    };
    auto r = runInProcess("preview a.png b.png --preset pilot --lut-layout godot --enable "
                          "sugar-bloom --stage sugar-bloom.f0=0.5 --stage filter-bloom.knee=0.2 "
                          "--interp linear",
                          h);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(seen.preset, lut::Preset::Pilot);
    EXPECT_EQ(seen.lutLayout, lut::LutLayout::Pilot);
    EXPECT_EQ(seen.interp, lut::Interpolation::Trilinear);
    r = runInProcess("preview a.png b.png --preset lecture", h);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(seen.preset, lut::Preset::Lecture);

    lut::cli::BenchOptions bench;
    h.bench = [&bench](const lut::cli::BenchOptions& o) {
        bench = o;
        return 0;
    };
    r = runInProcess("bench --interpolation nearest,tetra", h);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(bench.methods, (std::vector<lut::Interpolation>{lut::Interpolation::Nearest,
                                                              lut::Interpolation::Tetrahedral}));
    EXPECT_EQ(runInProcess("convert a.cube b.png --layout pilot --in-layout lattice").exitCode, 0);
    EXPECT_EQ(runInProcess("embed a.png b.png --lattice smash --corner bottom-left").exitCode, 0);
}

TEST(Vocabulary, EveryCommandHasExamplesThatParse) {
    const auto p = programTable();
    for (const auto& c : p.commands) {
        const auto examples = lut::cli::footerExamples(c.footer);
        EXPECT_FALSE(examples.empty()) << c.name << " --help has no examples";
        EXPECT_THAT(c.footer, HasSubstr("Examples:")) << c.name;
        for (const auto& e : examples) {
            SCOPED_TRACE(e);
            ASSERT_EQ(e.rfind("lutkit " + c.name, 0), 0u) << "an example of another command";
            const auto r = runInProcess(e.substr(7));
            EXPECT_EQ(r.exitCode, 0) << r.err;
        }
    }
}

TEST(Vocabulary, VersionAndHelp) {
    auto r = runInProcess("-V");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out, std::string("lutkit ") + LUTKIT_VERSION + "\n");
    r = runInProcess("--version");
    EXPECT_EQ(r.out, std::string("lutkit ") + LUTKIT_VERSION + "\n");
    r = runInProcess("help");
    EXPECT_EQ(r.exitCode, 0);
    for (const auto& c : programTable().commands)
        EXPECT_THAT(r.out, HasSubstr(c.name));
    r = runInProcess("help convert");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("--in-layout"));
    EXPECT_THAT(r.out, HasSubstr("Examples:"));
    EXPECT_EQ(runInProcess("convert --help").out, r.out);
    r = runInProcess("help nuetral");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("did you mean 'neutral'?"));
    r = runInProcess("nuetral x.cube");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("unknown command 'nuetral'; did you mean 'neutral'?"));
    r = runInProcess("conv a.cube b.cube");
    EXPECT_THAT(r.err, HasSubstr("did you mean 'convert'?"));
    // `help help` is help's help (it said "unknown command 'help'. Run 'lutkit help help'").
    r = runInProcess("help help");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("lutkit help [OPTIONS] [COMMAND]"));
}

// A misspelt option is named (issue 43): `apply --lutt` said only "--lut is required"; `--v`
// could be -v or any long option starting with v, and lutkit does not abbreviate: said so, where
// it suggested --view.
TEST(Vocabulary, MisspeltOptionsAreNamed) {
    auto r = runInProcess("apply --lutt a.cube shot.png -o out.png");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("lutkit apply: --lutt: no such option"));
    EXPECT_THAT(r.err, HasSubstr("did you mean '--lut'?"));
    EXPECT_THAT(r.err, ::testing::Not(HasSubstr("required")));
    r = runInProcess("bake out.cube --v foo --lut a.cube");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_THAT(r.err, HasSubstr("'--v' is ambiguous: a short option takes one dash (bake has no "
                                 "-v), a long one is written in full (--view)"));
    EXPECT_THAT(r.err, ::testing::Not(HasSubstr("did you mean")));
    r = runInProcess("convert a.cube b.cube --v");
    EXPECT_THAT(r.err, HasSubstr("(-v is --verbose)"));
    r = runInProcess("convert a.cube b.cube --in");
    EXPECT_THAT(r.err, HasSubstr("'--in' is ambiguous: --in-format, --in-layout, --interp, "));
    r = runInProcess("convert a.cube b.cube --layuot unreal");
    EXPECT_THAT(r.err, HasSubstr("did you mean '--layout'?"));
}
