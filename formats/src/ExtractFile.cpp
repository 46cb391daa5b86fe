// SPDX-License-Identifier: Apache-2.0
// The LUT an edited file shows; see lut/formats/ExtractFile.h.
#include "lut/formats/ExtractFile.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/StdStreams.h"
#include "lut/ops/Resample.h"
#include "lut/ops/Strength.h"
#include "lut/roundtrip/PatchFinder.h"
#include "lut/roundtrip/PatchReader.h"
#include "lut/roundtrip/SmushStrip.h"

#include <algorithm>

namespace lut::formats {

ExtractFileResult extractLutFromFile(const std::string& path, const ExtractFileOptions& o) {
    ExtractFileResult out;
    // The patch may be anywhere: the search needs the whole picture, so its size is bounded
    // before any pixel is read (issue 41: a 16384^2 PNG of 826 KB took 4.1 GB).
    if (!isStdinName(path)) {
        const ImageInfo info = readImageInfo(path);
        const std::uint64_t pixels =
            static_cast<std::uint64_t>(info.width) * static_cast<std::uint64_t>(info.height);
        if (pixels > limits::kMaxPatchSearchPixels)
            throw LimitError(path + ": " + std::to_string(info.width) + "x" +
                             std::to_string(info.height) +
                             " pixels, more than extract searches for a patch (at most 7680x4320, "
                             "an 8K screenshot: the search holds the whole picture); crop it "
                             "around the patch");
    }
    LoadedImage loaded = readImage(path);
    const ImageView view = loaded.image.view();
    const FindResult found = findPatch(view);
    PatchReading patch;
    if (found.status == FindStatus::Found) {
        patch = readPatch(view, found.placement);
        out.source = ExtractSource::Patch;
    } else if (loaded.image.width() == loaded.image.height() * loaded.image.height()) {
        // No marker frame, and an N^2 x N picture: a LUT strip, a graded neutral.
        out.source = ExtractSource::LutImage;
        FormatOptions ro;
        ro.layout = o.inLayout;
        out.image = readLut(path, ro);
        out.decision = decidePurpose(*out.image, o.inPurpose);
        out.purpose = o.extract.target.value_or(out.decision.purpose);
        // The strength blends the edit (lut/ops/Strength.h): an edit before it is made into the
        // game's LUT, the edit a game LUT makes after it is made, a LUT kept for its purpose as
        // it is.
        const bool full = isFullStrength(o.extract.strength);
        const bool blendAfter =
            out.decision.purpose == LutPurpose::Smash && out.purpose == LutPurpose::Raw;
        Lut3D table = out.image->toLut3D();
        if (!full && !blendAfter)
            table = applyStrength(table, o.extract.strength);
        if (out.purpose == out.decision.purpose) {
            const int size = o.extract.outputSize;
            out.lut = size > 0 && size != table.size()
                          ? resample(table, size, Interpolation::Tetrahedral)
                          : table;
            return out;
        }
        PurposeOptions po;
        po.stageLut = o.extract.originalLut;
        po.refine = o.extract.refine;
        po.measure = true;
        po.rawSize = o.extract.outputSize > 0 ? o.extract.outputSize : std::max(33, table.size());
        po.nthreads = o.extract.nthreads;
        out.conversion = convertPurpose(table, out.decision.purpose, out.purpose, po);
        out.lut = out.conversion->lut;
        if (!full && blendAfter)
            out.lut = applyStrength(out.lut, o.extract.strength);
        return out;
    } else if (found.status == FindStatus::NotFound && isSmushStripName(path) &&
               loaded.image.width() >= 256 && loaded.image.height() >= 16) {
        out.source = ExtractSource::SmushStrip;
        patch = readSmushStrip(view);
    } else {
        throw Error(path + ": " + found.message);
    }
    ExtractOptions eo = o.extract;
    eo.fileChromaSubsampling = loaded.info.chromaSubsampling;
    out.extract = extractLut(patch, eo);
    out.lut = out.extract->lut;
    out.purpose = out.extract->target;
    return out;
}

} // namespace lut::formats
