// lutkit compose: lut::compose, then the result written and its error printed.
#include "commands/Compose.h"

#include "LutFiles.h"
#include "Usage.h"
#include "Vocabulary.h"
#include "WrittenCheck.h"

#include "lut/ops/Compose.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lut::cli {

int runCompose(const ComposeCommandOptions& o) {
    if (!beginOutput(o.output, o.overwrite, {o.a, o.b}, o.verbosity.quiet))
        return kExitOk;
    const Lut3D a = readLutTable(o.a, o.verbosity);
    const Lut3D b = readLutTable(o.b, o.verbosity);
    ComposeOptions c;
    c.size = o.size;
    c.method = o.interp;
    const OpResult r = compose(a, b, c);
    std::cout << "composed " << o.b << " after " << o.a << " on a " << r.lut.size()
              << "^3 lattice (" << toString(o.interp) << ")\n"
              << "error    between lattice points, against B(A(x)): "
              << costText(r.error, r.sanitizedEntries) << "\n";
    writeLutTable(std::cout, o.output, r.lut, o.format, {o.a, o.b}, o.verbosity);
    checkWrittenLut(o.output, r.lut, o.verbosity);
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
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "");
    sub->footer("Examples:\n"
                "  lutkit compose look.cube display.cube look_display.cube\n"
                "  lutkit compose grade.cube calibration.3dl out.cube --size 65");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
