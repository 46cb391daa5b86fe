// SPDX-License-Identifier: Apache-2.0
#pragma once
// Smoothing a LUT: a Gaussian blur over the lattice of the LUT's *deviation from the identity*
// (entry - lattice input), added back to the identity. So the identity and any LUT that is an
// affine function of its input are left exactly as they are, and the edges of the cube are not
// pulled inwards (the deviation, not the value, is extended past the edge by repeating the edge
// entry). Separable, in double precision.
#include "lut/ops/OpResult.h"

namespace lut {

// sigma: the Gaussian's standard deviation in lattice steps, clamped to [0, 8]; <= 0 or NaN
// returns the LUT unchanged (bit for bit, error 0). The kernel is truncated at 3 sigma.
// error: |result - source| on the probe grid ComposeOptions::probes describes (both evaluated
// tetrahedrally), i.e. how much the smoothing changed the LUT. NaN/Inf entries are sanitized as
// in lut/ops/Compose.h.
OpResult smooth(const Lut3D& lut, double sigma, int nthreads = 0);

} // namespace lut
