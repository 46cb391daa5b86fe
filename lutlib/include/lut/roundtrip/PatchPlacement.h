// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where a round-trip patch sits in an image, how big its marker frame is, and what the frame's
// header says about it (the patch describes itself: extract needs no options for what embed set
// up).
//
// The marker frame (two cells wide around the patch, one cell = scale x scale pixels):
//  - outer ring: a checkerboard of two symbols, white and black;
//  - inner ring: the header (sync word, lattice, bit depth, layout, size, scale, target, the
//    stage LUT's digest, CRC-8) written clockwise from the top-left inner corner and repeated.
//    Patches made before the target and digest existed (header version 1) still read.
// Detection never looks at absolute levels: a symbol is "the colour of the even outer cells" or
// "the colour of the odd outer cells", whatever the edit made of white and black. Any per-pixel
// global edit (curves, levels, inversion, gradient maps, channel mixing) keeps equal pixels equal
// and so keeps the pattern; only an edit that maps white and black to the same colour destroys it.
#include "lut/LutPurpose.h"
#include "lut/io/Layout.h"
#include "lut/roundtrip/PatchLattice.h"

#include <cstdint>
#include <optional>

namespace lut {

constexpr int kMaxPatchScale = 31; // five header bits

// Where a patch sits, in pixels of the image it was found in or drawn into, and what its header
// records.
struct PatchPlacement {
    PatchLattice lattice = PatchLattice::Uniform;
    LutLayout layout = LutLayout::Hald;
    int size = 0;     // N
    int scale = 1;    // pixels per entry (edge of the square block) as embedded
    int cell = 1;     // pixels per entry as found (== scale unless the image was upscaled)
    int bitDepth = 8; // what the patch values were quantised to when embedded (8, 16, 32)
    int frameX = 0;   // top-left pixel of the marker frame
    int frameY = 0;
    int frameWidth = 0; // frame size in pixels
    int frameHeight = 0;
    int headerVersion = 2; // 1: made before the target and the digest were recorded
    // What the modder said they were making when embedding (none in version 1 headers).
    std::optional<LutPurpose> target;
    // The digest (lutDigest, lut/roundtrip/LutDigest.h) of the stage LUT the patch was made for
    // (embed --original-lut); none for a neutral stage.
    std::optional<std::uint16_t> stageDigest;
    int patchX() const { return frameX + 2 * cell; }
    int patchY() const { return frameY + 2 * cell; }
};

// Frame size in pixels of a patch (throws lut::Error for unsupported combinations: the header
// needs a patch at least 21 entries wide, i.e. N >= 5 for strips and N >= 9 for Hald).
void patchFrameSize(LutLayout layout, int size, int scale, int& width, int& height);

} // namespace lut
