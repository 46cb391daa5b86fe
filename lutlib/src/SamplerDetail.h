#pragma once
// Internal to lutlib: the input -> lattice mapping every sampler (scalar and SIMD) shares.
#include "lut/Lut3D.h"

namespace lut::detail {

struct LatticeMap {
    explicit LatticeMap(const Lut3D& lut);
    // Lattice cell (idx in 0..N-2) and fractions in [0,1] for an input, per the policy in
    // Sampler.h: NaN and -Inf -> domain min, +Inf -> domain max, clamp to the domain.
    void locate(glm::vec3 in, int idx[3], float frac[3]) const;
    int size;
    double scale[3];
    double offset[3];
};

} // namespace lut::detail
