// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit bake OUT: a colour conversion of an OpenColorIO config, or LUT files through OCIO's whole
// processor, baked into any LUT format, like ociobakelut (same option names), with a shaper when
// the input is HDR and the error against OCIO's processor reported (lut/formats/Bake.h).
#include "Notes.h"
#include "Outputs.h"

#include "lut/formats/Bake.h"

#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace lut::cli {

struct BakeCommandOptions {
    std::string output;
    formats::BakeOptions bake;
    std::string cccid; // the --cccid for the --lut/--invlut that follow it
    bool json = false;
    OutputOptions overwrite; // -y / -n (the output is the positional OUT)
    Verbosity verbosity;
};

int runBake(const BakeCommandOptions& options);

// The report of a bake (text or JSON) on stdout; also what convert --from/--to prints.
void printBakeReport(const std::string& output, const formats::BakeReport& report, bool json,
                     const Verbosity& verbosity);

// Adds the subcommand to app; onParsed is called with the options once they are parsed.
CLI::App* setupBake(CLI::App& app, std::function<void(const BakeCommandOptions&)> onParsed);

} // namespace lut::cli
