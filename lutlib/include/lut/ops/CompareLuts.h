#pragma once
// The difference between two LUTs as functions: what a lossy step (resampling, quantizing,
// writing and reading back) cost.
#include "lut/ErrorStats.h"
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"

namespace lut {

// Compares two LUTs by evaluating both with `method` on a probe grid of `probes` points per
// axis spanning a's domain (0: 2 * the larger size + 1, at most 97, so that probes fall between
// the lattice points of both).
ErrorStats compareLuts(const Lut3D& a, const Lut3D& b, Interpolation method, int probes = 0);

} // namespace lut
