// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: what extract checks on a read patch before it builds a LUT, and how it
// reports what it found (warnings with a kind, info notes). Each warning has a test that
// triggers it (docs/roundtrip.md, "Warnings").
#include "core/Printf.h"
#include "lut/ErrorStats.h"
#include "lut/roundtrip/Extract.h"
#include "lut/roundtrip/PatchReader.h"
#include "lut/roundtrip/RoundtripWarning.h"
#include "lut/smash/GameError.h"

#include <string>

namespace lut::detail {

// A warning: its kind in res.warnings, its message in res.diagnostics.
void addWarning(ExtractResult& res, RoundtripWarning w, const std::string& message);
// An info diagnostic.
void addNote(ExtractResult& res, const std::string& message);

// The checks on the patch itself, in this order: blocks that are not uniform, entries no smooth
// global edit explains (res.suspiciousEntries), values clipped at 0 or 1 (res.clippedValues),
// and a grey axis that follows a pure gamma or sRGB <-> 2.2 curve (res.gamma): a colour-profile
// conversion rather than an edit.
// When blocks are not uniform the likely cause is named (res.cause) with its fix; lossyFile says
// the file is known to be lossy (a JPEG), which makes colour-only deviation a compression mark.
void checkPatch(const PatchReading& patch, ExtractResult& res, bool lossyFile);

// Sub-lattice check: the patch's even lattice points (and the last one) predict the others by
// the same interpolation extract uses (spacing 2h instead of h).
struct SubLattice {
    GameError stats; // over all channels of the predicted entries, 8-bit steps
    // Per entry and channel, 8-bit steps: at a predicted entry its prediction error, at a kept
    // one the largest of its neighbours' (so every cell of the patch has a local value).
    Lut3D residual;
};
SubLattice subLatticeCheck(const PatchReading& patch);

} // namespace lut::detail
