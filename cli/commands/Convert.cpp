// SPDX-License-Identifier: Apache-2.0
// lutkit convert: prints what lut::formats::convertLut did and what it cost.
#include "commands/Convert.h"

#include "Json.h"
#include "Numbers.h"
#include "PurposeText.h"
#include "StrengthOptions.h"
#include "Usage.h"
#include "Vocabulary.h"
#include "WrittenCheck.h"
#include "commands/Bake.h"

#include "lut/LutPurpose.h"
#include "lut/formats/Bake.h"
#include "lut/formats/Convert.h"
#include "lut/formats/Hald.h"
#include "lut/formats/ImageFiles.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/LutDestination.h"
#include "lut/formats/Nutexb.h"
#include "lut/formats/OcioFiles.h"
#include "lut/formats/Registry.h"
#include "lut/io/FileNames.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

namespace lut::cli {

namespace {

std::string describe(const LutFile& f) {
    std::string s = f.format;
    if (!f.dialect.empty())
        s += " (" + f.dialect + ")";
    if (f.shaper)
        s += ", 1D shaper " + std::to_string(f.shaper->size());
    if (f.cube)
        s += ", " + std::to_string(f.cube->size()) + "^3";
    if (f.sourceBitDepth)
        s += ", " + std::to_string(f.sourceBitDepth) + "-bit";
    return s;
}

std::string fileJson(const std::string& path, const LutFile& f, double seconds) {
    return "{\"path\": " + json::quote(path) + ", \"format\": " + json::quote(f.format) +
           ", \"dialect\": " + json::quote(f.dialect) +
           ", \"size\": " + std::to_string(f.cube ? f.cube->size() : 0) +
           ", \"shaper_size\": " + std::to_string(f.shaper ? f.shaper->size() : 0) +
           ", \"bit_depth\": " + std::to_string(f.sourceBitDepth) +
           ", \"seconds\": " + json::number(seconds) + "}";
}

std::string reportJson(const ConvertOptions& o, const formats::ConvertReport& r) {
    std::ostringstream js;
    js << "{\"input\": " << fileJson(o.input, r.input, r.readSeconds) << ",\n \"output\": "
       << (r.readBack ? fileJson(o.output, *r.readBack, r.writeSeconds)
                      : "{\"path\": " + json::quote(o.output) +
                            ", \"format\": " + json::quote(r.outputFormat) +
                            ", \"seconds\": " + json::number(r.writeSeconds) + "}")
       << ",\n \"output_format\": " << json::quote(r.outputFormat)
       << ",\n \"purpose\": {\"input\": " << json::quote(toString(r.purpose.input.purpose))
       << ", \"input_said\": "
       << (r.purpose.input.said ? json::quote(toString(*r.purpose.input.said)) : "null")
       << ", \"output\": " << json::quote(toString(r.purpose.output))
       << ", \"conversion\": " << conversionJson(r.purpose.conversion) << "},\n \"strength\": "
       << (r.strength ? "{\"luma\": " + json::number(r.strength->luma) +
                            ", \"chroma\": " + json::number(r.strength->chroma) + "}"
                      : std::string("null"))
       << ",\n \"resample\": ";
    if (r.resample)
        js << "{\"from\": " << r.resample->from << ", \"to\": " << r.resample->to
           << ", \"interp\": " << json::quote(toString(r.resample->interp))
           << ", \"shaper_sampled\": " << (r.resample->shaper ? "true" : "false")
           << ", \"error\": " << json::stats(r.resample->error) << "}";
    else
        js << "null";
    js << ",\n \"storage\": " << (r.storage ? json::stats(*r.storage) : "null")
       << ",\n \"read_back_error\": "
       << (r.readBackError.empty() ? "null" : json::quote(r.readBackError))
       << ",\n \"input_diagnostics\": " << json::diagnostics(r.input.diagnostics)
       << ",\n \"diagnostics\": " << json::diagnostics(r.writeDiagnostics)
       << ",\n \"seconds\": " << json::number(r.totalSeconds) << "}\n";
    return js.str();
}

void printReport(const ConvertOptions& o, const formats::ConvertReport& r) {
    std::cout << "read     " << o.input << ": " << describe(r.input) << ", "
              << milliseconds(r.readSeconds) << "\n";
    if (o.verbosity.verbose)
        if (const std::string d = layoutDetail(r.input, o.inLayout.has_value(), "--in-layout");
            !d.empty())
            std::cout << "  " << d << "\n";
    printDiagnostics(std::cout, r.input.diagnostics, o.verbosity);
    if (r.strength) // of the edit, when it is made into another purpose (Convert.h)
        std::cout << "strength " << strengthText(o.strength)
                  << (r.purpose.conversion ? ", of the edit" : "") << "\n";
    const formats::PurposeStep& p = r.purpose;
    std::cout << "purpose  in:  " << p.input.text("--in-target") << "\n"
              << "         out: " << toString(p.output)
              << (p.outputFrom == formats::DestinationPurpose::Said ? " (--target)"
                  : p.outputFrom == formats::DestinationPurpose::GameFormat
                      ? p.input.purpose == LutPurpose::Raw
                            ? " (the output is a .nutexb, the game's LUT; --target raw writes IN "
                              "as it is)"
                            : " (the output is a .nutexb, the game's LUT)"
                  : p.output == p.input.purpose ? " (as IN; --target chooses)"
                                                : "")
              << "\n";
    if (p.conversion) {
        ConversionWords w;
        w.stage = o.originalLut.empty() ? "neutral" : o.originalLut;
        w.interp = o.interp;
        printConversion(std::cout, *p.conversion, w);
    }
    if (r.resample) {
        if (r.resample->shaper)
            std::cout << "resample "
                      << (r.resample->from
                              ? "the 1D shaper and " + std::to_string(r.resample->from) + "^3 table"
                              : std::string("the 1D table"))
                      << " sampled at a " << r.resample->to
                      << "^3 lattice over 0..1 (tetrahedral): ";
        else
            std::cout << "resample " << r.resample->from << "^3 -> " << r.resample->to << "^3 ("
                      << toString(r.resample->interp) << "): ";
        std::cout << r.resample->error.str() << "\n";
        if (r.resample->error.bounded)
            std::cout << "         max: " << r.resample->error.coverage() << "\n";
    } else
        std::cout << "resample none (same size)\n";
    std::cout << "wrote    " << o.output << ": " << r.outputFormat;
    if (r.readBack)
        std::cout << ", reads back as " << describe(*r.readBack);
    std::cout << ", " << milliseconds(r.writeSeconds) << "\n";
    printDiagnostics(std::cout, r.writeDiagnostics, o.verbosity);
    if (r.storage)
        std::cout << "storage  (quantisation, written file read back): " << r.storage->str()
                  << (r.storage->bounded ? "\n         max: " + r.storage->coverage() : "") << "\n";
    else
        std::cout << "storage  not measured: cannot read the output back: " << r.readBackError
                  << "\n";
    std::cout << "total    " << milliseconds(r.totalSeconds) << "\n";
}

} // namespace

int runConvert(const ConvertOptions& o) {
    if (!o.cccid.empty()) {
        // --cccid picks a correction of a .ccc/.cdl/.cc file: anywhere else it would be ignored
        // without a word.
        const std::string ext = extensionOf(o.input);
        if (ext != ".ccc" && ext != ".cdl" && ext != ".cc")
            throw UsageError("--cccid " + o.cccid + ": " + o.input +
                             " is not a .ccc, .cdl or .cc file (it picks one of their "
                             "corrections)");
    }
    if (isConvertBatch(o))
        return runConvertBatch(o);
    if (o.color.any())
        (void)formats::planColor(o.color); // a misspelt colour name is bad usage, before files
    const OutputTarget target = resolveOutput(
        o.output, o.overwrite, {o.input, o.originalLut, o.screenshot, o.color.config});
    if (target.skip) {
        if (!o.verbosity.quiet)
            std::cerr << "lutkit: " << printable(o.output) << " exists; skipped (-n)\n";
        return kExitOk;
    }
    const std::optional<LutPurpose> outPurpose = purposeOption(o.target);
    const std::optional<LutPurpose> inPurpose = purposeOption(o.inTarget);
    // Where OUT goes, decided by the library (lut/formats/LutDestination.h): its writer, what it
    // is for, its lattice and layout (--level: a Hald image). The options that make a game LUT
    // from an edit need a smash output: asked for, or the game's format.
    const formats::LutDestination dest =
        formats::resolveLutDestination({o.output, o.format, outPurpose, o.size, o.layout, o.level});
    if (!dest.forGame() && (!o.originalLut.empty() || !o.screenshot.empty() || o.refine))
        throw UsageError("--original-lut, --screenshot and --refine are for --target smash");
    if (o.layout)
        if (const std::string problem = layoutSizeProblem(*o.layout, o.size); !problem.empty())
            throw UsageError(problem);
    if (o.color.any()) {
        if (outPurpose || inPurpose)
            throw UsageError("--target and --in-target do not apply with --from/--to (the LUT "
                             "is baked with colour conversions, as it is)");
        if (!isFullStrength(o.strength))
            throw UsageError("--strength does not combine with --from/--to yet: convert at the "
                             "strength first, then bake the result");
        // The LUT in its own colour space, OpenColorIO's conversions around it, baked.
        formats::BakeOptions b;
        b.config = o.color.config;
        b.lut = o.input;
        b.lutFormat = o.inFormat;
        b.lutRead.layout = o.inLayout;
        if (!o.cccid.empty())
            b.lutRead.setAttribute(formats::kOcioCccIdAttribute, o.cccid);
        b.around = o.color;
        b.cubeSize = o.size;
        b.shaperSize = o.shaperSize;
        b.format = o.format;
        b.write.layout = o.layout;
        b.write.bitDepth = o.bitDepth;
        b.write.dither = o.dither;
        if (!o.name.empty())
            b.write.setAttribute(formats::nutexb::kNameAttribute, o.name);
        printBakeReport(o.output, formats::bake(o.output, b), o.json, o.verbosity);
        return kExitOk;
    }
    formats::ConvertOptions co;
    co.inFormat = o.inFormat;
    co.outFormat = o.format;
    co.read.layout = o.inLayout;
    if (!o.cccid.empty())
        co.read.setAttribute(formats::kOcioCccIdAttribute, o.cccid);
    co.write.layout = dest.layout;
    co.write.size = dest.size;
    co.write.bitDepth = o.bitDepth;
    co.write.dither = o.dither;
    if (!o.name.empty())
        co.write.setAttribute(formats::nutexb::kNameAttribute, o.name);
    co.interp = o.interp;
    co.inPurpose = inPurpose;
    co.outPurpose = outPurpose;
    co.strength = o.strength;
    // An edit made into the game's LUT: on the stage's picture, measured over the screenshot's
    // colours (else a grid), the refinement reported and written when asked.
    PurposeInputs held;
    preparePurposeInputs(o, held, co);
    formats::ConvertReport report;
    try {
        report = formats::convertLut(o.input, o.output, co);
    } catch (
        const formats::RequestError& e) { // the one convertLut throws: a size for the game's LUT
        throw UsageError(std::string(e.what()) + ": --size does not apply to --target smash");
    }
    warnPurposeFromContent(o.input, report.purpose.input, "--in-target", o.verbosity);
    if (o.json)
        std::cout << reportJson(o, report);
    else
        printReport(o, report);
    const bool madeGame =
        report.purpose.conversion && report.purpose.conversion->to == LutPurpose::Smash;
    if (!madeGame && (!o.originalLut.empty() || !o.screenshot.empty() || o.refine))
        std::cerr << "lutkit: warning: " << printable(o.input)
                  << " is already the game's LUT: --original-lut, --screenshot and --refine "
                     "were not used\n";
    checkWrittenLut(o.output, report.readBack ? *report.readBack : report.input, o.verbosity,
                    report.purpose.output == LutPurpose::Smash);
    return kExitOk;
}

CLI::App* setupConvert(CLI::App& app, std::function<void(const ConvertOptions&)> onParsed) {
    auto o = std::make_shared<ConvertOptions>();
    auto* sub = app.add_subcommand(
        "convert", "Convert a LUT to another format, reporting the error introduced");
    sub->add_option("IN", o->input, "input LUT file, or a folder of them (with -o DIR/)")
        ->required()
        ->type_name("FILE");
    sub->add_option("OUT", o->output, "output LUT file (format from the extension), or -o OUT")
        ->type_name("FILE");
    addOutputFormat(*sub, o->format);
    addInputFormat(*sub, o->inFormat);
    addLayout(*sub, "--layout", o->layout,
              "output LUT image layout (default unreal; reshade and unity-32 are 32^3, 1024x32)");
    addLayout(*sub, "--in-layout", o->inLayout, "input LUT image layout (default: detected)");
    sub->add_option("--cccid", o->cccid,
                    "the correction of a .ccc/.cdl input: its id or index (as ociobakelut "
                    "--cccid)")
        ->type_name("ID");
    auto* size = sub->add_option("--size", o->size,
                                 "output lattice size N, N^3 (default: the format's own, else the "
                                 "input's)")
                     ->check(CLI::Range(2, 256));
    sub->add_option("--level", o->level,
                    "Hald level L as ImageMagick's hald:L (N = L^2, layout hald)")
        ->check(CLI::Range(formats::kMinHaldLevel, formats::kMaxHaldLevel))
        ->excludes(size);
    addInterp(*sub, o->interp, "resampling interpolation (default tetrahedral)");
    addBitDepth(*sub, o->bitDepth, "LUT image output: 8, 16 or 32 (float)");
    sub->add_flag("--dither", o->dither, "8-bit image output: ordered dither");
    sub->add_option("--name", o->name, "nutexb name field (default color_grading_lut)");
    sub->add_flag("--json", o->json, "print the report as JSON");
    addOutputOptions(*sub, o->overwrite,
                     "the output, as OUT; a folder (existing, or ending in /) for a folder IN: "
                     "each LUT under its own name, as --format (default nutexb)");
    addPurpose(*sub, "--target", o->target,
               std::string("what OUT is for (default: ") + toString(LutPurpose::Smash) +
                   " for a .nutexb, else what IN is for): " + toString(LutPurpose::Raw) +
                   " = an edit, the look itself; " + toString(LutPurpose::Smash) +
                   " = the game's LUT (an edit IN, e.g. Smush-LUT's graded neutral.png, becomes "
                   "the LUT that makes the game show it)");
    addPurpose(*sub, "--in-target", o->inTarget,
               "what IN is for (default: what the file says, LUTKIT_PURPOSE, or a .nutexb; "
               "else raw)");
    sub->add_option("--original-lut", o->originalLut,
                    "smash: the stage's LUT the edited picture was taken with (default neutral; "
                    "a stage without its own LUT: builtin:smash-default)")
        ->type_name("FILE");
    sub->add_option("--screenshot", o->screenshot,
                    "smash: a screenshot whose pixels the error is measured over and refined "
                    "on (default: every input)")
        ->type_name("FILE");
    sub->add_flag("--refine", o->refine,
                  "smash: also compute the least-squares refinement (best between the game's "
                  "16^3 points) and write it if it beats the exact composition on colours it was "
                  "not fitted on; both are reported, and which was written");
    addStrengthOptions(*sub, o->strength);
    addColorOptions(*sub, o->color, ColorOptionSet::All);
    sub->add_option("--shaper-size,--shapersize", o->shaperSize,
                    "with --from: shaper entries when the input is HDR (default 4096)")
        ->check(CLI::Range(2, 65536))
        ->group("Colour management (OpenColorIO)");
    addVerbosity(*sub, o->verbosity, "also say how a LUT image input was read");
    sub->footer("Examples:\n"
                "  lutkit convert grade.cube color_grading_lut.nutexb   # for Smash Ultimate "
                "(compensated)\n"
                "  lutkit convert neutral_graded.png color_grading_lut.nutexb --original-lut "
                "stage.nutexb --refine\n"
                "  lutkit convert smush_out.png color_grading_lut.nutexb --in-target smash  # "
                "already the game's\n"
                "  lutkit convert color_grading_lut.nutexb look.cube --target raw  # the edit it "
                "makes\n"
                "  lutkit convert edited_strip.png grade.cube           # a graded 256x16 strip "
                "to .cube\n"
                "  lutkit convert grade.cube strip.png --layout unity --bit-depth 16\n"
                "  lutkit convert grade.cube lut.png --layout reshade       # ReShade's LUT.fx\n"
                "  lutkit convert grade.cube subtle.cube --strength 0.6 --chroma-strength 0.3\n"
                "  lutkit convert grade.3dl grade.cube --size 33 --json\n"
                "  lutkit convert grades.ccc shot042.cube --cccid shot042\n"
                "  lutkit convert srgb_look.cube acescg_look.cube --from ACEScg --lut-space sRGB "
                "--to sRGB\n"
                "  lutkit convert edited_strips/ -o stage_luts/   # every strip: a .nutexb, "
                "each with its in-game error");
    sub->callback([o, onParsed] {
        if (!o->output.empty() && !o->overwrite.output.empty())
            throw UsageError("OUT and -o both name the output: give one");
        if (o->output.empty())
            o->output = o->overwrite.output;
        if (o->output.empty())
            throw UsageError("OUT is required (or -o OUT; -o DIR/ for a folder of LUTs)");
        onParsed(*o);
    });
    return sub;
}

void preparePurposeInputs(const ConvertOptions& o, PurposeInputs& held,
                          formats::ConvertOptions& into) {
    if (!o.originalLut.empty()) {
        held.stage = readStageLut(o.originalLut, o.verbosity);
        into.purpose.stageLut = &held.stage;
    }
    if (!o.screenshot.empty()) {
        held.shot = formats::readImage(o.screenshot).image;
        held.shotView = held.shot.view();
        into.purpose.screenshot = &held.shotView;
    }
    into.purpose.measure = true;
    into.purpose.refine = o.refine;
    into.purpose.editInterpolation = o.interp;
}

} // namespace lut::cli
