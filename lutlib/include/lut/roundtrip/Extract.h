#pragma once
// Extracting: find the patch in an edited screenshot, read it, check it and turn the edit into a
// LUT for a target (docs/roundtrip.md). Works on lut::Image (no file I/O).
#include "lut/Error.h"
#include "lut/ErrorStats.h"
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/roundtrip/PatchPlacement.h"
#include "lut/roundtrip/PatchReader.h"
#include "lut/roundtrip/RoundtripWarning.h"

#include <cstddef>
#include <string_view>
#include <vector>

namespace lut {

enum class ExtractTarget { Raw, Smash };
const char* toString(ExtractTarget);
ExtractTarget parseTarget(std::string_view name); // "raw", "smash"; throws lut::Error

struct ExtractOptions {
    ExtractTarget target = ExtractTarget::Raw;
    const Lut3D* originalLut = nullptr; // smash: the stage's LUT the screenshot was taken with
    int outputSize = 0;                 // 0: 16, or the patch size for a uniform patch and raw
    int nthreads = 0;
};

struct ExtractResult {
    Lut3D lut;
    PatchPlacement placement;
    Diagnostics diagnostics;
    std::vector<RoundtripWarning> warnings;
    bool has(RoundtripWarning w) const;

    // Sub-lattice check: the patch's even lattice points predict the odd ones (spacing 2h);
    // between lattice points at spacing h the error is expected to be about a quarter of this.
    ErrorStats subLatticeError;
    ErrorStats expectedError; // subLatticeError / 4: the interpolation error at the patch spacing
    // Smash: what the game shows with the written (8-bit) LUT vs the edited look, on probes
    // between the 16^3 lattice points, display-encoded (8-bit steps via maxSteps8()).
    ErrorStats gameError;
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
