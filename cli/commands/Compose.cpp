// SPDX-License-Identifier: Apache-2.0
// lutkit compose: lut::compose, then the result written and its error printed.
#include "commands/Compose.h"

#include "LutFiles.h"
#include "PurposeText.h"
#include "Usage.h"
#include "Vocabulary.h"
#include "WrittenCheck.h"

#include "lut/ops/Compose.h"
#include "lut/smash/PurposeOps.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lut::cli {

int runCompose(const ComposeCommandOptions& o) {
    if (!beginOutput(o.output, o.overwrite, {o.a, o.b}, o.verbosity.quiet))
        return kExitOk;
    const PurposedPair p =
        readPurposedPair(o.a, o.b, o.inTarget, o.target, o.output, o.format, o.verbosity);
    ComposeOptions c;
    c.size = o.size;
    c.method = o.interp;
    // B's edit of the picture A gives, for what OUT is for (lut/smash/PurposeOps.h).
    PurposeOptions po;
    po.editInterpolation = o.interp;
    const PurposeOpResult pr =
        composeForPurpose({&p.a, p.pa.purpose}, {&p.b, p.pb.purpose}, p.out.to, c, po);
    const OpResult& r = pr.result;
    const std::optional<LutPurpose> says = printPurposeOp(std::cout, p, pr, o.interp);
    if (pr.tableOp)
        std::cout << "composed " << o.b << " after " << o.a << " on a " << r.lut.size()
                  << "^3 lattice (" << toString(o.interp) << ")\n"
                  << "error    between lattice points, against B(A(x)): "
                  << costText(r.error, r.sanitizedEntries) << "\n";
    else
        std::cout << "composed " << o.b << "'s edit on the picture the game shows with " << o.a
                  << ": the game's LUT that shows it (exact at its 16^3 lattice)\n";
    writeLutTable(std::cout, o.output, r.lut, o.format, {o.a, o.b}, o.verbosity, says);
    checkWrittenLut(o.output, r.lut, o.verbosity, p.out.to == LutPurpose::Smash);
    return kExitOk;
}

CLI::App* setupCompose(CLI::App& app, std::function<void(const ComposeCommandOptions&)> onParsed) {
    auto o = std::make_shared<ComposeCommandOptions>();
    auto* sub =
        app.add_subcommand("compose", "Combine two LUTs into one (B after A), reporting the error");
    sub->add_option("A", o->a, "the LUT applied first")->required()->type_name("FILE");
    sub->add_option("B", o->b, "the LUT applied to A's output")->required()->type_name("FILE");
    sub->add_option("OUT", o->output, "output LUT file (format from the extension)")
        ->required()
        ->type_name("FILE");
    sub->add_option("--size", o->size, "lattice size of the result (default: the larger)")
        ->check(CLI::Range(2, 256));
    addOutputFormat(*sub, o->format);
    addInterp(*sub, o->interp, "interpolation (default tetrahedral)");
    addPurpose(*sub, "--target", o->target,
               "what OUT is for (default: smash for a .nutexb, else what A is for): B's edit of "
               "the picture A gives, as an edit (raw) or as the game's LUT (smash)");
    addPurpose(*sub, "--in-target", o->inTarget,
               "what A and B are for (default: what each file says, LUTKIT_PURPOSE or a "
               ".nutexb; else raw)");
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "");
    sub->footer("Examples:\n"
                "  lutkit compose look.cube display.cube look_display.cube\n"
                "  lutkit compose grade.cube calibration.3dl out.cube --size 65\n"
                "  lutkit compose stage.nutexb look.cube new.nutexb   # look on the stage's "
                "picture");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
