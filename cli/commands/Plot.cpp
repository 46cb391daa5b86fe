// SPDX-License-Identifier: Apache-2.0
// lutkit plot: lut::plotLut written as an 8-bit PNG (or any image format by extension).
#include "commands/Plot.h"

#include "LutFiles.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/formats/ImageIO.h"
#include "lut/io/AtomicFile.h"
#include "lut/ops/Plot.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lut::cli {

int runPlot(const PlotCommandOptions& o) {
    if (!beginOutput(o.output, o.overwrite, {o.input}, o.verbosity.quiet))
        return kExitOk;
    checkNotSameFile(o.input, o.output);
    const Lut3D lut = readLutTable(o.input, o.verbosity);
    PlotOptions p;
    p.latticePoints = o.latticePoints;
    const Plot plot = plotLut(lut, p);
    formats::ImageWriteOptions w;
    w.bitDepth = 8;
    w.alpha = false;
    w.format = o.format.empty() ? "png" : o.format; // for - and devices
    formats::writeImage(o.output, plot.image, w);
    std::cout << "wrote    " << o.output << ": " << plot.image.width() << "x" << plot.image.height()
              << " (curves along the neutral axis, slices at blue 0, 0.5, 1, the lattice in 3D)\n";
    return kExitOk;
}

CLI::App* setupPlot(CLI::App& app, std::function<void(const PlotCommandOptions&)> onParsed) {
    auto o = std::make_shared<PlotCommandOptions>();
    auto* sub = app.add_subcommand(
        "plot", "Draw a LUT: curves along the neutral axis, slices and the lattice in 3D");
    sub->add_option("LUT", o->input, "the LUT to draw")->required()->type_name("FILE");
    sub->add_option("OUT", o->output, "the picture (PNG, or any image extension; - for stdout)")
        ->required()
        ->type_name("FILE");
    sub->add_option("--lattice-points", o->latticePoints,
                    "lattice points per axis in the 3D view (2-17, default 9)")
        ->check(CLI::Range(2, 17));
    addImageOutputFormat(*sub, o->format,
                         "image format when OUT is - (standard output) (default png)");
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "");
    sub->footer("Examples:\n"
                "  lutkit plot grade.cube grade.png\n"
                "  lutkit plot extracted.nutexb look.png --lattice-points 17\n"
                "  lutkit plot grade.cube - --format png     # the picture on standard output");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
