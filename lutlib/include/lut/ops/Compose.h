// SPDX-License-Identifier: Apache-2.0
#pragma once
// Combining LUTs: composition (one after the other) and mixing (including LUT strength, a mix
// with the identity). NaN entries count as 0 and infinities as +-65504 (their number is in
// OpResult::sanitizedEntries), so every output entry is finite.
#include "lut/interp/Interpolation.h"
#include "lut/ops/OpResult.h"

namespace lut {

struct ComposeOptions {
    int size = 0; // edge of the result's lattice; 0 = the larger of the two sizes
    Interpolation method = Interpolation::Tetrahedral;
    int nthreads = 0; // 0 = all cores
};

// B after A: entry (r, g, b) = B(A(x)) with x the lattice input over A's domain, each LUT
// evaluated with `method` (exactly its entry where x or A(x) is on its lattice; B clamps A's
// outputs to its own domain). Exact on the lattice; between lattice points the result
// interpolates, and error says what that costs: error.maxAbs bounds |B(A(p)) - result(p)| over
// every p in A's domain (held-out points between the result's lattice points plus the slope
// between them, lut/ops/ErrorBound.h), meanAbs is the mean over those points.
OpResult compose(const Lut3D& a, const Lut3D& b, const ComposeOptions& options = {});

// (1 - t) A + t B per entry, on A's lattice and domain: t = 0 gives A and t = 1 gives B bit for
// bit (when B has A's size and domain). t is clamped to [-1, 2] (NaN = 0); outside [0, 1] it
// extrapolates. When B has another size or domain it is first resampled onto A's lattice with
// `method`, and error bounds |mix of A and B - result| over A's domain as compose's does;
// otherwise the mix is exact (the interpolant of mixed entries is the mix of the interpolants)
// and error is 0.
OpResult mix(const Lut3D& a, const Lut3D& b, double t,
             Interpolation method = Interpolation::Tetrahedral, int nthreads = 0);

// LUT strength: mix(identity over A's domain, A, strength); 0 = neutral, 1 = A, up to 2
// exaggerates A. The same rule as Adjustments::strength (lut/ops/Adjust.h), clamped to [0, 2].
Lut3D withStrength(const Lut3D& a, double strength);

} // namespace lut
