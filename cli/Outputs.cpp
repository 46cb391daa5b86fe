// SPDX-License-Identifier: Apache-2.0
#include "Outputs.h"

#include "Notes.h"

#include "lut/io/FileNames.h"
#include "lut/os/Files.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace lut::cli {

bool writesToStdout(const std::string& path) {
    if (path == "-" || path == "/dev/stdout" || path == "/dev/fd/1" || path == "/proc/self/fd/1")
        return true;
    os::FileInfo p, out;
    // A special file that is our standard output (a terminal, a pipe): the same device and inode.
    return !path.empty() && os::fileInfo(path, p) == 0 && p.type != os::FileType::Regular &&
           p.type != os::FileType::Directory && os::openFileInfo(1, out) == 0 &&
           p.device == out.device && p.inode == out.inode;
}

void reserveStdoutForData() {
    static bool done = false;
    if (done)
        return;
    done = true;
    std::cout.flush();
    redirectReport(std::cerr.rdbuf()); // under -q: after the command (Notes.h)
}

void noteOutputPath(const std::string& path) {
    if (writesToStdout(path))
        reserveStdoutForData();
}

void addOverwriteOptions(CLI::App& sub, OutputOptions& o) {
    auto* y = sub.add_flag("-y,--overwrite", o.overwrite, "replace output files that exist");
    auto* n = sub.add_flag("-n,--no-clobber", o.noClobber,
                           "leave output files that exist alone (skip them)");
    y->excludes(n);
}

CLI::Option* addOutputOptions(CLI::App& sub, OutputOptions& o, const std::string& help) {
    auto* opt = sub.add_option("-o,--output,--output-dir", o.output, help)->type_name("PATH");
    addOverwriteOptions(sub, o);
    return opt;
}

std::string existsMessage(const std::string& path, bool batch) {
    return path + ": already exists; pass -y/--overwrite to replace it" +
           (batch ? " (or -n/--no-clobber to skip existing outputs)" : "");
}

CommandOutputs& commandOutputs() {
    static CommandOutputs outputs;
    return outputs;
}

OutputTarget resolveOutput(const std::string& path, const OutputOptions& options,
                           const std::vector<std::string>& inputs) {
    noteOutputPath(path);
    try {
        return commandOutputs().claim(path, options.rule(), inputs);
    } catch (const OutputExistsError& e) {
        throw Error(existsMessage(e.path(), false));
    }
}

bool beginOutput(const std::string& path, const OutputOptions& options,
                 const std::vector<std::string>& inputs, bool quiet) {
    if (resolveOutput(path, options, inputs).skip) {
        if (!quiet)
            std::cerr << "lutkit: " << printable(path) << " exists; skipped (-n)\n";
        return false;
    }
    return true;
}

} // namespace lut::cli
