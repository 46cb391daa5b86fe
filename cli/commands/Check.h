// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit check LUT...: the LUT check's report (lut/check/CheckLut.h), per file: pass / warn /
// fail for each check with its figures, the findings worst first; --report draws it
// (lut/check/CheckPicture.h); exit 1 when a check fails (--strict: or warns).
#include "Notes.h"
#include "Outputs.h"

#include "lut/io/Layout.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace lut::cli {

struct CheckCommandOptions {
    std::vector<std::string> inputs;
    bool json = false;
    bool strict = false;    // a warning fails too
    std::string image;      // check over this picture's colours
    std::string report;     // the report picture (a folder with several LUTs)
    std::string thresholds; // a thresholds file (docs/check.md)
    std::string target;     // raw | smash: a game LUT is checked as what the game shows
                            // (default smash for a .nutexb)
    std::string inFormat;
    std::optional<LutLayout> inLayout;
    OutputOptions overwrite; // -y / -n for the report picture
    Verbosity verbosity;     // -q: one line per file; -v: every finding
};

int runCheck(const CheckCommandOptions& options);

CLI::App* setupCheck(CLI::App& app, std::function<void(const CheckCommandOptions&)> onParsed);

} // namespace lut::cli
