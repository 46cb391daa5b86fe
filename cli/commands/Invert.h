// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit invert A OUT: the LUT that undoes A where it can be undone, and where it cannot
// (lut/ops/Invert.h): never NaN, a least-squares answer where A has no inverse.
#include "Notes.h"
#include "Outputs.h"

#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace lut::cli {

struct InvertCommandOptions {
    std::string input, output;
    std::string format;
    int size = 0;              // 0 = A's
    bool outputRange = false;  // the inverse's domain: the range of A's outputs
    std::string form = "auto"; // --lut-form auto|shaper|table (lut/ops/InvertShaper.h)
    bool json = false;
    OutputOptions overwrite; // -y / -n (the output is the positional OUT)
    Verbosity verbosity;
};

int runInvert(const InvertCommandOptions& options);

CLI::App* setupInvert(CLI::App& app, std::function<void(const InvertCommandOptions&)> onParsed);

} // namespace lut::cli
