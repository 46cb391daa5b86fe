// SPDX-License-Identifier: Apache-2.0
// lutkit bench in the portable editions (docs/portable.md): it times lutkit's kernels against
// OpenColorIO's processor, which they do not include, so it says so (commands/Bench.cpp is the
// Linux build's).
#include "commands/Bench.h"

#include "lut/formats/Edition.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace lut::cli {

int runBench(const BenchOptions&) {
    std::cerr << "lutkit: error: "
              << formats::notInEdition("lutkit bench", "OpenColorIO",
                                       "time lutkit with the web page's own benchmark")
              << "\n";
    return 1;
}

CLI::App* setupBench(CLI::App& app, std::function<void(const BenchOptions&)> onParsed) {
    auto* sub = app.add_subcommand("bench", "Kernel speed and error against OpenColorIO (the Linux "
                                            "build only)");
    auto options = std::make_shared<BenchOptions>();
    sub->callback([options, onParsed] { onParsed(*options); });
    return sub;
}

} // namespace lut::cli
