#pragma once
// Embedding: paste a neutral LUT patch with a self-describing marker frame into a screenshot, so
// the modder can grade it in any editor and extract the edit as a LUT afterwards (the round trip:
// docs/roundtrip.md; finding the patch again: lut/roundtrip/PatchFinder.h; the LUT:
// lut/roundtrip/Extract.h). Works on lut::Image (no file I/O).
#include "lut/Image.h"
#include "lut/io/Layout.h"
#include "lut/pipeline/SmashConstants.h"
#include "lut/roundtrip/PatchLattice.h"
#include "lut/roundtrip/PatchPlacement.h"

#include <optional>
#include <string_view>

namespace lut {

// The default patch is the game-display lattice (12^3, pilot layout, 2x2 pixels per entry:
// 296x32 pixels with its frame); with a uniform lattice the default size is the game's
// kSmashLutSize, 16 (also Pilot's lattice, 8-bit exact since 255/15 = 17), as a 64x64 Hald image.
constexpr int kDefaultPatchScale = 2;
constexpr int kDefaultPatchMargin = 8; // pixels between the frame and the screenshot's edge

enum class PatchCorner { TopLeft, TopRight, BottomLeft, BottomRight };
const char* toString(PatchCorner);
// "top-left", "top-right", "bottom-left", "bottom-right"; throws lut::Error.
PatchCorner parseCorner(std::string_view name);

struct EmbedOptions {
    PatchLattice lattice = PatchLattice::Smash;
    int size = kSmashLutSize;        // uniform lattice only (the game-display lattice is 12^3)
    std::optional<LutLayout> layout; // default: hald when N is a square, else pilot
    int scale = kDefaultPatchScale;
    PatchCorner corner = PatchCorner::TopLeft;
    int margin = kDefaultPatchMargin;
    int bitDepth =
        8; // the bit depth the image will be written at: patch values are quantised to it
};
LutLayout defaultPatchLayout(int size);

// Draws the frame and the neutral patch into `image` (in place). Throws lut::Error if it does
// not fit.
PatchPlacement embedPatch(const ImageView& image, const EmbedOptions& options);

} // namespace lut
