// SPDX-License-Identifier: Apache-2.0
#pragma once
// Resizing a LUT with the error reported: lut::resampleWithError (lut/ops/Resample.h) on a copy
// whose NaN entries count as 0 and infinities as +-65504, so the result and its error are finite
// (a NaN entry would otherwise spread to every interpolated neighbour).
#include "lut/interp/Interpolation.h"
#include "lut/ops/OpResult.h"

namespace lut {

// error: a bound of |source - result| over every input, as lut::resampleWithError reports it.
OpResult resize(const Lut3D& lut, int size, Interpolation method = Interpolation::Tetrahedral,
                int nthreads = 0);

} // namespace lut
