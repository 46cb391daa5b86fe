// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading a found round-trip patch: what the edit did to each lattice input (PatchReading), and
// the edit as a function of any input (PatchFunction).
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/roundtrip/BlockEvidence.h"
#include "lut/roundtrip/ChromaCheck.h"
#include "lut/roundtrip/PatchPlacement.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace lut {

// What the patch says before any target is applied.
struct PatchReading {
    PatchPlacement placement;
    Lut3D values; // the edit E at the patch lattice, entry (r,g,b) = E(input of entry (r,g,b))
    // Input value of each lattice index per channel (quantised neutral values). For a SmashStage
    // patch these are the game's LUT inputs i/15 the entries stand for; their display colours
    // are in `inputs` when the stage LUT is known.
    std::vector<float> axis;
    std::optional<Lut3D> inputs;      // SmashStage: the colour each entry held before the edit
    double blockMaxDeviation = 0.0;   // largest pixel deviation from its block mean (8-bit steps)
    std::size_t nonUniformBlocks = 0; // blocks with a deviation above 2.5 8-bit steps
    // The redundancy extract estimates the read error from (docs/roundtrip.md, "The expected
    // error"), all in [0,1] units:
    Lut3D blockSpread;        // per entry and channel: RMS deviation of the averaged pixels
    double frameSpread = 0.0; // largest distance of a marker cell from the mean of its symbol
    int storedBits = 32;      // 8 or 16 when every patch value is a multiple of 1/255 or 1/65535
    ChromaCheck chroma;       // chroma subsampling seen in the patch's pixels
    BlockEvidence blocks;     // how the pixels inside the blocks deviate (the likely cause)
};
// Throws lut::Error when the placement does not fit inside the image.
PatchReading readPatch(const ImageView& image, const PatchPlacement& placement);
// Pixels dropped at each side of a block before averaging (the border takes the brunt of
// resampling, JPEG ringing and chroma upsampling): 0 for cells of 1-2 pixels, 1 up to 5, 2 above.
int blockInset(int cell);

// Evaluates the edit the patch measured at any input: tetrahedral interpolation on the patch's
// (rectilinear, possibly quantised) lattice, clamped to the patch's input range.
class PatchFunction {
public:
    // Throws lut::Error when the axis and the table sizes differ or are below 2.
    PatchFunction(const Lut3D& values, std::vector<float> axis);
    glm::vec3 operator()(glm::vec3 in) const;

private:
    Lut3D m_values;
    std::vector<float> m_axis;
};

} // namespace lut
