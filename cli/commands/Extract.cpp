// lutkit extract: the LUT an edited screenshot's patch shows (docs/roundtrip.md).
#include "commands/Extract.h"

#include "Usage.h"
#include "Vocabulary.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/roundtrip/Extract.h"
#include "lut/roundtrip/PatchFinder.h"
#include "lut/roundtrip/PatchReader.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lut::cli {

int runExtract(const ExtractOptions& o) {
    checkNotSameFile(o.input, o.output); // never overwrite an input (issue 7)
    auto loaded = formats::readImage(o.input);
    lut::ExtractOptions eo;
    eo.target = parseTarget(o.target);
    eo.outputSize = o.size;
    if (eo.outputSize == 0 && extensionOf(o.output) == ".nutexb")
        eo.outputSize = 16;
    Lut3D original;
    if (!o.originalLut.empty()) {
        if (eo.target != ExtractTarget::Smash)
            std::cerr << "lutkit: warning: --original-lut only matters with --target "
                      << toString(ExtractTarget::Smash) << "\n";
        original = formats::readLut(o.originalLut).toLut3D();
        eo.originalLut = &original;
    }
    const FindResult found = findPatch(loaded.image.view());
    if (found.status != FindStatus::Found) {
        std::cerr << "lutkit: error: " << o.input << ": " << found.message << "\n";
        return kExitFailure;
    }
    if (o.verbosity.verbose) {
        const PatchPlacement& p = found.placement;
        std::cout << "found a " << p.size << "^3 " << toString(p.lattice) << "-lattice "
                  << toString(p.layout) << " patch, " << p.bitDepth << "-bit, scale " << p.scale
                  << " (" << p.cell << " pixels per entry as found), frame at (" << p.frameX << ", "
                  << p.frameY << ")\n";
    }
    const PatchReading patch = readPatch(loaded.image.view(), found.placement);
    ExtractResult res = extractLut(patch, eo);
    for (const auto& d : res.diagnostics) {
        if (!isShown(d, o.verbosity))
            continue;
        if (d.severity == Diagnostic::Severity::Info)
            std::cout << d.message << "\n";
        else
            std::cerr << "lutkit: " << o.input << ": " << d.str() << "\n";
    }
    if (eo.target == ExtractTarget::Smash && res.clampedEntries > 0)
        std::cout << "clamped " << res.clampedEntries << " values (farthest "
                  << res.clampedMax * 255.0 << " 8-bit steps outside [0,1])\n";

    LutFile file;
    file.cube = std::move(res.lut);
    FormatOptions fo;
    fo.layout = o.layout;
    const Diagnostics wd = formats::writeLut(o.output, file, fo, o.format);
    printDiagnostics(std::cerr, wd, o.verbosity, "lutkit: ");
    std::cout << "wrote " << file.cube->size() << "^3 " << toString(res.target)
              << " LUT: " << o.output << "\n";
    return kExitOk;
}

CLI::App* setupExtract(CLI::App& app, std::function<void(const ExtractOptions&)> onParsed) {
    auto o = std::make_shared<ExtractOptions>();
    auto* sub = app.add_subcommand(
        "extract", "Find the embedded patch in an edited screenshot and write its LUT");
    sub->add_option("EDITED", o->input, "the graded screenshot")->required()->type_name("FILE");
    sub->add_option("OUT", o->output, "output LUT (any format: .cube, .nutexb, .png strip...)")
        ->required()
        ->type_name("FILE");
    sub->add_option("--target", o->target,
                    std::string(toString(ExtractTarget::Raw)) + " (the edit itself, default) or " +
                        toString(ExtractTarget::Smash) + " (compensated for the game)")
        ->type_name("NAME")
        ->check(choicesValidator(targetChoices()));
    sub->add_option("--original-lut", o->originalLut,
                    "smash: the stage's LUT the screenshot was taken with")
        ->type_name("FILE");
    sub->add_option("--size", o->size, "output LUT size (default: patch size; 16 for smash/nutexb)")
        ->check(CLI::Range(2, 256));
    addOutputFormat(*sub, o->format);
    addLayout(*sub, "--layout", o->layout, "output LUT image layout (default unreal)");
    addVerbosity(*sub, o->verbosity, "also say where the patch was found and how it was made");
    sub->footer("Examples:\n"
                "  lutkit extract graded.png grade.cube\n"
                "  lutkit extract graded.png color_grading_lut.nutexb --target smash\n"
                "  lutkit extract graded.png strip.png --layout unity");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
