// SPDX-License-Identifier: Apache-2.0
#pragma once
// Whether a read patch went through chroma subsampling (a JPEG saved with 4:2:0 or 4:2:2 chroma,
// what most editors do by default), told from its pixels: at the boundary between two entries'
// blocks the brightness (luma) changes from one pixel to the next, while subsampled and
// upsampled colour (chroma) changes over two or more pixels. A JPEG's own metadata says the same
// when there is one (lut::formats::ImageInfo::chromaSubsampling); this works on any file.
#include "lut/Image.h"
#include "lut/roundtrip/PatchPlacement.h"

#include <string>

namespace lut {

struct ChromaCheck {
    bool measured = false; // enough colour edges between entries to tell (cells of 3+ pixels)
    // Share of an edge's change that happens between the two pixels at the block boundary
    // (1 = sharp; about 0.5 after 2x subsampling and upsampling), [0] across columns (horizontal
    // resolution), [1] across rows (vertical).
    double lumaSharpness[2] = {0.0, 0.0};
    double chromaSharpness[2] = {0.0, 0.0};
    bool horizontal = false; // chroma subsampled horizontally
    bool vertical = false;   // ... and vertically
    // "4:2:0", "4:2:2", "4:4:0" or "4:4:4"; "" when not measured.
    std::string scheme() const;
};

ChromaCheck checkChroma(const ImageView& image, const PatchPlacement& placement);

} // namespace lut
