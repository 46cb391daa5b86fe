// SPDX-License-Identifier: Apache-2.0
#pragma once
// The patch lattice: which input values a round-trip patch samples (docs/roundtrip.md).
#include "lut/Lut3D.h"

#include <glm/vec3.hpp>

#include <string_view>

namespace lut {

// Which inputs the patch samples.
//  - Uniform ("uniform"): j/(N-1) per channel, the lattice of an N^3 LUT (what raw engines use).
//  - Smash ("game-display"; "smash" is accepted too): the 12 display values the unedited game
//    shows for its lattice inputs i/15 (with a neutral stage LUT): srgbEncode(min(1,
//    (1.3703 i/15)^2.2)), i = 0..10, and 1 (i >= 11 all clip to white). Extracting for
//    --target smash then reads the edit exactly where the game's 16^3 LUT needs it instead of
//    interpolating: docs/roundtrip.md has the numbers.
//  - SmashStage (also shown as "game-display"): the game-display lattice for a stage that already
//    has a LUT L0 (embed --original-lut). Not a product of per-channel values: entry (i, j, k)
//    of the 16^3 patch holds the colour the unedited game displays for its LUT input
//    s = (i, j, k)/15, srgbEncode(min(1, (((L0(s) - s) * 0.99961 + s) * 1.3703)^2.2)), so the
//    edit is read at exactly the colours the compensation needs (stagePatchInput).
//  - SmushLegacy ("smush-lut strip"): not a lutkit patch; Smush-LUT's first .lut.png strip
//    (lut/roundtrip/SmushStrip.h), per-axis values of the game's default stage LUT, whose
//    edited values are the game's LUT itself. Never written to a header.
enum class PatchLattice { Uniform, Smash, SmashStage, SmushLegacy };
// "uniform", "game-display" (both game-display kinds) or "smush-lut strip".
const char* toString(PatchLattice);
// "uniform", "game-display" or its alias "smash"; throws lut::Error naming the accepted names.
PatchLattice parseLattice(std::string_view name);
constexpr int kSmashLatticeSize = 12;
// True for the lattices made for the game (Smash, SmashStage, SmushLegacy).
bool isGameDisplayLattice(PatchLattice lattice);

// The input value a patch lattice index stands for once stored at bitDepth: j/(N-1) (or the
// Smash lattice value) rounded to the nearest 8- or 16-bit step (exact for 32). For SmashStage
// (whose inputs are not per channel) this is the game's LUT input j/(N-1) the entry stands for.
float patchInputValue(PatchLattice lattice, int index, int size, int bitDepth);
float patchInputValue(int index, int size, int bitDepth); // uniform

// The SmashStage patch's inputs, entry (r, g, b) of the size^3 table: the display colour the game
// shows with the stage LUT `stage` (sampled trilinearly over [0,1], as the game does) for its LUT
// input s = (r, g, b)/(size-1), stored at bitDepth.
Lut3D stagePatchInputs(const Lut3D& stage, int size, int bitDepth);

} // namespace lut
