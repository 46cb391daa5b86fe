#pragma once
// Internal to lutlib: the input -> lattice mapping every sampler (scalar and SIMD) shares.
#include "interp/simd/SimdKernels.h"
#include "lut/Lut3D.h"

#include <vector>

namespace lut::detail {

struct LatticeMap {
    explicit LatticeMap(const Lut3D& lut);
    // Lattice cell (idx in 0..N-2) and fractions in [0,1] for an input, per the policy in
    // Sampler.h: NaN and -Inf -> domain min, +Inf -> domain max, clamp to the domain, snap to a
    // lattice point within float rounding of it. Float arithmetic, operation for operation the
    // same as the SIMD kernels (simd/SamplerKernels_avx2.cpp), so both pick the same cells.
    void locate(glm::vec3 in, int idx[3], float frac[3]) const;
    int size;
    float scale[3];    // (N-1)/(max-min), computed in double and kept finite
    float offset[3];   // domain min
    float snapBias[3]; // |min| * scale
};

// The table as the kernels read it: RGB plus one float of padding per entry.
std::vector<float> packTable(const Lut3D& lut);

} // namespace lut::detail
