// SPDX-License-Identifier: Apache-2.0
#pragma once
// The difference between two LUTs as functions: what a lossy step (resampling, quantizing,
// writing and reading back) cost.
#include "lut/ErrorStats.h"
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"

namespace lut {

// Compares two LUTs evaluated with `method` over a's domain. maxAbs is the largest difference
// over every input (bounded = true): on one lattice (same size and domain) exactly, the largest
// difference of entries (the interpolants differ by the interpolant of the entries' differences);
// otherwise bounded from held-out points between the lattice points plus the slope between them
// (lut/ops/ErrorBound.h). meanAbs: on one lattice the mean over a grid of `probes` points per
// axis (0: 2 * size + 1, at most 97), otherwise over the held-out points.
ErrorStats compareLuts(const Lut3D& a, const Lut3D& b, Interpolation method, int probes = 0);

} // namespace lut
