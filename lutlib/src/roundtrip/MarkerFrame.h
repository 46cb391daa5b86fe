#pragma once
// Internal to lutlib: the bits of the marker frame around a round-trip patch (the picture is in
// lut/roundtrip/PatchPlacement.h). The header is 35 bits, most significant first:
//     sync 0xB2 (8) | lattice (1) | bit depth (2) | layout (2) | N (9) | scale (5) | CRC-8 (8)
// The first 22 bits (up to N) fix the frame's geometry; they sit on the inner ring's top row,
// which is why a patch must be at least kMinHeaderRow - 2 entries wide.
#include "lut/io/Layout.h"
#include "lut/roundtrip/PatchLattice.h"

#include <array>
#include <utility>
#include <vector>

namespace lut::detail {

constexpr int kHeaderBits = 35;
constexpr int kGeometryBits = 22; // sync + lattice + depth + layout + size: enough to know the ring
constexpr int kPayloadBits = 27;  // everything before the CRC
constexpr int kMinHeaderRow = kGeometryBits + 2;

using HeaderBits = std::array<int, kHeaderBits>;

// What the header says.
struct MarkerHeader {
    PatchLattice lattice = PatchLattice::Uniform;
    int bitDepth = 8; // 8, 16 or 32
    LutLayout layout = LutLayout::Hald;
    int size = 0;
    int scale = 0;
};

// The header's bits, CRC included.
HeaderBits headerBits(const MarkerHeader& header);
// Reads the geometry fields from bits[0, kGeometryBits): false when the sync word is wrong or a
// field is invalid (bit depth code 3, size outside the LUT limits, a Smash lattice not 12^3).
bool decodeGeometry(const HeaderBits& bits, MarkerHeader& header);
// Checks the CRC over all bits and reads the scale: false when the CRC fails or scale is 0.
bool decodeHeader(const HeaderBits& bits, MarkerHeader& header);

// The patch's size in entries (cells) for a layout, as the layout draws it.
void patchCells(LutLayout layout, int size, int& cellsWide, int& cellsHigh);

// Cells of the inner ring, clockwise from the top-left inner corner, in frame cell coordinates
// (the frame is fw x fh cells, the outer ring at 0 and fw-1 / fh-1).
std::vector<std::pair<int, int>> innerRing(int fw, int fh);

} // namespace lut::detail
