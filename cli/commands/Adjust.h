// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit adjust LUT --adjustments FILE OUT: the editor's adjustment list (exposure, contrast,
// lift/gamma/gain, curves, hue curves, strength: lut/ops/AdjustmentList.h) applied to a LUT.
#include "Notes.h"
#include "Outputs.h"

#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace lut::cli {

struct AdjustCommandOptions {
    std::string input, output;
    std::string adjustments; // the list's file
    std::string format;
    OutputOptions overwrite; // -y / -n (the output is the positional OUT)
    Verbosity verbosity;
};

int runAdjust(const AdjustCommandOptions& options);

CLI::App* setupAdjust(CLI::App& app, std::function<void(const AdjustCommandOptions&)> onParsed);

} // namespace lut::cli
