// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit embed SCREENSHOT OUT: paste a neutral LUT patch with a marker frame into a screenshot.
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

struct EmbedOptions {
    std::string input;
    std::string format; // image format for - (standard output); default: the screenshot's
    std::string output;
    std::string target = "smash";    // what the modder is making (raw | smash): recorded
    std::string originalLut;         // smash: the stage's LUT the screenshot was taken with
    std::string lattice;             // lattice name ("" = from the target; uniform with --size)
    int size = 16;                   // uniform lattice size
    std::optional<LutLayout> layout; // patch layout (default: hald for square sizes, else unreal)
    int scale = 0;                   // 0: 8, or the largest that fits a smaller screenshot
    std::string corner = "top-left";
    int margin = 8;
    OutputOptions overwrite; // -y / -n (the output is the positional OUT)
    Verbosity verbosity;
};

int runEmbed(const EmbedOptions& options);

// Adds the subcommand to app; onParsed is called with the options once they are parsed.
CLI::App* setupEmbed(CLI::App& app, std::function<void(const EmbedOptions&)> onParsed);

} // namespace lut::cli
