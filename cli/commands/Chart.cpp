// SPDX-License-Identifier: Apache-2.0
// lutkit chart: lut::stressChart (or every chart, stacked) written as an image.
#include "commands/Chart.h"

#include "Usage.h"
#include "Vocabulary.h"

#include "lut/Error.h"
#include "lut/check/StressCharts.h"
#include "lut/formats/ImageIO.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lut::cli {

namespace {

Choices chartChoices() {
    Choices c{"chart", "chart", {}, {}, {}};
    for (const StressChartInfo& info : stressCharts())
        c.names.push_back(info.name);
    c.names.push_back("all");
    const std::vector<std::string> names = c.names;
    c.accept = [names](const std::string& s) {
        if (std::find(names.begin(), names.end(), s) == names.end())
            throw Error("unknown chart '" + s + "'");
    };
    return c;
}

} // namespace

int runChart(const ChartCommandOptions& o) {
    if (!beginOutput(o.output, o.overwrite, {}, o.verbosity.quiet))
        return kExitOk;
    Image image;
    std::string what;
    if (o.chart == "all") {
        image = stressChartSheet(o.width ? o.width : 1024);
        what = "every stress chart, one under the other";
        if (o.height)
            throw UsageError("--height: 'all' takes its height from --width");
    } else {
        const StressChart chart = *stressChartByName(o.chart);
        for (const StressChartInfo& info : stressCharts())
            if (info.chart == chart) {
                image = stressChart(chart, o.width ? o.width : info.width,
                                    o.height ? o.height : info.height);
                what = info.description;
            }
    }
    formats::ImageWriteOptions w;
    w.bitDepth = o.bitDepth;
    w.alpha = false;
    w.format = o.format.empty() ? "png" : o.format; // for - and devices
    formats::writeImage(o.output, image, w);
    if (!o.verbosity.quiet)
        std::cout << "wrote    " << o.output << ": " << image.width() << "x" << image.height()
                  << ", " << o.bitDepth << "-bit: " << what << "\n";
    return kExitOk;
}

CLI::App* setupChart(CLI::App& app, std::function<void(const ChartCommandOptions&)> onParsed) {
    auto o = std::make_shared<ChartCommandOptions>();
    auto* sub = app.add_subcommand(
        "chart", "Write a stress chart (grey ramp, hue sweeps, skin line, cube slices) to grade "
                 "in another tool and judge a LUT by eye");
    sub->add_option("NAME", o->chart,
                    "the chart: grey, hue-saturation, hue-lightness, skin, "
                    "slices, or all (every chart, stacked)")
        ->required()
        ->type_name("CHART")
        ->check(choicesValidator(chartChoices()));
    sub->add_option("OUT", o->output, "the picture (PNG, TIFF, EXR ...)")
        ->required()
        ->type_name("FILE");
    addImageOutputFormat(*sub, o->format,
                         "image format when OUT is - (standard output) (default png)");
    sub->add_option("--width", o->width, "width in pixels (default: the chart's own, 1024)")
        ->check(CLI::Range(16, 16384));
    sub->add_option("--height", o->height, "height in pixels (default: the chart's own)")
        ->check(CLI::Range(16, 16384));
    addBitDepth(*sub, o->bitDepth, "bits per channel: 8, 16 (default) or 32 (float)");
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "");
    std::string charts = "Charts:";
    for (const StressChartInfo& info : stressCharts())
        charts += "\n  " + std::string(info.name) +
                  std::string(16 - std::string(info.name).size(), ' ') + info.description + " (" +
                  std::to_string(info.width) + "x" + std::to_string(info.height) + ")";
    sub->footer(charts +
                "\n  all             every chart above, one under the other\n"
                "Grade the chart as you grade your picture, then compare, or run it through a LUT "
                "with lutkit apply; lutkit check --report shows them before and after a LUT.\n\n"
                "Examples:\n"
                "  lutkit chart all charts.png\n"
                "  lutkit chart grey - --format png   # the picture on standard output\n"
                "  lutkit chart hue-saturation sweep.tif --width 2048 --bit-depth 8\n"
                "  lutkit chart grey ramp.exr --bit-depth 32");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
