// SPDX-License-Identifier: Apache-2.0
// lutkit embed: a neutral LUT patch with a self-describing marker frame, pasted into a
// screenshot (docs/roundtrip.md); lutkit extract finds it again after grading.
#include "commands/Embed.h"

#include "LutFiles.h"
#include "PurposeText.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/roundtrip/Embed.h"
#include "lut/roundtrip/LutDigest.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lut::cli {

int runEmbed(const EmbedOptions& o) {
    // Never over the clean screenshot: fit and tests need it.
    const OutputTarget target = resolveOutput(o.output, o.overwrite, {o.input, o.originalLut});
    if (target.skip) {
        if (!o.verbosity.quiet)
            std::cerr << "lutkit: " << printable(o.output) << " exists; skipped (-n)\n";
        return kExitOk;
    }
    lut::EmbedOptions eo;
    eo.target = parseLutPurpose(o.target);
    if (!o.lattice.empty())
        eo.lattice = parseLattice(o.lattice);
    if (!o.originalLut.empty() && eo.target == LutPurpose::Raw)
        throw UsageError("--original-lut is for --target smash: a raw LUT does not depend on the "
                         "stage's LUT");
    eo.size = o.size;
    eo.layout = o.layout;
    eo.scale = o.scale;
    eo.corner = parseCorner(o.corner);
    eo.margin = o.margin;
    Lut3D original;
    if (!o.originalLut.empty()) {
        original = readStageLut(o.originalLut, o.verbosity);
        eo.originalLut = &original;
    }
    auto loaded = formats::readImage(o.input);
    // Keep the screenshot's own depth: the patch is quantised to exactly what will be stored.
    eo.bitDepth = loaded.info.bitDepth == 16 ? 16 : loaded.info.bitDepth == 32 ? 32 : 8;
    const PatchPlacement p = embedPatch(loaded.image.view(), eo);

    formats::ImageWriteOptions wo;
    wo.bitDepth = eo.bitDepth;
    wo.alpha = loaded.info.channels == 2 || loaded.info.channels == 4;
    wo.format = !o.format.empty() ? o.format : loaded.info.format; // for - and devices
    const std::string ext = target.inPlace() ? "." + wo.format : extensionOf(o.output);
    if (ext == ".png" && eo.bitDepth == 32)
        wo.bitDepth = 16;
    wo.metadata = loaded.metadata;
    formats::writeImage(target.writePath, loaded.image, wo);
    std::cout << "embedded a " << p.size << "^3 " << toString(p.lattice) << " patch for "
              << toString(*p.target)
              << (p.lattice == PatchLattice::SmashStage
                      ? " with the stage LUT " + digestText(*p.stageDigest) + " (" + o.originalLut +
                            ")"
                      : std::string())
              << ", " << toString(p.layout) << " layout at scale " << p.scale << " ("
              << p.frameWidth << "x" << p.frameHeight << " pixels with its frame) at (" << p.frameX
              << ", " << p.frameY << "), " << wo.bitDepth << "-bit: " << o.output << "\n";
    if (o.scale == 0 && p.scale < kDefaultPatchScale) // the default did not fit
        std::cerr << "lutkit: warning: " << printable(o.output)
                  << ": the screenshot is too small for scale " << kDefaultPatchScale
                  << "; at scale " << p.scale
                  << " a JPEG save (4:2:0 chroma) blends the patch's colours: save the graded "
                     "image as PNG or TIFF\n";
    if (ext == ".jpg" || ext == ".jpeg")
        std::cerr << "lutkit: warning: " << printable(o.output)
                  << ": JPEG is lossy: the patch survives a quality-90 save (about 0.7 8-bit "
                     "steps mean in game at scale 8, extract reports it), PNG and TIFF keep it "
                     "exact\n";
    if (!o.verbosity.quiet)
        std::cout << "grade the whole image with global adjustments only, then run: lutkit "
                     "extract EDITED "
                  << (*p.target == LutPurpose::Smash ? "color_grading_lut.nutexb" : "grade.cube")
                  << "  (the patch records what it is for: no options needed)\n";
    return kExitOk;
}

CLI::App* setupEmbed(CLI::App& app, std::function<void(const EmbedOptions&)> onParsed) {
    auto o = std::make_shared<EmbedOptions>();
    auto* sub =
        app.add_subcommand("embed", "Paste a neutral LUT patch with markers into a screenshot");
    sub->add_option("SCREENSHOT", o->input, "screenshot to copy (8- or 16-bit kept)")
        ->required()
        ->type_name("FILE");
    sub->add_option("OUT", o->output, "output image (PNG or TIFF recommended; - for stdout)")
        ->required()
        ->type_name("FILE");
    addImageOutputFormat(*sub, o->format,
                         "image format when OUT is - (standard output) (default: the "
                         "screenshot's)");
    sub->add_option("--target", o->target,
                    std::string("what you are making, recorded in the patch so extract needs no "
                                "options: ") +
                        toString(LutPurpose::Smash) + " (default) = the game's LUT; " +
                        toString(LutPurpose::Raw) +
                        " = the edit itself (engines that apply the LUT to the shown image)")
        ->type_name("NAME")
        ->check(choicesValidator(targetChoices()));
    sub->add_option("--original-lut", o->originalLut,
                    "smash: the stage's LUT the screenshot was taken with (default neutral); the "
                    "patch then holds the colours the game shows with it")
        ->type_name("FILE");
    sub->add_option("--lattice", o->lattice,
                    std::string("which inputs the patch samples (default: ") +
                        toString(PatchLattice::Smash) + " for smash, " +
                        toString(PatchLattice::Uniform) +
                        " for raw): " + toString(PatchLattice::Smash) +
                        " = the colours the game shows for its 16^3 inputs (12^3); " +
                        toString(PatchLattice::Uniform) + " = j/(N-1)")
        ->type_name("NAME")
        ->check(choicesValidator(latticeChoices()));
    auto* size = sub->add_option("--size", o->size,
                                 "uniform lattice size N (default 16; implies --lattice uniform)")
                     ->check(CLI::Range(5, 64));
    addLayout(*sub, "--layout", o->layout,
              "patch layout (default: hald for square sizes, else unreal)");
    sub->add_option("--scale", o->scale,
                    "pixels per entry edge (KxK blocks; default 8, lined up with JPEG's blocks, or "
                    "the largest that fits a smaller screenshot)")
        ->check(CLI::Range(1, 31));
    sub->add_option("--corner", o->corner, "where the patch goes (default top-left)")
        ->type_name("NAME")
        ->check(choicesValidator(cornerChoices()));
    sub->add_option("--margin", o->margin,
                    "pixels at least between the frame and the image edge (default 8; the patch "
                    "moves up to 15 more to sit on the 16-pixel JPEG grid)")
        ->check(CLI::Range(0, 4096));
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "");
    sub->footer("Examples:\n"
                "  lutkit embed screenshot.png patched.png     # grade patched.png, then extract\n"
                "  lutkit embed shot.png patched.png --original-lut stage_lut.nutexb\n"
                "  lutkit embed shot.png patched.png --target raw --corner bottom-right");
    sub->callback([o, size, onParsed] {
        if (o->lattice.empty() && size->count() > 0)
            o->lattice = toString(PatchLattice::Uniform);
        onParsed(*o);
    });
    return sub;
}

} // namespace lut::cli
