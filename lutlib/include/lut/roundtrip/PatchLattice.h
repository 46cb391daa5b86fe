#pragma once
// The patch lattice: which input values a round-trip patch samples per channel (docs/roundtrip.md).
#include <string_view>

namespace lut {

// Which inputs the patch samples per channel.
//  - Uniform ("uniform"): j/(N-1), the lattice of an N^3 LUT (what raw engines use).
//  - Smash ("game-display"; "smash" is accepted too): the 12 display values the unedited game
//    shows for its lattice inputs i/15 (with a neutral stage LUT): srgbEncode(min(1,
//    (1.3703 i/15)^2.2)), i = 0..10, and 1 (i >= 11 all clip to white). Extracting for
//    --target smash then reads the edit exactly where the game's 16^3 LUT needs it instead of
//    interpolating: docs/roundtrip.md has the numbers.
enum class PatchLattice { Uniform, Smash };
// "uniform" or "game-display".
const char* toString(PatchLattice);
// "uniform", "game-display" or its alias "smash"; throws lut::Error naming the accepted names.
PatchLattice parseLattice(std::string_view name);
constexpr int kSmashLatticeSize = 12;

// The input value a patch lattice index stands for once stored at bitDepth: j/(N-1) (or the
// Smash lattice value) rounded to the nearest 8- or 16-bit step (exact for 32).
float patchInputValue(PatchLattice lattice, int index, int size, int bitDepth);
float patchInputValue(int index, int size, int bitDepth); // uniform

} // namespace lut
