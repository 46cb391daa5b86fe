#pragma once
// lutkit extract EDITED OUT: find the patch in an edited screenshot and write the LUT it shows.
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

struct ExtractOptions {
    std::string input;
    std::string output;
    std::string target = "raw";      // target name (raw | smash)
    std::string originalLut;         // smash: the stage's LUT the screenshot was taken with
    int size = 0;                    // output size (0: raw = patch size, smash/nutexb = 16)
    std::string format;              // output format name ("" = by extension)
    std::optional<LutLayout> layout; // output layout for LUT images
    OutputOptions overwrite;         // -y / -n (the output is the positional OUT)
    Verbosity verbosity;
};

int runExtract(const ExtractOptions& options);

// Adds the subcommand to app; onParsed is called with the options once they are parsed.
CLI::App* setupExtract(CLI::App& app, std::function<void(const ExtractOptions&)> onParsed);

} // namespace lut::cli
