// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit bench: error against run time for the LUT kernels, against OpenColorIO and a copy.
#include "lut/interp/Interpolation.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace CLI {
class App;
}

namespace lut::cli {

struct BenchOptions {
    int width = 3840;
    int height = 2160;
    int threads = 0;                        // 0 = all cores
    int reps = 3;                           // timed runs per row; the best is reported
    std::vector<int> sizes{16, 17, 33, 65}; // LUT edge sizes
    std::vector<Interpolation> methods{Interpolation::Nearest, Interpolation::Trilinear,
                                       Interpolation::Tetrahedral};
    bool ocio = true;    // also time OpenColorIO's CPU processor
    bool scalar = false; // add rows for the scalar reference loop
    bool json = false;   // the figures as JSON on standard output instead of the table
};

// One row another subsystem adds below the kernel table (see Bench.cpp, "EXTRA ROWS").
struct BenchExtraRow {
    std::string label;                                  // e.g. "smash chain 1080p"
    double nsPerPixel = 0;                              // wall time per pixel
    std::string note;                                   // free text (error, ratio, ...)
    std::vector<std::pair<std::string, double>> values; // the same figures for --json
};

// Prints, for each interpolation and size: ns/pixel on the frame, max and mean error against the
// analytic grade the LUT was sampled from, OCIO's CPU processor on the same LUT and pixels and
// the ratio OCIO/ours, and ours relative to a plain copy of the same bytes.
int runBench(const BenchOptions& options);

// Adds the subcommand to app; onParsed is called with the options once they are parsed.
CLI::App* setupBench(CLI::App& app, std::function<void(const BenchOptions&)> onParsed);

} // namespace lut::cli
