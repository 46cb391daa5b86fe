// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the pixels inside a read patch's blocks say about how the patch was touched (extract names
// the likely cause from it: lut/roundtrip/EditCause.h). A global colour edit maps every uniform
// block to a uniform block; the ways a block stops being uniform differ:
//   blur        its border moves towards the neighbouring block's colour, its middle stays;
//   sharpen     its border moves away from the neighbour's colour (overshoot);
//   noise/grain every pixel moves, the middle as much as the border;
//   JPEG        the colour (chroma) moves, the brightness (luma) does not (blocks on the grid);
//   brush       blocks in one region only (or entries there that no global edit explains).
#include <cstddef>

namespace lut {

struct BlockEvidence {
    std::size_t blocks = 0;     // blocks looked at (cells of 3+ pixels; 0 for smaller cells)
    std::size_t nonUniform = 0; // blocks with a pixel more than 2.5 8-bit steps off their mean
    // Over the non-uniform blocks' border pixels next to a different neighbour: the mean share of
    // the way from the block's colour to the neighbour's (> 0 towards it, < 0 away from it).
    double towards = 0.0;
    double borderSteps = 0.0;   // RMS deviation of those border pixels, 8-bit steps
    double interiorSteps = 0.0; // RMS deviation of the non-uniform blocks' middles
    double chromaShare = 0.0;   // share of the deviation's energy in chroma (JPEG's YCbCr)
    // The non-uniform blocks' bounding box in patch cells, and the share of the patch it covers.
    int boxX0 = 0, boxY0 = 0, boxX1 = -1, boxY1 = -1;
    double boxShare = 0.0;
};

} // namespace lut
