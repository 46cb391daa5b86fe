// SPDX-License-Identifier: Apache-2.0
#pragma once
// Resampling a LUT to another lattice size, with the error it introduced (bounded over the whole
// domain, lut/ops/ErrorBound.h).
#include "lut/ErrorStats.h"
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"

namespace lut {

// A LUT of edge `size` over the same domain, each entry the source evaluated with `method`.
Lut3D resample(const Lut3D& source, int size, Interpolation method, int nthreads = 0);

// The same, also saying what it cost: error.maxAbs bounds |source - result| (both evaluated with
// `method`) over every input of the domain, from held-out points between the lattice points of
// both plus the slope between them (lut/ops/ErrorBound.h); meanAbs is the mean over those points.
struct ResampleResult {
    Lut3D lut;
    ErrorStats error;
};
ResampleResult resampleWithError(const Lut3D& source, int size, Interpolation method,
                                 int nthreads = 0);

} // namespace lut
