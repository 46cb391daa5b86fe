// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit extract EDITED OUT: find the patch in an edited screenshot and write the LUT it shows.
// Also reads Smush-LUT's files: a graded LUT image (its neutral.png) and its first versions'
// `.lut.png` strips (lut/roundtrip/SmushStrip.h).
#include "Notes.h"
#include "Outputs.h"

#include "lut/io/Layout.h"
#include "lut/ops/Strength.h"

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
    // target name (raw | smash); "" = what the patch records, smash for a .nutexb output
    std::string target;
    std::string originalLut;           // smash: the stage's LUT the screenshot was taken with
    bool refine = false;               // smash: the least-squares refinement
    int size = 0;                      // output size (0: raw = patch size, smash = 16)
    std::string format;                // output format name ("" = by extension)
    std::optional<LutLayout> layout;   // output layout for LUT images
    std::optional<LutLayout> inLayout; // EDITED is a graded LUT image: its layout
    std::string inTarget;              // EDITED is a graded LUT image: what it is ("" = its tag,
                                       // else raw)
    OutputOptions overwrite;           // -y / -n (the output is the positional OUT)
    StrengthOptions strength;          // the edit blended with what was there before it
    Verbosity verbosity;
};

int runExtract(const ExtractOptions& options);

// Adds the subcommand to app; onParsed is called with the options once they are parsed.
CLI::App* setupExtract(CLI::App& app, std::function<void(const ExtractOptions&)> onParsed);

} // namespace lut::cli
