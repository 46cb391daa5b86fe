// SPDX-License-Identifier: Apache-2.0
#pragma once
// The game's LUT a LUT file stands for, where a stage's LUT is named by a file (--original-lut
// of preview, embed, extract and convert --target smash): Smash Ultimate samples one 16^3 table
// over [0,1] trilinearly, so a file that is one 3D table is taken as it is, and a file with a 1D
// shaper (a Resolve .cube, a .csp or .clf read as shaper + table, a 1D-only file) is evaluated
// exactly (shaper, then table) at the game's 16^3 lattice over [0,1] -- never merged into a
// table of its own size over the shaper's range -- with what that costs measured between the
// lattice points (sampleOnLattice, lut/ops/Lattice.h) and said in a diagnostic.
#include "lut/Error.h"
#include "lut/Lut3D.h"
#include "lut/LutFile.h"

#include <string>

namespace lut {

struct StageLutFile {
    Lut3D lut;
    Diagnostics diagnostics; // one note (a warning above one 8-bit step) when a shaper was sampled
};

// Throws lut::Error if the file holds no table.
StageLutFile stageLutFromFile(const LutFile& file, const std::string& path);

} // namespace lut
