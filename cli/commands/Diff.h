// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit diff A B: how two LUTs differ, in ΔE2000 and 8-bit steps per channel, and where (named
// regions of the cube), over the lattice or over the colours of an image; a heat map PNG
// (lut/ops/Diff.h, lut/ops/HeatMap.h).
#include "Notes.h"
#include "Outputs.h"

#include "lut/interp/Interpolation.h"

#include <functional>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace lut::cli {

struct DiffCommandOptions {
    std::string a, b;
    std::string image;       // compare over this image's colours ("" = over the lattice)
    std::string heatmap;     // write a heat-map PNG here ("" = none)
    std::string format;      // the heat map's image format for - (standard output); default png
    int size = 0;            // lattice compared on (0 = the larger of the two)
    int slices = 5;          // heat map of the lattice: slices of the cube
    double maxDeltaE = 10.0; // ΔE at the top of the heat map's ramp (0 = the largest found)
    Interpolation interp = Interpolation::Tetrahedral;
    std::string inTarget; // what A and B are for ("" = what each file says, else an edit)
    bool json = false;
    std::optional<double> failAbove; // exit 1 when the largest ΔE2000 is above this
    OutputOptions overwrite;         // -y / -n for --heatmap
    Verbosity verbosity;
};

// Exit code 0 whether or not the LUTs differ (1 is for bad input); with --fail-above DE, 1 when
// the largest ΔE2000 found is above DE (as cmp exits 1 when files differ), said on stderr.
int runDiff(const DiffCommandOptions& options);

CLI::App* setupDiff(CLI::App& app, std::function<void(const DiffCommandOptions&)> onParsed);

} // namespace lut::cli
