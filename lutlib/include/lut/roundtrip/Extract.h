// SPDX-License-Identifier: Apache-2.0
#pragma once
// Extracting: find the patch in an edited screenshot, read it, check it and turn the edit into a
// LUT for a target (docs/roundtrip.md). Works on lut::Image (no file I/O).
#include "lut/Error.h"
#include "lut/ErrorStats.h"
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/LutPurpose.h"
#include "lut/ops/Strength.h"
#include "lut/roundtrip/EditCause.h"
#include "lut/roundtrip/PatchPlacement.h"
#include "lut/roundtrip/PatchReader.h"
#include "lut/roundtrip/RoundtripWarning.h"
#include "lut/smash/GameError.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lut {

struct ExtractOptions {
    // Default: what the patch's header records (embed's --target), else smash for a game-display
    // patch and raw for a uniform one (patches made before the target was recorded).
    std::optional<LutPurpose> target;
    std::string targetReason; // why the caller chose the target, for the note ("" = "given")
    // Smash: the stage's LUT the screenshot was taken with. A patch embedded with --original-lut
    // already holds its picture (only checked against the recorded digest); other patches are
    // interpolated at the colours it shows.
    const Lut3D* originalLut = nullptr;
    int outputSize = 0;  // 0: 16, or the patch size for a uniform patch and raw
    bool refine = false; // smash: least-squares refinement between lattice points
    // What the file's metadata says about chroma subsampling ("4:2:0", "4:2:2", "4:4:4"; ""
    // unknown: lut::formats::ImageInfo::chromaSubsampling); the patch's pixels are checked too.
    std::string fileChromaSubsampling;
    // The edit at a strength (lut/ops/Strength.h): each patch entry blended with the colour it
    // held before the edit, so the LUT (raw, or the game's) gives that share of the edit. The
    // checks of the patch look at the edit as it was made.
    StrengthOptions strength;
    int nthreads = 0;
};

// Where the target came from.
enum class TargetSource { Option, Patch, Lattice };
const char* toString(TargetSource); // "given", "recorded in the patch", "the patch's lattice"

// An estimate that is meant to be an upper bound of the true error in practice: built from the
// patch's own redundancy (the spread of the pixels of each block, the marker cells' spread, the
// sub-lattice check of neighbouring cells), never from a best case (docs/roundtrip.md).
struct ExpectedError {
    GameError atLattice; // at the output LUT's lattice points
    GameError overall;   // at every input: the lattice points and between them
    std::string covers;  // what is compared with what, in which units
    // The largest interpolation term between the patch's entries (8-bit steps): the sub-lattice
    // check and each entry's prediction from its neighbours.
    double interpolationSteps = 0.0;
};

struct ExtractResult {
    Lut3D lut;
    PatchPlacement placement;
    LutPurpose target = LutPurpose::Raw;
    TargetSource targetSource = TargetSource::Lattice;
    Diagnostics diagnostics;
    std::vector<RoundtripWarning> warnings;
    bool has(RoundtripWarning w) const;
    EditCause cause = EditCause::None; // the likely cause when the patch is not a global edit

    ExpectedError expected;
    // The parts of the estimate, 8-bit steps:
    GameError subLattice;      // the patch's even points predicting the odd ones (spacing 2h)
    double readNoiseMax = 0.0; // largest read error of one entry (storage, blocks, marker cells)
    double readNoiseMean = 0.0;
    // What the LUT does against the edit as the patch measured it (no read or interpolation
    // error of the patch counted): smash, the game with the 8-bit LUT; raw, the LUT applied with
    // trilinear interpolation. A best case: the expected error above adds what the patch cannot
    // know.
    GameError modelError;
    bool refined = false;           // smash: the LUT is the least-squares refinement
    GameError exactModelError;      // smash with refine: the exact composition's model error
    std::string refineDecision;     // smash with refine: what it was fitted on, which was written
    std::size_t clampedEntries = 0; // smash: channel values that needed L outside [0,1]
    double clampedMax = 0.0;        // ... and the farthest one (in [0,1] units)
    std::size_t clippedValues = 0;  // channel values at 0 or 1 that were not 0 or 1 in the neutral
    std::size_t suspiciousEntries = 0; // entries no smooth or piecewise-smooth edit explains
    double gamma = 1.0;                // fitted grey-axis exponent
};

// Finds the patch (throws lut::Error when not found or scaled by a non-integer factor), reads it,
// checks it and builds the LUT for the target.
ExtractResult extractLut(const ImageView& edited, const ExtractOptions& options);
// The same from an already read patch.
ExtractResult extractLut(const PatchReading& patch, const ExtractOptions& options);

} // namespace lut
