// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: the bits of the marker frame around a round-trip patch (the picture is in
// lut/roundtrip/PatchPlacement.h). Two header versions, told apart by the sync byte; both are
// written most significant bit first, clockwise around the inner ring and repeated:
//   version 1 (35 bits, patches embedded before issue 14; read, never written):
//     sync 0xB2 (8) | lattice (1) | bit depth (2) | layout (2) | N (9) | scale (5) | CRC-8 (8)
//   version 2 (55 bits):
//     sync 0xB5 (8) | lattice (2) | bit depth (2) | layout (2) | N (9) | scale (5) |
//     target (2: none, raw, smash) | digest present (1) | stage LUT digest (16) | CRC-8 (8)
// The geometry fields (sync up to N: 22 or 23 bits) fix the frame's size; they sit on the inner
// ring's top row, which is why a patch must be at least kMinHeaderRow - 2 entries wide. The CRC
// covers every bit before it.
#include "lut/LutPurpose.h"
#include "lut/io/Layout.h"
#include "lut/roundtrip/PatchLattice.h"

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace lut::detail {

constexpr int kMaxHeaderBits = 55;
constexpr int kSyncBits = 8;
constexpr int kMaxGeometryBits = 23;
constexpr int kMinHeaderRow = kMaxGeometryBits + 2; // inner top row cells needed

using HeaderBits = std::array<int, kMaxHeaderBits>;

// What the header says.
struct MarkerHeader {
    int version = 2;
    PatchLattice lattice = PatchLattice::Uniform;
    int bitDepth = 8; // 8, 16 or 32
    LutLayout layout = LutLayout::Hald;
    int size = 0;
    int scale = 0;
    std::optional<LutPurpose> target;         // version 2
    std::optional<std::uint16_t> stageDigest; // version 2
};

// Bits of each part for a header version (1 or 2); 0 for an unknown version.
int headerBitCount(int version);
int geometryBitCount(int version);
// The version a sync byte (the first kSyncBits bits) announces, 0 if none.
int versionFromSync(const HeaderBits& bits);

// The header's bits (version 2 unless header.version says 1), CRC included.
HeaderBits headerBits(const MarkerHeader& header);
// Reads the geometry fields: false when the sync word is unknown or a field is invalid (bit
// depth code 3, size outside the LUT limits, a game-display lattice of the wrong size).
bool decodeGeometry(const HeaderBits& bits, MarkerHeader& header);
// Checks the CRC over all bits and reads the remaining fields: false when the CRC fails or a field
// is invalid.
bool decodeHeader(const HeaderBits& bits, MarkerHeader& header);

// The patch's size in entries (cells) for a layout, as the layout draws it.
void patchCells(LutLayout layout, int size, int& cellsWide, int& cellsHigh);

// Cells of the inner ring, clockwise from the top-left inner corner, in frame cell coordinates
// (the frame is fw x fh cells, the outer ring at 0 and fw-1 / fh-1).
std::vector<std::pair<int, int>> innerRing(int fw, int fh);

} // namespace lut::detail
