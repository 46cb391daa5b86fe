// lutkit embed: a neutral LUT patch with a self-describing marker frame, pasted into a
// screenshot (docs/roundtrip.md); lutkit extract finds it again after grading.
#include "commands/Embed.h"

#include "Usage.h"
#include "Vocabulary.h"

#include "lut/formats/ImageIO.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/roundtrip/Embed.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lut::cli {

int runEmbed(const EmbedOptions& o) {
    // Never over the clean screenshot: fit and tests need it.
    const OutputTarget target = resolveOutput(o.output, o.overwrite, {o.input});
    if (target.skip) {
        if (!o.verbosity.quiet)
            std::cerr << "lutkit: " << o.output << " exists; skipped (-n)\n";
        return kExitOk;
    }
    auto loaded = formats::readImage(o.input);
    lut::EmbedOptions eo;
    eo.lattice = o.lattice.empty() ? PatchLattice::Smash : parseLattice(o.lattice);
    eo.size = o.size;
    eo.layout = o.layout;
    eo.scale = o.scale;
    eo.corner = parseCorner(o.corner);
    eo.margin = o.margin;
    // Keep the screenshot's own depth: the patch is quantised to exactly what will be stored.
    eo.bitDepth = loaded.info.bitDepth == 16 ? 16 : loaded.info.bitDepth == 32 ? 32 : 8;
    const PatchPlacement p = embedPatch(loaded.image.view(), eo);

    formats::ImageWriteOptions wo;
    wo.bitDepth = eo.bitDepth;
    wo.alpha = loaded.info.channels == 2 || loaded.info.channels == 4;
    const std::string ext = extensionOf(o.output);
    if ((ext == ".jpg" || ext == ".jpeg") && o.scale < 4)
        std::cerr << "lutkit: warning: " << o.output
                  << ": JPEG is lossy; use PNG or TIFF, or at least --scale 4 so blocks can be "
                     "averaged\n";
    if (ext == ".png" && eo.bitDepth == 32)
        wo.bitDepth = 16;
    wo.metadata = loaded.metadata;
    formats::writeImage(target.writePath, loaded.image, wo);
    std::cout << "embedded a " << p.size << "^3 " << toString(p.lattice) << "-lattice "
              << toString(p.layout) << " patch at scale " << p.scale << " (" << p.frameWidth << "x"
              << p.frameHeight << " pixels with its frame) at (" << p.frameX << ", " << p.frameY
              << "), " << wo.bitDepth << "-bit: " << o.output << "\n";
    if (!o.verbosity.quiet)
        std::cout << "grade the whole image with global adjustments only, then run: lutkit "
                     "extract EDITED OUT\n";
    return kExitOk;
}

CLI::App* setupEmbed(CLI::App& app, std::function<void(const EmbedOptions&)> onParsed) {
    auto o = std::make_shared<EmbedOptions>();
    auto* sub =
        app.add_subcommand("embed", "Paste a neutral LUT patch with markers into a screenshot");
    sub->add_option("SCREENSHOT", o->input, "screenshot to copy (8- or 16-bit kept)")
        ->required()
        ->type_name("FILE");
    sub->add_option("OUT", o->output, "output image (PNG or TIFF recommended)")
        ->required()
        ->type_name("FILE");
    sub->add_option("--lattice", o->lattice,
                    std::string("which inputs the patch samples: ") +
                        toString(PatchLattice::Smash) +
                        " (default) = the display values of the game's 16^3 inputs (12^3); " +
                        toString(PatchLattice::Uniform) + " = j/(N-1)")
        ->type_name("NAME")
        ->check(choicesValidator(latticeChoices()));
    auto* size = sub->add_option("--size", o->size,
                                 "uniform lattice size N (default 16; implies --lattice uniform)")
                     ->check(CLI::Range(5, 64));
    addLayout(*sub, "--layout", o->layout,
              "patch layout (default: hald for square sizes, else unreal)");
    sub->add_option("--scale", o->scale, "pixels per entry edge (KxK blocks, default 2)")
        ->check(CLI::Range(1, 31));
    sub->add_option("--corner", o->corner, "where the patch goes (default top-left)")
        ->type_name("NAME")
        ->check(choicesValidator(cornerChoices()));
    sub->add_option("--margin", o->margin,
                    "pixels between the frame and the image edge (default 8)")
        ->check(CLI::Range(0, 4096));
    addOverwriteOptions(*sub, o->overwrite);
    addVerbosity(*sub, o->verbosity, "");
    sub->footer("Examples:\n"
                "  lutkit embed screenshot.png patched.png     # grade patched.png, then extract\n"
                "  lutkit embed shot.png patched.png --lattice uniform --size 16 --corner "
                "bottom-right");
    sub->callback([o, size, onParsed] {
        if (o->lattice.empty() && size->count() > 0)
            o->lattice = toString(PatchLattice::Uniform);
        onParsed(*o);
    });
    return sub;
}

} // namespace lut::cli
