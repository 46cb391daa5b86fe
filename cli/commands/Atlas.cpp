// SPDX-License-Identifier: Apache-2.0
// lutkit atlas: build an atlas from LUT files, split it into strips, say what one holds.
#include "commands/Atlas.h"

#include "LutFiles.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/formats/Atlas.h"
#include "lut/formats/Registry.h"
#include "lut/io/FileNames.h"
#include "lut/os/Files.h"
#include "lut/os/Paths.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

namespace lut::cli {

namespace {

std::string stem(const std::string& path) {
    return os::fromPath(os::toPath(path).stem());
}

std::string rowLabel(const formats::AtlasRowReport& r) {
    return r.source.empty() ? std::string("(neutral)") : r.source;
}

// The lines a MultiLUT.fx user pastes: the texture, its size and the row names for the combo.
std::string multiLutText(const std::string& output, const formats::AtlasBuildReport& r) {
    std::string items;
    for (const auto& row : r.rows)
        items += (row.source.empty() ? std::string("Neutral") : stem(row.source)) + "\\0";
    const std::string n = std::to_string(r.shape.size);
    return "MultiLUT.fx: #define fLUT_TextureName \"" +
           os::fromPath(os::toPath(output).filename()) + "\", fLUT_TileSizeXY " + n +
           ", fLUT_TileAmount " + n + ", fLUT_LutAmount " + std::to_string(r.shape.rows) +
           "; ui_items=\"" + items + "\"";
}

int build(const AtlasCommandOptions& o) {
    if (o.inputs.empty())
        throw UsageError("atlas build needs the LUT files, one per row: atlas build A B C -o "
                         "atlas.png");
    if (o.output.output.empty())
        throw UsageError("atlas build needs -o ATLAS.png");
    formats::AtlasBuildOptions b;
    b.layout = o.layout.value_or(LutLayout::Reshade);
    if (b.layout == LutLayout::Hald)
        throw UsageError("an atlas stacks strips: --layout hald is not one (reshade, unreal, "
                         "unity, unity-32 or smush)");
    if (const std::string problem = layoutSizeProblem(b.layout, o.size); !problem.empty())
        throw UsageError(problem);
    b.size = o.size;
    b.neutralFirst = o.neutralFirst;
    b.interp = o.interp;
    b.read.layout = o.inLayout;
    if (!beginOutput(o.output.output, o.output, o.inputs, o.verbosity.quiet))
        return kExitOk;
    const formats::AtlasBuildReport r = formats::buildAtlas(o.inputs, o.output.output, b);
    for (std::size_t k = 0; k < r.rows.size(); ++k) {
        const formats::AtlasRowReport& row = r.rows[k];
        printDiagnostics(std::cerr, row.diagnostics, o.verbosity, "lutkit: ");
        std::cout << "row " << k << "  " << rowLabel(row);
        if (row.resample)
            std::cout << ": " << row.sourceSize << "^3 resampled to " << r.shape.size << "^3 ("
                      << toString(o.interp) << "): " << row.resample->str();
        else if (!row.source.empty())
            std::cout << ": " << row.sourceSize << "^3";
        std::cout << "; 8-bit storage: " << row.storage.str();
        if (row.clamped)
            std::cout << " (" << row.clamped << " values outside 0..1 clamped)";
        if (row.neutral)
            std::cout << "; neutral";
        std::cout << "\n";
    }
    std::cout << "wrote    " << o.output.output << ": " << r.shape.size * r.shape.size << "x"
              << r.shape.size * r.shape.rows << ", " << r.shape.rows << " rows of " << r.shape.size
              << "^3 in the " << toString(r.shape.layout) << " layout\n";
    if (!o.verbosity.quiet && layoutPlacement(r.shape.layout) == LutLayout::Pilot)
        std::cout << multiLutText(o.output.output, r) << "\n";
    return kExitOk;
}

int split(const AtlasCommandOptions& o) {
    if (o.inputs.size() != 1)
        throw UsageError("atlas split takes one atlas picture: atlas split atlas.png -o DIR/");
    if (o.output.output.empty())
        throw UsageError("atlas split needs -o DIR/ (the folder for one strip per row)");
    const std::string& in = o.inputs.front();
    const std::filesystem::path dir = os::toPath(o.output.output);
    if (os::exists(o.output.output) && !os::isDirectory(o.output.output))
        throw Error(o.output.output + ": not a folder (split writes one strip per row into it)");
    formats::registerBuiltinFormats();
    const formats::AtlasReading a = formats::readAtlas(in, o.inLayout);
    if (!os::isDirectory(o.output.output)) { // made as apply -o DIR/ makes it, once the atlas read
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        if (ec)
            throw Error(o.output.output + ": cannot create the folder: " + ec.message());
    }
    printDiagnostics(std::cerr, a.diagnostics, o.verbosity, "lutkit: ");
    const std::string ext = extensionOf(in).empty() ? ".png" : extensionOf(in);
    const std::string base = stem(in);
    // Every name first: nothing is written when one would be refused.
    std::vector<std::string> paths;
    std::vector<bool> skip;
    for (int k = 0; k < a.shape.rows; ++k) {
        char num[16];
        std::snprintf(num, sizeof num, "%02d", k);
        paths.push_back(os::fromPath(dir / os::toPath(base + "-" + num + ext)));
        skip.push_back(resolveOutput(paths.back(), o.output, {in}).skip);
    }
    FormatOptions wo;
    wo.layout = a.shape.layout;
    wo.bitDepth = 8;
    // The rows read again one at a time, each written as it comes (none is kept).
    formats::forEachAtlasRow(in, a, [&](int k, const Lut3D& row) {
        if (skip[static_cast<std::size_t>(k)]) {
            if (!o.verbosity.quiet)
                std::cerr << "lutkit: " << printable(paths[static_cast<std::size_t>(k)])
                          << " exists; skipped (-n)\n";
            return;
        }
        LutFile f;
        f.cube = row;
        (void)formats::writeLut(paths[static_cast<std::size_t>(k)], f, wo, "strip");
        std::cout << "row " << k << "  " << paths[static_cast<std::size_t>(k)]
                  << (a.neutral[static_cast<std::size_t>(k)] ? " (neutral)" : "") << "\n";
    });
    std::cout << "split    " << in << ": " << a.shape.rows << " rows of " << a.shape.size
              << "^3 in the " << toString(a.shape.layout) << " layout (" << a.layoutReason << ")\n";
    return kExitOk;
}

int info(const AtlasCommandOptions& o) {
    if (o.inputs.empty())
        throw UsageError("atlas info needs an atlas picture: atlas info atlas.png");
    if (!o.output.output.empty())
        throw UsageError("atlas info writes nothing: -o is for build and split");
    formats::registerBuiltinFormats();
    for (const std::string& in : o.inputs) {
        const formats::AtlasReading a = formats::readAtlas(in, o.inLayout);
        printDiagnostics(std::cerr, a.diagnostics, o.verbosity, "lutkit: ");
        std::cout << "file     " << in << "\n"
                  << "size     " << a.width << "x" << a.height << "\n"
                  << "rows     " << a.shape.rows << " (" << a.shape.size << "^3 each)\n"
                  << "layout   " << toString(a.shape.layout) << " (" << a.layoutReason << ")\n";
        std::string neutral;
        for (int k = 0; k < a.shape.rows; ++k)
            if (a.neutral[static_cast<std::size_t>(k)])
                neutral += (neutral.empty() ? "" : ", ") + std::to_string(k);
        std::cout << "neutral  " << (neutral.empty() ? std::string("none") : "row " + neutral)
                  << "\n";
        std::cout << "repeats  ";
        if (a.duplicates.empty())
            std::cout << "none\n";
        for (std::size_t i = 0; i < a.duplicates.size(); ++i)
            std::cout << (i ? ", " : "") << "row " << a.duplicates[i].first << " = row "
                      << a.duplicates[i].second << (i + 1 == a.duplicates.size() ? "\n" : "");
    }
    return kExitOk;
}

} // namespace

int runAtlas(const AtlasCommandOptions& o) {
    const bool building = o.action == "build";
    if (!building && (o.layout || o.size || o.neutralFirst))
        throw UsageError("--layout, --size and --neutral-first are for atlas build (split and "
                         "info read the layout with --in-layout)");
    if (building)
        return build(o);
    if (o.action == "split")
        return split(o);
    return info(o);
}

CLI::App* setupAtlas(CLI::App& app, std::function<void(const AtlasCommandOptions&)> onParsed) {
    auto o = std::make_shared<AtlasCommandOptions>();
    auto* sub = app.add_subcommand(
        "atlas", "Build a LUT atlas (ReShade's MultiLUT: one strip per row), split one, or say "
                 "what one holds");
    sub->add_option("ACTION", o->action,
                    "build (LUT files -> -o atlas), split (atlas -> -o DIR/, one strip per row) "
                    "or info")
        ->required()
        ->type_name("ACTION")
        ->check(choicesValidator(atlasActionChoices()));
    sub->add_option("FILES", o->inputs,
                    "build: the LUTs (any format), one row each, top to bottom; split and info: "
                    "atlas pictures")
        ->type_name("FILE");
    addOutputOptions(*sub, o->output,
                     "build: the atlas picture (.png); split: the folder (made when missing)");
    addLayout(*sub, "--layout", o->layout,
              "build: the rows' layout (default reshade, 1024x32 rows as MultiLUT.fx reads)");
    addLayout(*sub, "--in-layout", o->inLayout,
              "split, info: the atlas's layout (default: detected); build: of LUT images read");
    sub->add_option("--size", o->size,
                    "build: every row N^3, resampled with the error said (default: the layout's, "
                    "32 for reshade; else the first LUT's, and another size is refused)")
        ->check(CLI::Range(2, 256));
    sub->add_flag("--neutral-first", o->neutralFirst,
                  "build: row 0 is the neutral LUT (MultiLUT's \"Neutral\" entry)");
    addInterp(*sub, o->interp, "build: resampling interpolation (default tetrahedral)");
    addVerbosity(*sub, o->verbosity, "");
    sub->footer("Examples:\n"
                "  lutkit atlas build warm.cube cold.cube sepia.png -o atlas.png --neutral-first\n"
                "  lutkit atlas build a.cube b.cube -o atlas.png --layout unreal --size 16\n"
                "  lutkit atlas split atlas.png -o rows/\n"
                "  lutkit atlas info atlas.png\n"
                "A row that stores the same 8-bit values as another is refused, naming both; "
                "rows of\nanother size are refused unless --size (or a layout of one size) asks "
                "for resampling.");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
