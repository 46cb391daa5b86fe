// SPDX-License-Identifier: Apache-2.0
#pragma once
// Inverting a LUT file whose 1D shaper S runs before its 3D table T (a Resolve .cube, a .csp or
// .clf read as shaper + table): f = T(S(x)), so f^-1 = S^-1(T^-1(y)). T is inverted as a table
// (lut::invert, lut/ops/Invert.h) and S per channel exactly (piecewise linear, as Lut1D
// interpolates; through its running maximum where it is not monotone), then the inverse is
// written as one 3D table: each entry of T^-1 taken through S^-1 -- never by inverting a table
// in which S and T were merged first. What one table costs is measured on inputs the lattice did
// not use: the residual |f(inverse(y)) - y| with f evaluated exactly (shaper, then table) at
// held-out targets y between the inverse's lattice points (as lut/ops/Lattice.h places them).
#include "lut/ErrorStats.h"
#include "lut/LutFile.h"
#include "lut/ops/Invert.h"

#include <cstddef>

namespace lut {

struct FileInvertResult {
    InvertResult table;          // T^-1 through S^-1; its report is T's inversion
    std::size_t shaperFolds = 0; // segments of S (all channels) that are not strictly monotone
    // |f(inverse(y)) - y| on held-out targets (targets outside f's gamut included).
    ErrorStats heldOutResidual;
    std::size_t heldOut = 0;
};

// A file without a shaper is lut::invert of its table (heldOutResidual measured alike). Throws
// lut::Error if the file holds no 3D table.
FileInvertResult invert(const LutFile& file, const InvertOptions& options = {});

} // namespace lut
