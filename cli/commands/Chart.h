// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit chart NAME OUT: the stress charts colourists grade to judge a LUT by eye
// (lut/check/StressCharts.h), as pictures to grade in other tools; `all` stacks every chart.
#include "Notes.h"
#include "Outputs.h"

#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace lut::cli {

struct ChartCommandOptions {
    std::string chart; // a chart's name, or "all"
    std::string output;
    int width = 0, height = 0; // 0 = the chart's own
    int bitDepth = 16;
    std::string format;      // the picture's format when OUT is - (standard output); default png
    OutputOptions overwrite; // -y / -n (the output is the positional OUT)
    Verbosity verbosity;
};

int runChart(const ChartCommandOptions& options);

CLI::App* setupChart(CLI::App& app, std::function<void(const ChartCommandOptions&)> onParsed);

} // namespace lut::cli
