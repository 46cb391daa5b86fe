// SPDX-License-Identifier: Apache-2.0
// lutkit extract: the LUT an edited screenshot's patch shows (docs/roundtrip.md).
#include "commands/Extract.h"

#include "LutFiles.h"
#include "PurposeText.h"
#include "StrengthOptions.h"
#include "Usage.h"
#include "Vocabulary.h"
#include "WrittenCheck.h"

#include "lut/formats/ExtractFile.h"
#include "lut/formats/LutDestination.h"
#include "lut/formats/Registry.h"
#include "lut/io/FileNames.h"
#include "lut/io/Layout.h"
#include "lut/roundtrip/Extract.h"
#include "lut/smash/SmashConstants.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lut::cli {

namespace {

void writeOut(const ExtractOptions& o, const formats::LutDestination& dest, Lut3D lut,
              LutPurpose purpose) {
    LutFile file;
    file.cube = std::move(lut);
    file.purpose = purpose; // the output says what it is for (lut/LutPurpose.h)
    FormatOptions fo;
    fo.layout = o.layout;
    const Diagnostics wd = formats::writeLut(o.output, file, fo, o.format);
    printDiagnostics(std::cerr, wd, o.verbosity, "lutkit: ");
    std::cout << "wrote " << file.cube->size() << "^3 " << toString(purpose) << " LUT: " << o.output
              << (purpose == LutPurpose::Smash && !dest.gameFormat()
                      ? " (it says " + purposeTag(purpose) +
                            ": convert and preview take it as "
                            "the game's LUT)"
                      : std::string())
              << "\n";
    checkWrittenLut(o.output, file, o.verbosity, purpose == LutPurpose::Smash);
}

} // namespace

int runExtract(const ExtractOptions& o) {
    const OutputTarget target = resolveOutput(o.output, o.overwrite, {o.input, o.originalLut});
    if (target.skip) {
        if (!o.verbosity.quiet)
            std::cerr << "lutkit: " << printable(o.output) << " exists; skipped (-n)\n";
        return kExitOk;
    }
    // Where OUT goes and what it is for (lut/formats/LutDestination.h).
    const formats::LutDestination dest = formats::resolveLutDestination(
        {o.output, o.format, purposeOption(o.target), o.size, o.layout, 0});
    formats::ExtractFileOptions fo;
    lut::ExtractOptions& eo = fo.extract;
    eo.target = dest.purpose;
    if (dest.purposeFrom == formats::DestinationPurpose::GameFormat)
        eo.targetReason = "the output is a .nutexb, the game's LUT; --target raw writes the edit";
    if (!o.originalLut.empty() && eo.target && *eo.target == LutPurpose::Raw)
        throw UsageError("--original-lut is for --target smash: a raw LUT does not depend on the "
                         "stage's LUT");
    if (o.refine && eo.target && *eo.target == LutPurpose::Raw)
        throw UsageError("--refine is for --target smash (the game's interpolation between its "
                         "16^3 entries)");
    if (o.size > 0 && o.size != kSmashLutSize && eo.target && *eo.target == LutPurpose::Smash)
        throw UsageError("the game's LUT is 16^3: --size does not apply to --target smash");
    eo.outputSize = o.size;
    eo.refine = o.refine;
    eo.strength = o.strength;
    Lut3D original;
    if (!o.originalLut.empty()) {
        original = readStageLut(o.originalLut, o.verbosity);
        eo.originalLut = &original;
    }
    fo.inLayout = o.inLayout;
    fo.inPurpose = purposeOption(o.inTarget);
    formats::ExtractFileResult r = formats::extractLutFromFile(o.input, fo);

    if (r.source == formats::ExtractSource::LutImage) {
        printDiagnostics(std::cerr, r.image->diagnostics, o.verbosity, "lutkit: ");
        warnPurposeFromContent(o.input, r.decision, "--in-target", o.verbosity);
        const bool converted = r.conversion.has_value();
        if (!converted && (!o.originalLut.empty() || o.refine))
            throw UsageError("--original-lut and --refine are for the game's LUT made from an "
                             "edit (--target smash)");
        if (!o.verbosity.quiet)
            std::cout << "no patch: " << o.input << " is a " << r.image->toLut3D().size()
                      << "^3 LUT image (" << r.image->dialect
                      << " layout), read as a graded neutral (Smush-LUT's neutral.png, or lutkit "
                         "neutral): "
                      << r.decision.text("--in-target") << "\n"
                      << "target: " << toString(r.purpose)
                      << (converted ? r.purpose == LutPurpose::Smash
                                          ? " (the game's LUT that shows this edit)"
                                          : " (the edit this game LUT makes)"
                                    : " (as it is; a .nutexb output or --target chooses)")
                      << "\n";
        if (!o.verbosity.quiet && !isFullStrength(o.strength))
            std::cout << "strength: " << strengthText(o.strength) << ", of the edit\n";
        if (converted) {
            ConversionWords w;
            w.stage = o.originalLut.empty() ? "neutral" : o.originalLut;
            printConversion(std::cout, *r.conversion, w);
        }
        writeOut(o, dest, std::move(r.lut), r.purpose);
        return kExitOk;
    }
    if (r.source == formats::ExtractSource::SmushStrip && !o.verbosity.quiet)
        std::cout << "no patch: " << o.input
                  << " is named like a Smush-LUT strip (.lut.): its top-left 256x16 pixels "
                     "read as Smush-LUT's strip (the default stage LUT's values, graded)\n";
    const ExtractResult& res = *r.extract;
    if (o.verbosity.verbose) {
        const PatchPlacement& p = res.placement;
        std::cout << "found a " << p.size << "^3 " << toString(p.lattice) << " patch, "
                  << toString(p.layout) << " layout, " << p.bitDepth << "-bit, scale " << p.scale
                  << " (" << p.cell << " pixels per entry as found), frame at (" << p.frameX << ", "
                  << p.frameY << ")\n";
    }
    for (const auto& d : res.diagnostics) {
        if (!isShown(d, o.verbosity))
            continue;
        if (d.severity == Diagnostic::Severity::Info)
            std::cout << d.message << "\n";
        else
            std::cerr << "lutkit: " << printable(o.input + ": " + d.str()) << "\n";
    }
    if (res.target == LutPurpose::Smash && res.clampedEntries > 0)
        std::cout << "clamped " << res.clampedEntries << " values (farthest "
                  << res.clampedMax * 255.0 << " 8-bit steps outside [0,1])\n";
    writeOut(o, dest, std::move(r.lut), r.purpose);
    return kExitOk;
}

