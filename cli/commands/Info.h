// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit info IN: what a LUT file holds, as text or JSON.
#include "Notes.h"

#include "lut/io/Layout.h"

#include <functional>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace lut::cli {

struct InfoOptions {
    std::string input;
    std::string inFormat;              // input format name ("" = from the extension)
    std::optional<LutLayout> inLayout; // LUT images: the layout (default: detected)
    int size = 0;                      // lattice size when sampling foreign (OpenColorIO) formats
    bool json = false;
    Verbosity verbosity;
};

// "near" neutral: every entry within half an 8-bit step of the identity, so an 8-bit store of it
// is exactly the 8-bit neutral.
constexpr double kNearNeutralTolerance = 0.5 / 255.0;
constexpr double kExactNeutralTolerance = 1e-6;

int runInfo(const InfoOptions& options);

// Adds the subcommand to app; onParsed is called with the options once they are parsed.
CLI::App* setupInfo(CLI::App& app, std::function<void(const InfoOptions&)> onParsed);

} // namespace lut::cli
