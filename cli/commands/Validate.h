// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit validate FILE...: parse LUT files and report problems with file:line:col.
#include "Notes.h"

#include "lut/io/Layout.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace lut::cli {

struct ValidateOptions {
    std::vector<std::string> inputs;
    bool strict = false;               // report every departure from the Adobe 1.0 .cube spec
    std::string inFormat;              // input format name ("" = from the extension)
    std::optional<LutLayout> inLayout; // LUT images: the layout (default: detected)
    Verbosity verbosity;
};

// Parses each file and reports: "FILE: ok (adobe 3D, 33^3)" on stdout for a good file,
// "FILE:line:col: warning: ..." lines on stdout for departures (--strict) and notes, and
// "FILE:line:col: error: ..." on stderr for a file that does not parse. Exit 1 if any file has
// an error or (with --strict) any departure, 0 otherwise.
int runValidate(const ValidateOptions& options);

// Adds the subcommand to app; onParsed is called with the options once they are parsed.
CLI::App* setupValidate(CLI::App& app, std::function<void(const ValidateOptions&)> onParsed);

} // namespace lut::cli