CLI::App* setupExtract(CLI::App& app, std::function<void(const ExtractOptions&)> onParsed) {
    auto o = std::make_shared<ExtractOptions>();
    auto* sub = app.add_subcommand(
        "extract", "Find the embedded patch in an edited screenshot and write its LUT");
    sub->add_option("EDITED", o->input,
                    "the graded screenshot (or a graded LUT image: Smush-LUT's neutral.png, its "
                    ".lut.png strips)")
        ->required()
        ->type_name("FILE");
    sub->add_option("OUT", o->output, "output LUT (any format: .cube, .nutexb, .png strip...)")
        ->required()
        ->type_name("FILE");
    sub->add_option("--target", o->target,
                    std::string("default: what the patch records (embed --target), ") +
                        toString(LutPurpose::Smash) + " for a .nutexb output; " +
                        toString(LutPurpose::Raw) + " = the edit itself, " +
                        toString(LutPurpose::Smash) + " = compensated for the game")
        ->type_name("NAME")
        ->check(choicesValidator(targetChoices()));
    sub->add_option("--original-lut", o->originalLut,
                    "smash: the stage's LUT the screenshot was taken with (default neutral; a "
                    "patch embedded with --original-lut already holds it)")
        ->type_name("FILE");
    sub->add_flag("--refine", o->refine,
                  "smash: also compute the least-squares refinement (best between the game's "
                  "16^3 points) and write it if it beats the exact composition on colours it was "
                  "not fitted on; both are reported, and which was written");
    sub->add_option("--size", o->size,
                    "output LUT size (default: the patch's for raw, 16 for smash and .nutexb)")
        ->check(CLI::Range(2, 256));
    addOutputFormat(*sub, o->format);
    addLayout(*sub, "--layout", o->layout, "output LUT image layout (default unreal)");
    addOverwriteOptions(*sub, o->overwrite);
    addLayout(*sub, "--in-layout", o->inLayout,
              "EDITED is a graded LUT image: its layout (default: detected)");
    addPurpose(*sub, "--in-target", o->inTarget,
               "EDITED is a graded LUT image: what it is for (default: what the file says, "
               "else raw, the edit)");
    addStrengthOptions(*sub, o->strength);
    addVerbosity(*sub, o->verbosity, "also say where the patch was found and how it was made");
    sub->footer("Examples:\n"
                "  lutkit extract graded.png color_grading_lut.nutexb   # for Smash Ultimate\n"
                "  lutkit extract graded.png grade.cube                 # what embed set up\n"
                "  lutkit extract graded.png grade.cube --target raw    # the edit itself\n"
                "  lutkit extract graded.png color_grading_lut.nutexb --refine\n"
                "  lutkit extract graded.png grade.cube --chroma-strength 0.5  # half the colour\n"
                "  lutkit extract neutral_graded.png color_grading_lut.nutexb  # Smush-LUT's "
                "neutral.png");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
