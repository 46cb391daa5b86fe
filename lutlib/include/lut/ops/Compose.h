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
    // Probe points per axis for the error; 0 = 2 (size - 1) + 1 (every cell centre) when that is
    // at most 129, else about 128 placed off the lattice (spacing coprime with the lattice's).
    int probes = 0;
    int nthreads = 0; // 0 = all cores
};

// B after A: entry (r, g, b) = B(A(x)) with x the lattice input over A's domain, each LUT
// evaluated with `method` (exactly its entry where x or A(x) is on its lattice; B clamps A's
// outputs to its own domain). Exact on the lattice; between lattice points the result
// interpolates, and error measures that: |B(A(p)) - result(p)| over a probes^3 grid spanning A's
// domain, which includes every cell centre of the result's lattice.
OpResult compose(const Lut3D& a, const Lut3D& b, const ComposeOptions& options = {});

// (1 - t) A + t B per entry, on A's lattice and domain: t = 0 gives A and t = 1 gives B bit for
// bit (when B has A's size and domain). t is clamped to [-1, 2] (NaN = 0); outside [0, 1] it
// extrapolates. When B has another size or domain it is first resampled onto A's lattice with
// `method`, and error is that resampling's error times |t| (compared on the probe grid);
// otherwise the mix is exact (the interpolant of mixed entries is the mix of the interpolants)
// and error is 0.
OpResult mix(const Lut3D& a, const Lut3D& b, double t,
             Interpolation method = Interpolation::Tetrahedral, int nthreads = 0);

// LUT strength: mix(identity over A's domain, A, strength); 0 = neutral, 1 = A, up to 2
// exaggerates A. The same rule as Adjustments::strength (lut/ops/Adjust.h), clamped to [0, 2].
Lut3D withStrength(const Lut3D& a, double strength);

} // namespace lut
