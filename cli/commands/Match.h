// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit match SOURCE REFERENCE... OUT: a LUT that gives SOURCE the look of the references
// (lut/match/Match.h, docs/match.md).
#include "Notes.h"
#include "Outputs.h"
#include "StrengthOptions.h"

#include "lut/io/Layout.h"
#include "lut/match/MatchOptions.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace lut::cli {

struct MatchCommandOptions {
    std::string source;
    std::vector<std::string> references;
    std::string output;
    int size = 33;
    MatchMethod method = MatchMethod::Auto;
    MatchLutForm form = MatchLutForm::Auto; // --lut-form auto|shaper|table
    StrengthOptions strength; // --strength, --luma-strength, --chroma-strength (StrengthOptions.h)
    std::vector<MatchPreserve> preserve;
    std::string maskSource;
    std::vector<std::string> maskReferences; // the n-th masks the n-th reference
    std::string target;                      // "", raw, smash
    std::string originalLut;                 // smash: the stage's LUT the source was taken with
    std::string reportImage;                 // --report-image OUT.png
    bool json = false;
    std::string format;              // output format name ("" = by extension)
    std::optional<LutLayout> layout; // output layout for LUT images
    OutputOptions overwrite;         // -y / -n (the output is the positional OUT)
    Verbosity verbosity;
};

int runMatch(const MatchCommandOptions& options);

CLI::App* setupMatch(CLI::App& app, std::function<void(const MatchCommandOptions&)> onParsed);

} // namespace lut::cli
