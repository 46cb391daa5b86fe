// SPDX-License-Identifier: Apache-2.0
#pragma once
// The lutkit command line as plain data, read from the CLI11 option tables: what the man page
// and the shell completions are generated from, and what the vocabulary test checks.
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace lut::cli {

struct OptionEntry {
    std::vector<std::string> shortNames; // "-o"
    std::vector<std::string> longNames;  // "--output-dir" (aliases too: "--interpolation")
    std::string positional;              // "IN" for a positional argument, else ""
    std::string valueName; // "FILE", "DIR", "NAME", "INT" ...; "" for a flag (no value)
    std::string help;
    std::vector<std::string> values;     // the fixed set of values, when there is one
    std::vector<std::string> validators; // validator names ("choices:layout", "moved" ...)
    bool required = false;
    bool repeatable = false; // takes several values or may be given several times
    bool hidden = false;     // not in --help (moved options)

    std::string displayName() const; // "-o, --output-dir" or "IN"
};

struct CommandEntry {
    std::string name;
    std::string description;
    std::string footer; // more help, with the examples
    std::vector<OptionEntry> options;
};

struct ProgramEntry {
    std::string name;
    std::string description;
    std::string footer;
    std::vector<OptionEntry> options; // lutkit's own: -h, -V
    std::vector<CommandEntry> commands;
};

// Reads every subcommand of app (hidden ones excluded) and every option (help flags included).
ProgramEntry describeProgram(CLI::App& app);

// The example command lines of a help footer: its lines that start with "  lutkit ", each
// without the leading blanks and without a trailing "# comment".
std::vector<std::string> footerExamples(const std::string& footer);

} // namespace lut::cli
