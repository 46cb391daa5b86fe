// SPDX-License-Identifier: Apache-2.0
// The patch lattice's names and input values; see lut/roundtrip/PatchLattice.h.
#include "lut/roundtrip/PatchLattice.h"

#include "lut/Error.h"
#include "lut/Quantize.h"
#include "lut/interp/Sampler.h"
#include "lut/roundtrip/SmushStrip.h"
#include "lut/smash/GameDisplay.h"

#include <string>

namespace lut {

const char* toString(PatchLattice l) {
    return l == PatchLattice::Uniform       ? "uniform"
           : l == PatchLattice::SmushLegacy ? "smush-lut strip"
                                            : "game-display";
}

PatchLattice parseLattice(std::string_view name) {
    if (name == "game-display" || name == "smash")
        return PatchLattice::Smash;
    if (name == "uniform")
        return PatchLattice::Uniform;
    throw Error("unknown lattice '" + std::string(name) +
                "' (expected game-display or uniform; also accepted: smash)");
}

bool isGameDisplayLattice(PatchLattice lattice) {
    return lattice != PatchLattice::Uniform;
}

namespace {
float quantizeTo(float v, int bitDepth) {
    if (bitDepth == 8)
        return fromUnorm8(toUnorm8(v));
    if (bitDepth == 16)
        return fromUnorm16(toUnorm16(v));
    return v;
}
} // namespace

float patchInputValue(PatchLattice lattice, int index, int size, int bitDepth) {
    if (lattice == PatchLattice::SmashStage)
        return static_cast<float>(index) / static_cast<float>(size - 1);
    if (lattice == PatchLattice::SmushLegacy)
        return smushStripAxis()[static_cast<std::size_t>(index)];
    const float v = lattice == PatchLattice::Smash
                        ? static_cast<float>(detail::gameDisplayLatticeValue(index))
                        : static_cast<float>(index) / static_cast<float>(size - 1);
    return quantizeTo(v, bitDepth);
}

float patchInputValue(int index, int size, int bitDepth) {
    return patchInputValue(PatchLattice::Uniform, index, size, bitDepth);
}

Lut3D stagePatchInputs(const Lut3D& stage, int size, int bitDepth) {
    const auto sampler = makeSampler(stage, Interpolation::Trilinear);
    Lut3D out(size);
    for (int b = 0; b < size; ++b)
        for (int g = 0; g < size; ++g)
            for (int r = 0; r < size; ++r) {
                const glm::vec3 s = glm::vec3(r, g, b) / static_cast<float>(size - 1);
                const glm::vec3 l0 = sampler->sample(s);
                glm::vec3 v;
                for (int c = 0; c < 3; ++c)
                    v[c] = quantizeTo(static_cast<float>(detail::gameShown(l0[c], s[c])), bitDepth);
                out.at(r, g, b) = v;
            }
    return out;
}

} // namespace lut
