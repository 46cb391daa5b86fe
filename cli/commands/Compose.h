// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit compose A B OUT: B after A as one LUT, at a size the user chooses, with the error of
// that size reported (lut/ops/Compose.h).
#include "Notes.h"
#include "Outputs.h"

#include "lut/interp/Interpolation.h"

#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace lut::cli {

struct ComposeCommandOptions {
    std::string a, b, output;
    std::string format; // output format ("" = by extension)
    int size = 0;       // 0 = the larger of the two
    Interpolation interp = Interpolation::Tetrahedral;
    std::string target;      // what OUT is for ("" = smash for a .nutexb, else A's)
    std::string inTarget;    // what A and B are for ("" = what each file says, else raw)
    OutputOptions overwrite; // -y / -n (the output is the positional OUT)
    Verbosity verbosity;
};

int runCompose(const ComposeCommandOptions& options);

CLI::App* setupCompose(CLI::App& app, std::function<void(const ComposeCommandOptions&)> onParsed);

} // namespace lut::cli
