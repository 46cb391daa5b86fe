// SPDX-License-Identifier: Apache-2.0
#include "interp/LatticeMapping.h"

#include "lut/Lut3D.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace lut::detail {

LatticeMapping makeLatticeMapping(const Lut3D& lut) {
    const float lo[3] = {lut.domainMin().x, lut.domainMin().y, lut.domainMin().z};
    const float hi[3] = {lut.domainMax().x, lut.domainMax().y, lut.domainMax().z};
    return makeLatticeMapping(lut.size(), lo, hi);
}

LatticeMapping makeLatticeMapping(int size, const float min[3], const float max[3]) {
    LatticeMapping m;
    m.size = size;
    for (int c = 0; c < 3; ++c) {
        const double lo = min[c], hi = max[c];
        double s = (m.size - 1) / (hi - lo);
        // Degenerate domain: keep the scale (and the snapping bias) finite in float.
        if (!(s <= FLT_MAX))
            s = FLT_MAX;
        m.scale[c] = static_cast<float>(s);
        m.offset[c] = static_cast<float>(lo);
        m.snapBias[c] =
            static_cast<float>(std::min(std::fabs(lo) * s, static_cast<double>(FLT_MAX) / 4));
    }
    return m;
}

void locateOnAxis(const float* axis, int n, float v, int& i, float& f) {
    if (!(v > axis[0])) { // also NaN
        i = 0;
        f = 0.0f;
        return;
    }
    if (v >= axis[n - 1]) {
        i = n - 2;
        f = 1.0f;
        return;
    }
    i = static_cast<int>(std::upper_bound(axis, axis + n, v) - axis) - 1;
    i = std::clamp(i, 0, n - 2);
    const float span = axis[i + 1] - axis[i];
    f = span > 0.0f ? std::clamp((v - axis[i]) / span, 0.0f, 1.0f) : 0.0f;
}

} // namespace lut::detail
