// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: input -> lattice cell + fraction, the one definition every 3D LUT
// evaluation uses: the scalar samplers (interp/ScalarLattice.h), the SIMD kernels
// (simd/SamplerKernels_avx2.cpp) and the round trip's PatchFunction.
//
// The policy (the user-facing statement is in lut/interp/Sampler.h), per channel:
//     t = (x - domainMin) * (N - 1) / (domainMax - domainMin)
//     NaN and -Inf -> 0 (domainMin), +Inf -> N - 1 (domainMax), clamp to [0, N - 1]
//     a t within float rounding of a lattice point is moved onto it (kSnapRelative)
//     cell = min(floor(t), N - 2), fraction = t - cell
// so domainMax is cell N-2 at fraction 1, and a lattice input returns its entry exactly.
//
// Deliberately free of glm and of the standard library's inline templates, like
// simd/SimdKernels.h: the kernels include it under -mavx2.

namespace lut {
class Lut3D;
}

namespace lut::detail {

// Inputs whose lattice coordinate t is within (t + snapBias) * kSnapRelative of an integer are
// moved onto it: that bound covers the float rounding of a lattice input and of (x - min) * scale,
// so lattice points given as floats return their entries exactly.
constexpr float kSnapRelative = 1.0f / 4194304.0f; // 2^-22

// The per-LUT constants of the mapping, plain data so the kernels can read them.
struct LatticeMapping {
    int size = 0;           // N
    float scale[3] = {};    // (N-1) / (max - min), computed in double and kept finite
    float offset[3] = {};   // domain min
    float snapBias[3] = {}; // |min| * scale: the domain's share of the snapping tolerance
};
LatticeMapping makeLatticeMapping(const Lut3D& lut);
// The same for N points over [min, max] per channel (a 1D shaper's axis).
LatticeMapping makeLatticeMapping(int size, const float min[3], const float max[3]);

// One channel of the mapping, written once for any vector width. `Ops` supplies the lane types
// (Float, Int) and the operations: ScalarOps in interp/ScalarLattice.h, the AVX2 ones in
// simd/SamplerKernels_avx2.cpp. roundNearest may break ties either way: a tie (|t - r| = 0.5)
// is far outside the snapping tolerance, so it never changes t.
template <class Ops>
inline void locateAxis(typename Ops::Float x, typename Ops::Float offset, typename Ops::Float scale,
                       typename Ops::Float snapBias, typename Ops::Float top,
                       typename Ops::Int maxCell, typename Ops::Int& cell,
                       typename Ops::Float& frac) {
    using F = typename Ops::Float;
    F t = Ops::mul(Ops::sub(x, offset), scale);
    t = Ops::maxWithZero(t); // NaN and -Inf land on 0
    t = Ops::min(t, top);    // +Inf on the top
    const F r = Ops::roundNearest(t);
    const F tolerance = Ops::mul(Ops::add(t, snapBias), Ops::splat(kSnapRelative));
    t = Ops::select(Ops::lessEqual(Ops::abs(Ops::sub(t, r)), tolerance), r, t);
    cell = Ops::minInt(Ops::truncate(t), maxCell);
    frac = Ops::sub(t, Ops::toFloat(cell));
}

// The same policy on a rectilinear axis (strictly increasing values, n >= 2), for lattices
// that are not evenly spaced (the round trip's patch): NaN and values <= axis[0] -> cell 0,
// fraction 0; values >= axis[n-1] -> cell n-2, fraction 1.
void locateOnAxis(const float* axis, int n, float x, int& cell, float& frac);

} // namespace lut::detail
