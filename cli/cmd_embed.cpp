#include "cmd_embed.h"

#include "Commands.h"
#include "lut/formats/ImageIO.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/io/Format.h"
#include "lut/roundtrip/Embed.h"

#include <iostream>

namespace lut::cli {

int runEmbed(const EmbedOptions& o) {
    checkNotSameFile(o.input, o.output); // keep the clean screenshot: fit and tests need it
    auto loaded = formats::readImage(o.input);
    lut::EmbedOptions eo;
    eo.lattice = o.lattice.empty() ? PatchLattice::Smash : parseLattice(o.lattice);
    eo.size = o.size;
    if (!o.layout.empty())
        eo.layout = parseLayout(o.layout);
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
    formats::writeImage(o.output, loaded.image, wo);
    std::cout << "embedded a " << p.size << "^3 " << toString(p.lattice) << "-lattice "
              << toString(p.layout) << " patch at scale " << p.scale << " (" << p.frameWidth << "x"
              << p.frameHeight << " pixels with its frame) at (" << p.frameX << ", " << p.frameY
              << "), " << wo.bitDepth << "-bit: " << o.output << "\n"
              << "grade the whole image with global adjustments only, then run: lutkit extract "
                 "EDITED OUT\n";
    return kExitOk;
}

} // namespace lut::cli
