// SPDX-License-Identifier: Apache-2.0
// lutkit fit: a 3D LUT fitted to a before/after image pair (lut/roundtrip/Fit.h).
#include "commands/Fit.h"

#include "Usage.h"
#include "Vocabulary.h"
#include "WrittenCheck.h"

#include "lut/ErrorStats.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/roundtrip/Fit.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

namespace lut::cli {

int runFit(const FitOptions& o) {
    const OutputTarget target = resolveOutput(o.output, o.overwrite, {o.before, o.after});
    if (target.skip) {
        if (!o.verbosity.quiet)
            std::cerr << "lutkit: " << printable(o.output) << " exists; skipped (-n)\n";
        return kExitOk;
    }
    auto before = formats::readImage(o.before);
    auto after = formats::readImage(o.after);
    lut::FitOptions fo;
    fo.size = o.size;
    fo.smoothness = o.smoothness;
    fo.robust = !o.noRobust;
    FitResult res = fitLut(before.image.view(), after.image.view(), fo);
    printDiagnostics(std::cerr, res.diagnostics, o.verbosity, "lutkit: ");
    char buf[400];
    std::snprintf(
        buf, sizeof buf,
        "fit %d^3 to %zu pixels (%zu distinct colours): error over those pixels rms %.3g, max "
        "%.3g 8-bit steps; %.3g%% of the cube extrapolated; %zu outlier pixels\n",
        o.size, res.pixels, res.distinctColours, res.rmsSteps8, roundUpSignificant(res.maxSteps8),
        100.0 * res.extrapolatedShare, res.outlierPixels);
    std::cout << buf;
    if (res.heldOutColours > 0) {
        std::snprintf(buf, sizeof buf,
                      "held out on colours it was not fitted to: rms %.3g, max %.3g 8-bit steps "
                      "(a fit on 7/8 of the colours measured on the %zu pixels of the other %zu; "
                      "the max with half a step of margin)\n",
                      res.heldOutRmsSteps8, roundUpSignificant(res.heldOutMaxSteps8),
                      res.heldOutPixels, res.heldOutColours);
        std::cout << buf;
    }
    LutFile file;
    file.cube = std::move(res.lut);
    FormatOptions wo;
    wo.layout = o.layout;
    const Diagnostics wd = formats::writeLut(o.output, file, wo, o.format);
    printDiagnostics(std::cerr, wd, o.verbosity, "lutkit: ");
    std::cout << "wrote " << o.output << "\n";
    checkWrittenLut(o.output, file, o.verbosity);
    return kExitOk;
}

CLI::App* setupFit(CLI::App& app, std::function<void(const FitOptions&)> onParsed) {
    auto o = std::make_shared<FitOptions>();
    auto* sub =
        app.add_subcommand("fit", "Fit a 3D LUT to a before/after image pair (no patch needed)");
    sub->add_option("BEFORE", o->before, "the ungraded image")->required()->type_name("FILE");
    sub->add_option("AFTER", o->after, "the same image graded")->required()->type_name("FILE");
    sub->add_option("OUT", o->output, "output LUT (any format)")->required()->type_name("FILE");
    sub->add_option("--size", o->size, "LUT size (default 33)")->check(CLI::Range(2, 129));
    sub->add_option("--smoothness", o->smoothness,
                    "smoothness weight lambda, in pixels (default 1)")
        ->check(CLI::Range(0.0, 1e9));
    sub->add_flag("--no-robust", o->noRobust, "plain least squares (no outlier down-weighting)");
    addOutputFormat(*sub, o->format);
    addLayout(*sub, "--layout", o->layout, "output LUT image layout (default unreal)");
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "");
    sub->footer("Examples:\n"
                "  lutkit fit before.png after.png grade.cube\n"
                "  lutkit fit before.png after.png color_grading_lut.nutexb --size 16");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
