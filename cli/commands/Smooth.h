// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit smooth A OUT --sigma S: a Gaussian blur of the LUT's deviation from the identity, with
// how much it changed the LUT (lut/ops/Smooth.h).
#include "Notes.h"
#include "Outputs.h"

#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace lut::cli {

struct SmoothCommandOptions {
    std::string input, output;
    std::string format;
    double sigma = 1.0;      // lattice steps
    OutputOptions overwrite; // -y / -n (the output is the positional OUT)
    Verbosity verbosity;
};

int runSmooth(const SmoothCommandOptions& options);

CLI::App* setupSmooth(CLI::App& app, std::function<void(const SmoothCommandOptions&)> onParsed);

} // namespace lut::cli
