// SPDX-License-Identifier: Apache-2.0
#pragma once
// Embedding: paste a neutral LUT patch with a self-describing marker frame into a screenshot, so
// the modder can grade it in any editor and extract the edit as a LUT afterwards (the round trip:
// docs/roundtrip.md; finding the patch again: lut/roundtrip/PatchFinder.h; the LUT:
// lut/roundtrip/Extract.h). Works on lut::Image (no file I/O).
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/LutPurpose.h"
#include "lut/io/Layout.h"
#include "lut/roundtrip/PatchLattice.h"
#include "lut/roundtrip/PatchPlacement.h"
#include "lut/smash/SmashConstants.h"

#include <optional>
#include <string_view>

namespace lut {

// Pixels per entry edge by default. 8 puts every entry on its own 8x8 JPEG block and (with the
// grid alignment below) every 2x2 entries on one 16x16 macroblock, so a quality-90 JPEG with 4:2:0
// chroma keeps the patch (docs/roundtrip.md has the measurements).
constexpr int kDefaultPatchScale = 8;
constexpr int kDefaultPatchMargin = 8; // pixels between the frame and the screenshot's edge
constexpr int kJpegGrid = 16;          // a 4:2:0 JPEG's macroblock edge in pixels

enum class PatchCorner { TopLeft, TopRight, BottomLeft, BottomRight };
const char* toString(PatchCorner);
// "top-left", "top-right", "bottom-left", "bottom-right"; throws lut::Error.
PatchCorner parseCorner(std::string_view name);

struct EmbedOptions {
    // What the modder is making; recorded in the header so extract does the same by default, and
    // it picks the default lattice: the game-display lattice for smash (12^3; 16^3 with an
    // original LUT), the uniform 16^3 lattice for raw (exact at a raw 16^3 LUT's points).
    LutPurpose target = LutPurpose::Smash;
    std::optional<PatchLattice> lattice; // default: from the target (above)
    int size = kSmashLutSize;            // uniform lattice only
    // Smash: the stage's LUT the screenshot was taken with. The game-display patch then holds the
    // colours the game displays for its LUT inputs with this LUT (PatchLattice::SmashStage), and
    // the header records its digest (lut/roundtrip/LutDigest.h). Refused for raw.
    const Lut3D* originalLut = nullptr;
    std::optional<LutLayout> layout; // default: hald when N is a square, else pilot
    // Pixels per entry edge; 0: kDefaultPatchScale, or the largest scale that fits a smaller
    // screenshot (the placement says which; below kDefaultPatchScale a lossy save may cost
    // accuracy).
    int scale = 0;
    PatchCorner corner = PatchCorner::TopLeft;
    int margin = kDefaultPatchMargin; // at least this many pixels from the image's edges
    // Put the patch's first entry on the 16-pixel JPEG grid (moving the frame by up to 15
    // pixels inwards), so blocks of 8 or 16 pixels line up with JPEG's blocks.
    bool alignToJpegGrid = true;
    int bitDepth = 8; // the bit depth the image will be written at: patch values are quantised
};
LutLayout defaultPatchLayout(int size);
// The lattice embed uses for these options (the default from the target and the original LUT).
PatchLattice effectiveLattice(const EmbedOptions& options);

// Draws the frame and the neutral patch into `image` (in place). Throws lut::Error if it does
// not fit or the options contradict each other (an original LUT for a raw patch).
PatchPlacement embedPatch(const ImageView& image, const EmbedOptions& options);

} // namespace lut
