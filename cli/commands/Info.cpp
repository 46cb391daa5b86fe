// SPDX-License-Identifier: Apache-2.0
// lutkit info: what a LUT file holds, as text or JSON.
#include "commands/Info.h"

#include "Json.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/Error.h"
#include "lut/LutFile.h"
#include "lut/formats/Hald.h"
#include "lut/formats/Registry.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>

namespace lut::cli {

namespace {

std::string vec(glm::vec3 v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g", v.x, v.y, v.z);
    return buf;
}

} // namespace

int runInfo(const InfoOptions& o) {
    FormatOptions options;
    options.layout = o.inLayout;
    options.size = o.size;
    const LutFile file = formats::readLut(o.input, options, o.inFormat);
    if (!file.cube && !file.shaper)
        throw Error(o.input + ": holds no table");

    // Neutrality of the whole file (shaper then cube), over its input domain.
    double deviation = 0.0;
    if (file.cube && !file.shaper)
        deviation = file.cube->maxDeviationFromIdentity();
    else
        deviation = file.toLut3D(0).maxDeviationFromIdentity();
    const char* neutral = deviation <= kExactNeutralTolerance  ? "exact"
                          : deviation <= kNearNeutralTolerance ? "near"
                                                               : "no";

    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    if (file.cube)
        std::tie(lo, hi) = file.cube->valueRange();
    else
        for (const auto& e : file.shaper->entries())
            for (int c = 0; c < 3; ++c)
                if (!std::isnan(e[c])) {
                    lo = std::min(lo, e[c]);
                    hi = std::max(hi, e[c]);
                }

    const std::string title = file.cube ? file.cube->title() : file.shaper->title();
    const std::size_t comments = file.cube ? file.cube->comments().size() : 0;
    const glm::vec3 dmin = file.cube ? file.cube->domainMin() : file.shaper->domainMin();
    const glm::vec3 dmax = file.cube ? file.cube->domainMax() : file.shaper->domainMax();
    // The library says 0 for values stored as floating point (text formats, float images).
    const bool isFloat = file.sourceBitDepth == 0;
    const int bitDepth = isFloat ? 32 : file.sourceBitDepth;

    if (o.json) {
        std::ostringstream js;
        js << "{\"path\": " << json::quote(o.input) << ", \"format\": " << json::quote(file.format)
           << ", \"dialect\": " << json::quote(file.dialect)
           << ", \"size\": " << (file.cube ? file.cube->size() : 0)
           << ", \"title\": " << json::quote(title) << ", \"domain_min\": " << json::vec3(dmin)
           << ", \"domain_max\": " << json::vec3(dmax) << ", \"shaper\": ";
        if (file.shaper)
            js << "{\"size\": " << file.shaper->size()
               << ", \"domain_min\": " << json::vec3(file.shaper->domainMin())
               << ", \"domain_max\": " << json::vec3(file.shaper->domainMax()) << "}";
        else
            js << "null";
        js << ", \"neutral\": " << json::quote(neutral)
           << ", \"max_deviation_from_identity\": " << json::number(deviation)
           << ", \"value_min\": " << json::number(lo) << ", \"value_max\": " << json::number(hi)
           << ", \"comments\": " << comments
           << ", \"purpose\": " << (file.purpose ? json::quote(toString(*file.purpose)) : "null")
           << ", \"purpose_source\": "
           // why, as the library decides it (a .nutexb says it by its format)
           << json::quote(!file.purpose                                         ? "none"
                          : decidePurpose(file).source == PurposeSource::Format ? "format"
                                                                                : "file")
           << ", \"source_bit_depth\": " << bitDepth
           << ", \"float\": " << (isFloat ? "true" : "false")
           << ", \"diagnostics\": " << json::diagnostics(file.diagnostics) << "}\n";
        std::cout << js.str();
        return kExitOk;
    }

    std::cout << "file        " << o.input << "\n"
              << "format      " << file.format
              << (file.dialect.empty() ? "" : " (" + file.dialect + ")") << "\n";
    if (file.cube)
        std::cout << "size        "
                  << (file.format == "hald" ? formats::haldSizeText(file.cube->size())
                                            : std::to_string(file.cube->size()) + "^3")
                  << "\n";
    if (file.shaper)
        std::cout << "shaper      1D, " << file.shaper->size() << " entries, domain "
                  << vec(file.shaper->domainMin()) << " .. " << vec(file.shaper->domainMax())
                  << "\n";
    else
        std::cout << "shaper      none\n";
    std::cout << "domain      " << vec(dmin) << " .. " << vec(dmax) << "\n"
              << "title       " << (title.empty() ? "(none)" : title) << "\n";
    char buf[128];
    std::snprintf(buf, sizeof buf, "%s (max deviation from identity %.3g = %.3g 8-bit steps)",
                  neutral, deviation, deviation * 255.0);
    std::cout << "neutral     " << buf << "\n";
    std::snprintf(buf, sizeof buf, "%.9g .. %.9g", lo, hi);
    // What the LUT is for (lut/LutPurpose.h), or what the commands take it for.
    const std::string purpose =
        file.purpose ? decidePurpose(file).text("")
                     : "not said (taken as raw, an edit: --in-target or --lut-target smash say "
                       "it is the game's LUT)";
    std::cout << "values      " << buf << "\n"
              << "purpose     " << purpose << "\n"
              << "comments    " << comments << "\n"
              << "bit depth   " << bitDepth << (isFloat ? "-bit float" : "-bit integer") << "\n";
    if (o.verbosity.verbose)
        if (const std::string d = layoutDetail(file, o.inLayout.has_value(), "--in-layout");
            !d.empty())
            std::cout << "  " << d << "\n";
    printDiagnostics(std::cout, file.diagnostics, o.verbosity);
    return kExitOk;
}

CLI::App* setupInfo(CLI::App& app, std::function<void(const InfoOptions&)> onParsed) {
    auto o = std::make_shared<InfoOptions>();
    auto* sub =
        app.add_subcommand("info", "Describe a LUT file: format, size, domain, neutrality, range");
    sub->add_option("IN", o->input, "LUT file")->required()->type_name("FILE");
    addInputFormat(*sub, o->inFormat);
    addLayout(*sub, "--in-layout", o->inLayout, "LUT images: the layout (default: detected)");
    sub->add_option("--size", o->size, "lattice size when sampling OpenColorIO formats")
        ->check(CLI::Range(2, 256));
    sub->add_flag("--json", o->json, "print JSON");
    addVerbosity(*sub, o->verbosity, "also say how a LUT image was read");
    addMovedOption(*sub, "--format",
                   "info reads a LUT: name its format with --in-format (--format is the output "
                   "format of the commands that write)");
    addMovedOption(*sub, "--layout",
                   "info reads a LUT: name its layout with --in-layout (--layout is the output "
                   "layout of the commands that write)");
    sub->footer("Examples:\n"
                "  lutkit info grade.cube\n"
                "  lutkit info color_grading_lut.nutexb --json\n"
                "  lutkit info strip.png --in-layout unity");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
