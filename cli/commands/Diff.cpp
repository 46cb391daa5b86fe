// SPDX-License-Identifier: Apache-2.0
// lutkit diff: prints lut::diffLuts' report (and writes its heat map).
#include "commands/Diff.h"

#include "Json.h"
#include "LutFiles.h"
#include "Numbers.h"
#include "PurposeText.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/ErrorStats.h"
#include "lut/formats/ImageIO.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/ops/Diff.h"
#include "lut/ops/HeatMap.h"
#include "lut/smash/PurposeOps.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

namespace lut::cli {

namespace {

std::string steps(glm::dvec3 v) {
    return "R " + significant(v.x) + "  G " + significant(v.y) + "  B " + significant(v.z);
}

// A maximum, rounded up (a printed maximum never rounds below what it stands for).
std::string maxSteps(glm::dvec3 v) {
    return steps(
        glm::dvec3(roundUpSignificant(v.x), roundUpSignificant(v.y), roundUpSignificant(v.z)));
}

// What the 8-bit maximum covers (DiffReport::maxEveryInput, boundSteps8).
std::string maxCovers(const DiffCommandOptions& o, const DiffReport& r) {
    if (!o.image.empty())
        return "the image's colours";
    if (r.maxEveryInput)
        return "every input";
    return "the lattice's points";
}

void printJson(const DiffCommandOptions& o, const DiffReport& r, double heatScale,
               const std::string& compared) {
    std::cout << "{\"a\": " << json::quote(o.a) << ", \"b\": " << json::quote(o.b)
              << ", \"compared\": " << json::quote(compared)
              << ", \"over\": " << json::quote(o.image.empty() ? "lattice" : o.image)
              << ", \"colors\": " << r.count
              << ", \"identical\": " << (r.identical() ? "true" : "false")
              << ",\n \"delta_e2000\": {\"max\": " << json::number(r.maxDeltaE)
              << ", \"mean\": " << json::number(r.meanDeltaE)
              << ", \"p95\": " << json::number(r.p95DeltaE) << "}"
              << ",\n \"max_8bit_steps\": " << json::vec3(r.maxSteps8)
              << ", \"max_8bit_steps_covers\": " << json::quote(maxCovers(o, r))
              << ", \"bound_8bit_steps\": "
              << (std::isnan(r.boundSteps8) ? std::string("null") : json::number(r.boundSteps8))
              << ", \"mean_8bit_steps\": " << json::vec3(r.meanSteps8)
              << ",\n \"worst\": {\"input\": " << json::vec3(r.worst.input)
              << ", \"a\": " << json::vec3(r.worst.a) << ", \"b\": " << json::vec3(r.worst.b)
              << ", \"delta_e2000\": " << json::number(r.worst.deltaE) << "},\n \"regions\": [";
    const auto ranked = r.rankedRegions();
    for (std::size_t i = 0; i < ranked.size(); ++i) {
        const auto& g = ranked[i];
        std::cout << (i ? ",\n   " : "\n   ") << "{\"region\": " << json::quote(toString(g.region))
                  << ", \"colors\": " << g.count
                  << ", \"mean_delta_e2000\": " << json::number(g.meanDeltaE)
                  << ", \"max_delta_e2000\": " << json::number(g.maxDeltaE)
                  << ", \"max_8bit_steps\": " << json::vec3(g.maxSteps8)
                  << ", \"worst_input\": " << json::vec3(g.worstInput) << "}";
    }
    std::cout << "],\n \"heatmap\": "
              << (o.heatmap.empty() ? "null"
                                    : "{\"path\": " + json::quote(o.heatmap) +
                                          ", \"max_delta_e2000\": " + json::number(heatScale) + "}")
              << ", \"seconds\": " << json::number(r.seconds) << "}\n";
}

void printText(const DiffCommandOptions& o, const DiffReport& r, const std::string& compared) {
    std::cout << "compared " << r.count << " colours "
              << (o.image.empty() ? "on a lattice over A's domain" : "of " + o.image) << ": "
              << compared << "\n";
    if (r.identical()) {
        std::cout << "identical: ΔE2000 0, 0 8-bit steps\n";
        return;
    }
    std::cout << "ΔE2000   max " << significant(r.maxDeltaE) << ", mean "
              << significant(r.meanDeltaE) << ", 95th percentile " << significant(r.p95DeltaE)
              << " (entries taken as sRGB-encoded)\n"
              << "8-bit    max   " << maxSteps(r.maxSteps8) << "\n"
              << "         mean  " << steps(r.meanSteps8) << "\n";
    if (r.maxEveryInput)
        std::cout << "         max: exact over every input (one lattice: between its points the "
                     "difference is a blend of the entries' differences)\n";
    else if (!std::isnan(r.boundSteps8))
        std::cout << "         max: at the lattice's points; over every input of A's domain at "
                     "most "
                  << significant(roundUpSignificant(r.boundSteps8)) << " 8-bit steps (a bound: "
                  << "the two lattices differ, so between the points the difference can grow)\n";
    else if (o.image.empty())
        std::cout << "         max: at the lattice's points (sampled: between them the difference "
                     "can be larger)\n";
    std::cout << "worst    input " << triple(r.worst.input) << ": A " << triple(r.worst.a) << ", B "
              << triple(r.worst.b) << " (ΔE " << significant(r.worst.deltaE) << ")\n"
              << "where    (largest mean ΔE first)\n";
    for (const auto& g : r.rankedRegions())
        std::cout << "  " << toString(g.region)
                  << std::string(12 - std::string(toString(g.region)).size(), ' ') << "mean ΔE "
                  << significant(g.meanDeltaE) << ", max " << significant(g.maxDeltaE) << " at "
                  << triple(g.worstInput) << " (" << g.count << " colours)\n";
    if (r.sanitizedEntriesA || r.sanitizedEntriesB)
        std::cout << "note     NaN/Inf entries counted as 0 or +-65504: A " << r.sanitizedEntriesA
                  << ", B " << r.sanitizedEntriesB << "\n";
}

} // namespace

int runDiff(const DiffCommandOptions& o) {
    // What each is for (lut/LutPurpose.h): a game LUT is compared by what the game shows.
    PurposeDecision pa, pb;
    const Lut3D a = readLutTable(o.a, o.verbosity, &pa, purposeOption(o.inTarget));
    const Lut3D b = readLutTable(o.b, o.verbosity, &pb, purposeOption(o.inTarget));
    lut::DiffOptions d;
    d.method = o.interp;
    d.size = o.size;
    d.boundBetween = true;
    HeatMapOptions h;
    h.maxDeltaE = o.maxDeltaE;
    h.method = o.interp;
    DiffReport report;
    std::string compared;
    HeatMap heat;
    // The heat maps draw tables: a game LUT's is the edit it makes (what the game shows).
    const bool game = pa.purpose == LutPurpose::Smash || pb.purpose == LutPurpose::Smash;
    auto drawn = [&](const Lut3D& x, const PurposeDecision& p) {
        return p.purpose == LutPurpose::Smash ? editOfGameLut(x, std::max(x.size(), 65)) : x;
    };
    // -n with an existing heat map: the comparison is still printed, the picture not rewritten.
    const bool writeHeatmap =
        !o.heatmap.empty() &&
        resolveOutput(o.heatmap, o.overwrite, {o.a, o.b, o.image}).skip == false;
    if (!o.image.empty()) {
        const formats::LoadedImage img = formats::readImage(o.image);
        const ImageView view = img.image.view();
        PurposeDiff pd = diffForPurpose({&a, pa.purpose}, {&b, pb.purpose}, &view, d);
        report = pd.report;
        compared = pd.compared;
        if (!o.heatmap.empty())
            heat = game ? diffHeatMap(drawn(a, pa), drawn(b, pb), view, h)
                        : diffHeatMap(a, b, view, h);
    } else {
        PurposeDiff pd = diffForPurpose({&a, pa.purpose}, {&b, pb.purpose}, nullptr, d);
        report = pd.report;
        compared = pd.compared;
        if (!o.heatmap.empty())
            heat = game ? diffHeatMapSlices(drawn(a, pa), drawn(b, pb), h, o.slices)
                        : diffHeatMapSlices(a, b, h, o.slices);
    }
    if (writeHeatmap) {
        formats::ImageWriteOptions w;
        w.bitDepth = 8;
        w.alpha = false;
        w.format = o.format.empty() ? "png" : o.format; // for - and devices
        formats::writeImage(o.heatmap, heat.image, w);
    }
    if (o.json) {
        printJson(o, report, heat.maxDeltaE, compared);
    } else {
        std::cout << "purpose  A: " << pa.text("--in-target")
                  << "\n         B: " << pb.text("--in-target") << "\n";
        printText(o, report, compared);
        if (writeHeatmap)
            std::cout << "wrote    " << o.heatmap << ": heat map, black = ΔE 0 to pale yellow = ΔE "
                      << significant(heat.maxDeltaE) << " and above\n";
    }
    // --fail-above: the answer of a script (cmp-like), said even with -q.
    if (o.failAbove && report.maxDeltaE > *o.failAbove) {
        std::cout.flush();
        std::cerr << "lutkit: error: " << printable(o.a) << " and " << printable(o.b)
                  << " differ by up to ΔE2000 " << significant(report.maxDeltaE)
                  << ", above --fail-above " << significant(*o.failAbove) << "\n";
        return kExitFailure;
    }
    return kExitOk;
}

CLI::App* setupDiff(CLI::App& app, std::function<void(const DiffCommandOptions&)> onParsed) {
    auto o = std::make_shared<DiffCommandOptions>();
    auto* sub = app.add_subcommand(
        "diff", "Compare two LUTs: ΔE2000 and 8-bit steps, where they differ, a heat map");
    sub->add_option("A", o->a, "first LUT file")->required()->type_name("FILE");
    sub->add_option("B", o->b, "second LUT file")->required()->type_name("FILE");
    sub->add_option("--image", o->image,
                    "compare over this image's colours (e.g. a screenshot) instead of the lattice")
        ->type_name("FILE");
    sub->add_option("--heatmap", o->heatmap,
                    "write a heat-map PNG: on the image, or on slices of the cube (- for stdout)")
        ->type_name("FILE");
    addImageOutputFormat(*sub, o->format,
                         "the heat map's image format when it is - (standard output) (default "
                         "png)");
    sub->add_option("--size", o->size, "lattice compared on (default: the larger of the two)")
        ->check(CLI::Range(2, 256));
    sub->add_option("--slices", o->slices, "heat map of the lattice: slices of the cube (1-16)")
        ->check(CLI::Range(1, 16));
    sub->add_option("--max-delta-e", o->maxDeltaE,
                    "ΔE2000 at the top of the heat map's ramp (default 10; 0 = the largest)")
        ->check(CLI::Range(0.0, 1000.0));
    addInterp(*sub, o->interp, "interpolation (default tetrahedral)");
    addPurpose(*sub, "--in-target", o->inTarget,
               "what A and B are for, over what the files say (raw: an edit; smash: the game's "
               "LUT, compared by what the game shows; default: what each file says, else raw)");
    sub->add_flag("--json", o->json, "print the report as JSON");
    sub->add_option("--fail-above", o->failAbove,
                    "exit 1 when the largest ΔE2000 is above this (0: any difference), as cmp "
                    "exits 1 when files differ")
        ->check(CLI::Range(0.0, 1000.0));
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "");
    sub->footer(
        "ΔE2000 takes LUT entries as sRGB-encoded display values. A game LUT (a "
        ".nutexb, a file that says smash) is compared by what the game shows with it, "
        "at the colour the neutral game shows for each input (as lutkit preview shows "
        "a screenshot). Exit code 0 whether the LUTs differ or not; with --fail-above DE, 1 "
        "when the largest ΔE2000 is above DE (2 for bad usage, and 1 for a file it "
        "cannot read, as always).\n\n"
        "Examples:\n"
        "  lutkit diff old.cube new.cube\n"
        "  lutkit diff expected.cube built.cube --fail-above 0.5 -q   # a test in a script\n"
        "  lutkit diff old.cube new.cube --image screenshot.png --heatmap where.png\n"
        "  lutkit diff a.cube b.3dl --heatmap slices.png --slices 9 --json");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
