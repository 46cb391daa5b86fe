// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit plot LUT OUT.png: the per-channel curves along the neutral axis, three slices of the cube
// and the lattice in 3D, as one picture (lut/ops/Plot.h; the editor shows the same).
#include "Notes.h"
#include "Outputs.h"

#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace lut::cli {

struct PlotCommandOptions {
    std::string input, output;
    int latticePoints = 9;   // lattice points per axis in the 3D view
    std::string format;      // image format for - (standard output); default png
    OutputOptions overwrite; // -y / -n (the output is the positional OUT)
    Verbosity verbosity;
};

int runPlot(const PlotCommandOptions& options);

CLI::App* setupPlot(CLI::App& app, std::function<void(const PlotCommandOptions&)> onParsed);

} // namespace lut::cli
