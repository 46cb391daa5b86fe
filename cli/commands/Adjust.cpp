// SPDX-License-Identifier: Apache-2.0
// lutkit adjust: lut::parseAdjustmentList and lut::applyAdjustments, the result written.
#include "commands/Adjust.h"

#include "LutFiles.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/Version.h"
#include "lut/io/InputFile.h"
#include "lut/ops/AdjustmentList.h"
#include "lut/ops/Clipping.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lut::cli {

namespace {
constexpr std::size_t kMaxAdjustmentListBytes = 1 << 20;
}

int runAdjust(const AdjustCommandOptions& o) {
    if (!beginOutput(o.output, o.overwrite, {o.input, o.adjustments}, o.verbosity.quiet))
        return kExitOk;
    const Adjustments adj = parseAdjustmentList(
        readFile(o.adjustments, kMaxAdjustmentListBytes, "adjustment list"), o.adjustments);
    PurposeDecision purpose; // a game LUT adjusted stays the game's LUT (never compensated twice)
    const Lut3D lut = readLutTable(o.input, o.verbosity, &purpose);
    const Lut3D out = applyAdjustments(lut, adj);
    std::cout << "adjusted " << o.input << " with " << o.adjustments
              << (adj.isNeutral() ? " (neutral: nothing changes)" : "") << "\n";
    if (o.verbosity.verbose)
        std::cout << formatAdjustmentList(adj);
    const ClipCount clip = countOutOfRange(out);
    if (clip.outside)
        std::cout << "range    " << clip.outside << " of " << clip.entries
                  << " entries leave 0..1 (" << clip.below << " below, " << clip.above
                  << " above): an 8-bit format clips them\n";
    writeLutTable(std::cout, o.output, out, o.format, {o.input, o.adjustments}, o.verbosity,
                  knownPurpose(purpose));
    return kExitOk;
}

CLI::App* setupAdjust(CLI::App& app, std::function<void(const AdjustCommandOptions&)> onParsed) {
    auto o = std::make_shared<AdjustCommandOptions>();
    auto* sub =
        app.add_subcommand("adjust", "Apply an adjustment list (as the editor saves it) to a LUT");
    sub->add_option("LUT", o->input, "the LUT to adjust")->required()->type_name("FILE");
    sub->add_option("OUT", o->output, "output LUT file (format from the extension)")
        ->required()
        ->type_name("FILE");
    sub->add_option("--adjustments", o->adjustments,
                    "the adjustment list (one \"keyword numbers\" line each; " LUTKIT_DOC_DIR
                    "/docs/editor.md)")
        ->required()
        ->type_name("FILE");
    addOutputFormat(*sub, o->format);
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "print the adjustments applied");
    sub->footer("An adjustment list looks like:\n"
                "  # lutkit adjustment list 1\n"
                "  exposure 0.5\n"
                "  lift 0.01 0 -0.01\n"
                "  curve.master 0,0 0.25,0.2 1,1\n"
                "  strength 0.8\n\n"
                "Examples:\n"
                "  lutkit adjust grade.cube --adjustments warm.txt warm.cube\n"
                "  lutkit adjust neutral.cube --adjustments look.txt look.nutexb -v");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
