// SPDX-License-Identifier: Apache-2.0
// lutkit invert: lut::invert, then the result written and its report printed.
#include "commands/Invert.h"

#include "Json.h"
#include "LutFiles.h"
#include "Numbers.h"
#include "Usage.h"
#include "Vocabulary.h"
#include "WrittenCheck.h"

#include "lut/formats/Cube.h"
#include "lut/formats/Registry.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/io/FormatRegistry.h"
#include "lut/ops/Invert.h"
#include "lut/ops/InvertFile.h"
#include "lut/ops/InvertShaper.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

namespace lut::cli {

namespace {

// A 3D inverse's two forms (lut/ops/InvertShaper.h): which was written, and each one's round trip.
struct FormChoice {
    bool shaper = false;
    const ErrorStats* table = nullptr;  // the table alone's round trip
    const ErrorStats* shaped = nullptr; // a shaper and a table's, when one was made
};

void printReport(const InvertCommandOptions& o, const InvertReport& r, bool oneD,
                 const FormChoice& form = {}) {
    if (o.json) {
        std::cout << "{\"input\": " << json::quote(o.input)
                  << ", \"output\": " << json::quote(o.output) << ", \"points\": " << r.points
                  << ", \"unreachable\": " << r.unreachable
                  << ", \"folded_cells\": " << r.foldedCells
                  << ", \"invertible\": " << (r.invertible() ? "true" : "false")
                  << ", \"max_residual\": " << json::number(r.maxResidual)
                  << ", \"mean_residual\": " << json::number(r.meanResidual)
                  << ", \"residual\": " << json::stats(r.residual)
                  << ", \"round_trip\": " << json::stats(r.roundTrip);
        if (form.table)
            std::cout << ", \"form\": " << json::quote(form.shaper ? "shaper" : "table")
                      << ", \"round_trip_table\": " << json::stats(*form.table)
                      << ", \"round_trip_shaper\": "
                      << (form.shaped ? json::stats(*form.shaped) : std::string("null"));
        std::cout << ", \"unreachable_by_region\": {";
        bool first = true;
        for (int i = 0; i < kRegionCount; ++i)
            if (r.unreachableByRegion[static_cast<std::size_t>(i)]) {
                std::cout << (first ? "" : ", ") << json::quote(toString(static_cast<Region>(i)))
                          << ": " << r.unreachableByRegion[static_cast<std::size_t>(i)];
                first = false;
            }
        std::cout << "}, \"seconds\": " << json::number(r.seconds) << "}\n";
        return;
    }
    std::cout << "inverted " << o.input << (oneD ? " (1D, per channel)" : "") << ": " << r.points
              << " points, " << significant(r.seconds * 1e3) << " ms\n";
    if (r.invertible())
        std::cout << "         invertible everywhere";
    else
        std::cout << "         " << r.unreachable << " points have no exact preimage "
                  << "(least-squares answer); " << r.foldedCells
                  << (oneD ? " segments not strictly monotone" : " cells flat or folded");
    std::cout << "\nresidual |A(inverse(y)) - y| at the inverse's lattice points: max "
              << significant(roundUpSignificant(r.maxResidual)) << ", mean "
              << significant(r.meanResidual) << "\n"
              << "         over every y, between them too: " << r.residual.str() << "\n"
              << "         max: " << r.residual.coverage() << "\n"
              << "round trip |inverse(A(x)) - x| over every x: " << r.roundTrip.str() << "\n"
              << "         max: " << r.roundTrip.coverage() << "\n";
    if (form.table && form.shaped)
        std::cout << "form     " << (form.shaper ? "a 1D shaper then the table" : "the table alone")
                  << "; round trip max " << significant(roundUpSignificant(form.table->maxSteps8()))
                  << " 8-bit steps with the table alone, "
                  << significant(roundUpSignificant(form.shaped->maxSteps8()))
                  << " with a 1D shaper first (--lut-form)\n";
    if (r.unreachable) {
        std::cout << "where    no inverse:";
        for (int i = 0; i < kRegionCount; ++i)
            if (const auto n = r.unreachableByRegion[static_cast<std::size_t>(i)])
                std::cout << " " << toString(static_cast<Region>(i)) << " " << n;
        std::cout << "\n";
        for (const auto& w : r.worst)
            if (o.verbosity.verbose)
                std::cout << "  target " << triple(w.target) << " -> " << triple(w.solution)
                          << " reaches " << triple(w.reached) << " (off by "
                          << significant(w.residual) << ")\n";
    }
}

} // namespace

int runInvert(const InvertCommandOptions& o) {
    if (!beginOutput(o.output, o.overwrite, {o.input}, o.verbosity.quiet))
        return kExitOk;
    const LutFile file = formats::readLut(o.input, {});
    printDiagnostics(std::cerr, file.diagnostics, o.verbosity, "lutkit: ");
    // The inverse lives where its input does: a game LUT's inverse is written as the game's.
    const std::optional<LutPurpose> purpose = knownPurpose(decidePurpose(file));
    InvertOptions io;
    io.size = o.size;
    io.outputRangeDomain = o.outputRange;
    std::ostringstream written; // after the report (JSON: not at all)
    if (file.shaper && !file.cube) {
        // Per-channel curves stay curves: inverted exactly where monotone.
        const InvertResult1D r = invert(*file.shaper, io);
        LutFile out;
        out.shaper = r.lut;
        out.purpose = purpose;
        const WrittenLut w = writeLutFile(o.output, out, o.format, {o.input});
        printReport(o, r.report, true);
        if (!o.json) {
            std::cout << "wrote    " << o.output << ": " << w.format << ", 1D, " << r.lut.size()
                      << " entries\n";
            printDiagnostics(std::cout, w.diagnostics, o.verbosity);
        }
        checkWrittenLut(o.output, out, o.verbosity);
        return kExitOk;
    }
    if (file.shaper) {
        // Shaper then table: the table inverted, the shaper inverted exactly on its entries.
        const FileInvertResult r = invert(file, io);
        writeLutTable(written, o.output, r.table.lut, o.format, {o.input}, o.verbosity, purpose);
        printReport(o, r.table.report, false);
        if (!o.json)
            std::cout << "shaper   A is a 1D shaper then a " << file.cube->size()
                      << "^3 table: the table inverted as above, the shaper exactly"
                      << (r.shaperFolds ? " (" + std::to_string(r.shaperFolds) +
                                              " segments not strictly monotone)"
                                        : std::string())
                      << "\nbetween  |A(inverse(y)) - y| with A exact, on " << r.heldOut
                      << " targets between the inverse's lattice points: "
                      << r.heldOutResidual.str() << "\n"
                      << written.str();
        return kExitOk;
    }
    const InvertResult r = invert(*file.cube, io);
    // Where the inverse is steep a 1D shaper before the table follows it (Resolve's .cube form):
    // written when asked, or (auto) when it halves a round trip of more than a step and the
    // output holds it; both figures printed.
    ShaperInvertResult shaped;
    if (o.form != "table")
        shaped = invertWithShaper(*file.cube, io);
    FormChoice form;
    form.table = &r.report.roundTrip;
    form.shaped = shaped.made ? &shaped.report.roundTrip : nullptr;
    Diagnostics notes;
    auto note = [&](const std::string& text) {
        notes.push_back({Diagnostic::Severity::Info, o.output, 0, 0, text});
    };
    if (shaped.made) {
        const double t = r.report.roundTrip.maxAbs, s = shaped.report.roundTrip.maxAbs;
        const bool helps = t > 1.0 / 255.0 && s < 0.5 * t;
        if (o.form == "shaper" || helps) {
            FormatOptions fo;
            const Format* writer = o.format.empty()
                                       ? FormatRegistry::instance().writerForPath(o.output)
                                       : FormatRegistry::instance().byName(o.format);
            if (!o.format.empty())
                FormatRegistry::instance().applyAlias(o.format, fo);
            form.shaper = writer && writer->holdsShaperFor(fo);
            if (!form.shaper)
                note("its format holds no 1D shaper: the table alone (round trip max " +
                     significant(roundUpSignificant(t * 255.0)) + " 8-bit steps; " +
                     significant(roundUpSignificant(s * 255.0)) +
                     " with a shaper, as a .cube or --format resolve_cube)");
        }
    } else if (o.form == "shaper") {
        note("A's neutral axis does not rise in every channel: no shaper, the table alone");
    }
    if (form.shaper) {
        LutFile out = shaped.lut;
        out.purpose = purpose;
        const WrittenLut w = writeLutFile(o.output, out, o.format, {o.input});
        // Resolve's form, which ffmpeg and Photoshop do not read: said, with what the one table
        // they read costs (the library's warning, as match gives it).
        if (o.format.empty() && o.form == "auto" && extensionOf(o.output) == ".cube")
            notes.push_back(formats::resolveCubeReadersWarning(
                o.output, "the inverse is steep",
                "as one table its round trip would be max " +
                    significant(roundUpSignificant(form.table->maxSteps8())) +
                    " 8-bit steps over A's domain",
                "the inverse as one table"));
        printReport(o, shaped.report, false, form);
        if (!o.json) {
            std::cout << "wrote    " << o.output << ": " << w.format << ", a " << out.shaper->size()
                      << "-entry 1D shaper then a " << out.cube->size() << "^3 table\n";
            printDiagnostics(std::cout, notes, o.verbosity);
            printDiagnostics(std::cout, w.diagnostics, o.verbosity);
        }
        checkWrittenLut(o.output, out, o.verbosity);
        return kExitOk;
    }
    writeLutTable(written, o.output, r.lut, o.format, {o.input}, o.verbosity, purpose);
    printReport(o, r.report, false, form);
    if (!o.json) {
        printDiagnostics(std::cout, notes, o.verbosity);
        std::cout << written.str();
    }
    checkWrittenLut(o.output, r.lut, o.verbosity);
    return kExitOk;
}

CLI::App* setupInvert(CLI::App& app, std::function<void(const InvertCommandOptions&)> onParsed) {
    auto o = std::make_shared<InvertCommandOptions>();
    auto* sub =
        app.add_subcommand("invert", "Invert a LUT, reporting where it has no inverse (never NaN)");
    sub->add_option("A", o->input, "the LUT to invert")->required()->type_name("FILE");
    sub->add_option("OUT", o->output, "output LUT file (format from the extension)")
        ->required()
        ->type_name("FILE");
    sub->add_option("--size", o->size, "lattice size (1D: entries) of the inverse (default: A's)")
        ->check(CLI::Range(2, 65536));
    sub->add_flag("--output-range", o->outputRange,
                  "span the inverse over the range of A's outputs instead of A's domain");
    sub->add_option("--lut-form", o->form,
                    "auto (default: a 1D shaper then the table where the inverse is steep and "
                    "the output holds one, as Resolve's .cube; the report gives both round "
                    "trips), shaper, table (the table alone)")
        ->check(choicesValidator(matchShaperChoices()))
        ->type_name("NAME");
    addOutputFormat(*sub, o->format);
    sub->add_flag("--json", o->json, "print the report as JSON");
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "list the targets furthest from an inverse");
    sub->footer("Examples:\n"
                "  lutkit invert to_log.cube from_log.cube\n"
                "  lutkit invert grade.cube ungrade.cube --size 65 -v");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
