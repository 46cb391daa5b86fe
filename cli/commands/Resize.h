// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit resize A OUT --size N: a LUT on another lattice, with the error that costs
// (lut/ops/Resize.h).
#include "Notes.h"
#include "Outputs.h"

#include "lut/interp/Interpolation.h"

#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace lut::cli {

struct ResizeCommandOptions {
    std::string input, output;
    std::string format;
    int size = 0; // required
    Interpolation interp = Interpolation::Tetrahedral;
    OutputOptions overwrite; // -y / -n (the output is the positional OUT)
    Verbosity verbosity;
};

int runResize(const ResizeCommandOptions& options);

CLI::App* setupResize(CLI::App& app, std::function<void(const ResizeCommandOptions&)> onParsed);

} // namespace lut::cli
