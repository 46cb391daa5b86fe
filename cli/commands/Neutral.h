// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit neutral OUT: a neutral (identity) LUT in any writable format.
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

struct NeutralOptions {
    std::string output;
    std::string format;              // output format name ("" = from the extension)
    std::optional<LutLayout> layout; // LUT images: the layout (default: the format's)
    int size = 0;                    // 0 = kNeutralSize, or what the destination fixes
    int level = 0;                   // Hald level L (N = L^2, layout hald); 0 = use size
    int bitDepth = 0;                // LUT images: 8, 16 or 32 (0 = the format's default)
    std::string name;                // nutexb name field
    std::string title;
    OutputOptions overwrite; // -y / -n (the output is the positional OUT)
    Verbosity verbosity;
};

// The lattice size `lutkit neutral` writes when --size is not given and the destination fixes
// none (lut/formats/LutDestination.h, newTableSize: the format's fixed size, nutexb's 16; 16 for
// LUT images, the 256x16 strip every engine expects, a Hald of level 4): 33 for every text/float
// LUT format (.cube, .3dl, .csp, .clf ... the size grading tools default to).
constexpr int kNeutralSize = 33;

int runNeutral(const NeutralOptions& options);

// Adds the subcommand to app; onParsed is called with the options once they are parsed.
CLI::App* setupNeutral(CLI::App& app, std::function<void(const NeutralOptions&)> onParsed);

} // namespace lut::cli
