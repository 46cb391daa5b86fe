// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Resize.h"

#include "lut/Error.h"
#include "lut/ops/Resample.h"
#include "ops/OpsDetail.h"

namespace lut {

OpResult resize(const Lut3D& lut, int size, Interpolation method, int nthreads) {
    if (lut.empty())
        throw Error("resize: the LUT has no entries");
    OpResult out;
    const Lut3D clean = detail::sanitizedCopy(lut, out.sanitizedEntries);
    ResampleResult r = resampleWithError(clean, size, method, nthreads);
    out.lut = std::move(r.lut);
    out.error = r.error;
    return out;
}

} // namespace lut
