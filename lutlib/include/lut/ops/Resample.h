#pragma once
// Resampling a LUT to another lattice size, with the error it introduced (measured with
// compareLuts, lut/ops/CompareLuts.h).
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

} // namespace lut
