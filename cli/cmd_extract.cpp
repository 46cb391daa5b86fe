#include "cmd_extract.h"

#include "Commands.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/roundtrip/Extract.h"
#include "lut/roundtrip/PatchFinder.h"
#include "lut/roundtrip/PatchReader.h"

#include <cstdio>
#include <iostream>

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
            std::cerr << "lutkit: warning: --original-lut only matters with --target smash\n";
        original = formats::readLut(o.originalLut).toLut3D();
        eo.originalLut = &original;
    }
    const FindResult found = findPatch(loaded.image.view());
    if (found.status != FindStatus::Found) {
        std::cerr << "lutkit: error: " << o.input << ": " << found.message << "\n";
        return kExitFailure;
    }
    const PatchReading patch = readPatch(loaded.image.view(), found.placement);
    ExtractResult res = extractLut(patch, eo);
    for (const auto& d : res.diagnostics) {
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
    fo.layout = layoutOption("--layout", o.layout);
    const Diagnostics wd = formats::writeLut(o.output, file, fo, o.format);
    for (const auto& d : wd)
        std::cerr << "lutkit: " << d.str() << "\n";
    std::cout << "wrote " << file.cube->size() << "^3 " << toString(eo.target)
              << " LUT: " << o.output << "\n";
    return kExitOk;
}

} // namespace lut::cli
