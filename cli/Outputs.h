// SPDX-License-Identifier: Apache-2.0
#pragma once
// The output options every writing subcommand shares (-o, -y, -n) and the one place the CLI
// applies the library's output rule (lut/io/OutputPolicy.h), so every command refuses an existing
// output the same way and names the same flag.
#include "lut/io/OutputPolicy.h"

#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
} // namespace CLI

namespace lut::cli {

struct OutputOptions {
    std::string output;     // -o: a file, a folder (existing, or ending in /), a pattern, or -
    bool overwrite = false; // -y
    bool noClobber = false; // -n
    ExistingOutput rule() const {
        return overwrite   ? ExistingOutput::Replace
               : noClobber ? ExistingOutput::Skip
                           : ExistingOutput::Refuse;
    }
};

// The one rule for what lutkit prints when a command's data goes to standard output ("-",
// /dev/stdout, /dev/fd/1, /proc/self/fd/1, or any path that is the file descriptor 1): the data
// alone is on stdout, every note, report, JSON and "wrote" line on stderr. Whether a path
// writes to standard output:
bool writesToStdout(const std::string& path);
// Called (by resolveOutput, beginOutput and the batch planner) once a command knows its data goes
// to standard output: from then on everything the command prints to std::cout goes to stderr.
// The data itself is written to the file descriptor (lut/io/OutputFile.h), never through
// std::cout. Idempotent.
void reserveStdoutForData();
// reserveStdoutForData() when writesToStdout(path).
void noteOutputPath(const std::string& path);

// -y/--overwrite and -n/--no-clobber (exclusive).
void addOverwriteOptions(CLI::App& sub, OutputOptions& target);
// -o/--output PATH (old spelling --output-dir), plus -y and -n.
CLI::Option* addOutputOptions(CLI::App& sub, OutputOptions& target, const std::string& help);

// The message for an output that exists: "OUT: already exists; pass -y/--overwrite to replace
// it" (with -n/--no-clobber named when several files are written).
std::string existsMessage(const std::string& path, bool batch);

// The outputs of the command this run executes (lut::CommandOutputs): no two are one file.
CommandOutputs& commandOutputs();

// checkOutput with the rule of `options` through commandOutputs(), an existing file reported with
// existsMessage (as lut::Error: exit code 1). inputs are every file the command reads (the LUT
// too).
OutputTarget resolveOutput(const std::string& path, const OutputOptions& options,
                           const std::vector<std::string>& inputs);

// resolveOutput for the commands with one positional OUT: false when -n found the file there
// (said on stderr unless quiet): the command then writes nothing and succeeds.
bool beginOutput(const std::string& path, const OutputOptions& options,
                 const std::vector<std::string>& inputs, bool quiet);

} // namespace lut::cli
