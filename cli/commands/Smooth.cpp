// SPDX-License-Identifier: Apache-2.0
// lutkit smooth: lut::smooth, the result written and the change printed.
#include "commands/Smooth.h"

#include "LutFiles.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/ops/Smooth.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lut::cli {

int runSmooth(const SmoothCommandOptions& o) {
    if (!beginOutput(o.output, o.overwrite, {o.input}, o.verbosity.quiet))
        return kExitOk;
    PurposeDecision purpose;
    const Lut3D a = readLutTable(o.input, o.verbosity, &purpose);
    const OpResult r = smooth(a, o.sigma);
    std::cout << "smoothed " << o.input << " (sigma " << o.sigma << " lattice steps)\n"
              << "change   against the original: " << costText(r.error, r.sanitizedEntries) << "\n";
    // The result is for what the input was for (a game LUT resampled is still the game's).
    writeLutTable(std::cout, o.output, r.lut, o.format, {o.input}, o.verbosity,
                  knownPurpose(purpose));
    return kExitOk;
}

CLI::App* setupSmooth(CLI::App& app, std::function<void(const SmoothCommandOptions&)> onParsed) {
    auto o = std::make_shared<SmoothCommandOptions>();
    auto* sub = app.add_subcommand(
        "smooth",
        "Smooth a LUT (Gaussian blur of its deviation from neutral), reporting the change");
    sub->add_option("A", o->input, "the LUT to smooth")->required()->type_name("FILE");
    sub->add_option("OUT", o->output, "output LUT file (format from the extension)")
        ->required()
        ->type_name("FILE");
    sub->add_option("--sigma", o->sigma, "blur radius in lattice steps, 0-8 (default 1)")
        ->check(CLI::Range(0.0, 8.0));
    addOutputFormat(*sub, o->format);
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "");
    sub->footer("Examples:\n"
                "  lutkit smooth extracted.cube smooth.cube\n"
                "  lutkit smooth noisy.cube out.cube --sigma 2.5");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
