// SPDX-License-Identifier: Apache-2.0
// lutkit resize: lut::resize, the result written and its error printed.
#include "commands/Resize.h"

#include "LutFiles.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/ops/Resize.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lut::cli {

int runResize(const ResizeCommandOptions& o) {
    if (!beginOutput(o.output, o.overwrite, {o.input}, o.verbosity.quiet))
        return kExitOk;
    PurposeDecision purpose;
    const Lut3D a = readLutTable(o.input, o.verbosity, &purpose);
    const OpResult r = resize(a, o.size, o.interp);
    std::cout << "resized  " << o.input << ": " << a.size() << "^3 -> " << r.lut.size() << "^3 ("
              << toString(o.interp) << ")\n"
              << "error    against the original between lattice points: "
              << costText(r.error, r.sanitizedEntries) << "\n";
    // The result is for what the input was for (a game LUT resampled is still the game's).
    writeLutTable(std::cout, o.output, r.lut, o.format, {o.input}, o.verbosity,
                  knownPurpose(purpose));
    return kExitOk;
}

CLI::App* setupResize(CLI::App& app, std::function<void(const ResizeCommandOptions&)> onParsed) {
    auto o = std::make_shared<ResizeCommandOptions>();
    auto* sub =
        app.add_subcommand("resize", "Resample a LUT to another lattice size, reporting the error");
    sub->add_option("A", o->input, "the LUT to resize")->required()->type_name("FILE");
    sub->add_option("OUT", o->output, "output LUT file (format from the extension)")
        ->required()
        ->type_name("FILE");
    sub->add_option("--size", o->size, "the new lattice size")
        ->required()
        ->check(CLI::Range(2, 256));
    addOutputFormat(*sub, o->format);
    addInterp(*sub, o->interp, "interpolation (default tetrahedral)");
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "");
    sub->footer("Examples:\n"
                "  lutkit resize grade.cube grade17.cube --size 17\n"
                "  lutkit resize small.cube big.cube --size 65 --interp trilinear");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
