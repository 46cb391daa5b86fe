#pragma once
#include "lut/ErrorStats.h"
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"

namespace lut {

// A LUT of edge `size` over the same domain, each entry the source evaluated with `method`.
Lut3D resample(const Lut3D& source, int size, Interpolation method, int nthreads = 0);

// The same, also saying what it cost: error is measured by evaluating both the source and the
// result (with `method`) on a dense grid of probe points between lattice points of both.
struct ResampleResult {
    Lut3D lut;
    ErrorStats error;
};
ResampleResult resampleWithError(const Lut3D& source, int size, Interpolation method,
                                 int nthreads = 0);

// Rounds every entry to the nearest 8-bit step (clamped to [0,1]) and reports the error.
ErrorStats quantize8(Lut3D& lut);

// Compares two LUTs by evaluating both with `method` on a probe grid of `probes` points per
// axis spanning a's domain.
ErrorStats compareLuts(const Lut3D& a, const Lut3D& b, Interpolation method, int probes = 0);

} // namespace lut
