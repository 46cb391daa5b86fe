// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit mix A B OUT --strength t: (1 - t) A + t B per entry on A's lattice (lut/ops/Compose.h).
#include "Notes.h"
#include "Outputs.h"

#include "lut/interp/Interpolation.h"

#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace lut::cli {

struct MixCommandOptions {
    std::string a, b, output;
    std::string format;
    double strength = 0.5; // t: 0 = A, 1 = B
    Interpolation interp = Interpolation::Tetrahedral;
    std::string target;      // what OUT is for ("" = smash for a .nutexb, else A's)
    std::string inTarget;    // what A and B are for ("" = what each file says, else raw)
    OutputOptions overwrite; // -y / -n (the output is the positional OUT)
    Verbosity verbosity;
};

int runMix(const MixCommandOptions& options);

CLI::App* setupMix(CLI::App& app, std::function<void(const MixCommandOptions&)> onParsed);

} // namespace lut::cli
