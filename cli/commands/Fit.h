// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit fit BEFORE AFTER OUT: fit a 3D LUT to a before/after image pair.
#include "Notes.h"
#include "Outputs.h"

#include "lut/io/Layout.h"

#include <functional>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace lut::cli {

struct FitOptions {
    std::string before;
    std::string after;
    std::string output;
    int size = 33;
    double smoothness = 1.0;
    bool noRobust = false;
    std::string format;              // output format name ("" = by extension)
    std::optional<LutLayout> layout; // output layout for LUT images
    OutputOptions overwrite;         // -y / -n (the output is the positional OUT)
    Verbosity verbosity;
};

int runFit(const FitOptions& options);

// Adds the subcommand to app; onParsed is called with the options once they are parsed.
CLI::App* setupFit(CLI::App& app, std::function<void(const FitOptions&)> onParsed);

} // namespace lut::cli
