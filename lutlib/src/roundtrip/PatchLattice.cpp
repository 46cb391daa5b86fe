// The patch lattice's names and input values; see lut/roundtrip/PatchLattice.h.
#include "lut/roundtrip/PatchLattice.h"

#include "lut/Error.h"
#include "lut/Quantize.h"
#include "roundtrip/GameDisplay.h"

#include <string>

namespace lut {

const char* toString(PatchLattice l) {
    return l == PatchLattice::Smash ? "game-display" : "uniform";
}

PatchLattice parseLattice(std::string_view name) {
    if (name == "game-display" || name == "smash")
        return PatchLattice::Smash;
    if (name == "uniform")
        return PatchLattice::Uniform;
    throw Error("unknown lattice '" + std::string(name) +
                "' (expected game-display or uniform; also accepted: smash)");
}

float patchInputValue(PatchLattice lattice, int index, int size, int bitDepth) {
    const float v = lattice == PatchLattice::Smash
                        ? static_cast<float>(detail::gameDisplayLatticeValue(index))
                        : static_cast<float>(index) / static_cast<float>(size - 1);
    if (bitDepth == 8)
        return fromUnorm8(toUnorm8(v));
    if (bitDepth == 16)
        return fromUnorm16(toUnorm16(v));
    return v;
}

float patchInputValue(int index, int size, int bitDepth) {
    return patchInputValue(PatchLattice::Uniform, index, size, bitDepth);
}

} // namespace lut
