// SPDX-License-Identifier: Apache-2.0
// lutkit mix: lut::mix, the result written and its error printed.
#include "commands/Mix.h"

#include "LutFiles.h"
#include "PurposeText.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/ops/Compose.h"
#include "lut/smash/PurposeOps.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lut::cli {

int runMix(const MixCommandOptions& o) {
    if (!beginOutput(o.output, o.overwrite, {o.a, o.b}, o.verbosity.quiet))
        return kExitOk;
    const PurposedPair p =
        readPurposedPair(o.a, o.b, o.inTarget, o.target, o.output, o.format, o.verbosity);
    // Both made for what OUT is for, then mixed (lut/smash/PurposeOps.h).
    PurposeOptions po;
    po.editInterpolation = o.interp;
    const PurposeOpResult pr = mixForPurpose({&p.a, p.pa.purpose}, {&p.b, p.pb.purpose}, o.strength,
                                             p.out.to, o.interp, po);
    const OpResult& r = pr.result;
    const std::optional<LutPurpose> says = printPurposeOp(std::cout, p, pr, o.interp);
    std::cout << "mixed    " << o.a << " and " << o.b << " at strength " << o.strength << " on A's "
              << r.lut.size() << "^3 lattice\n"
              << "error    "
              << (r.error.maxAbs == 0.0
                      ? std::string("none: B has A's lattice, the mix is exact")
                      : "B resampled onto A's lattice: " + costText(r.error, r.sanitizedEntries))
              << "\n";
    writeLutTable(std::cout, o.output, r.lut, o.format, {o.a, o.b}, o.verbosity, says);
    return kExitOk;
}

CLI::App* setupMix(CLI::App& app, std::function<void(const MixCommandOptions&)> onParsed) {
    auto o = std::make_shared<MixCommandOptions>();
    auto* sub = app.add_subcommand("mix", "Blend two LUTs: (1 - t) A + t B");
    sub->add_option("A", o->a, "the LUT at strength 0")->required()->type_name("FILE");
    sub->add_option("B", o->b, "the LUT at strength 1")->required()->type_name("FILE");
    sub->add_option("OUT", o->output, "output LUT file (format from the extension)")
        ->required()
        ->type_name("FILE");
    sub->add_option("--strength", o->strength,
                    "t: 0 = A, 1 = B, between blends, -1..2 extrapolates (default 0.5)")
        ->check(CLI::Range(-1.0, 2.0));
    addOutputFormat(*sub, o->format);
    addInterp(*sub, o->interp, "interpolation when B has another lattice (default tetrahedral)");
    addPurpose(*sub, "--target", o->target,
               "what OUT is for (default: smash for a .nutexb, else what A is for): A and B are "
               "made for it, then mixed");
    addPurpose(*sub, "--in-target", o->inTarget,
               "what A and B are for (default: what each file says, LUTKIT_PURPOSE or a "
               ".nutexb; else raw)");
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "");
    sub->footer("Examples:\n"
                "  lutkit mix neutral.cube grade.cube half.cube --strength 0.5\n"
                "  lutkit mix day.cube night.cube dusk.cube --strength 0.3");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
