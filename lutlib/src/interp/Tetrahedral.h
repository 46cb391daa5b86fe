// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: the tetrahedral blend of one lattice cell, written once for any vector
// width and used by the scalar sampler, the AVX2 kernel and the round trip's PatchFunction.
//
// The cube is split into six tetrahedra by the order of the fractions (fr, fg, fb); each runs
//     c000 -> c000 + e(max axis) -> c111 - e(min axis) -> c111
// and shares the main diagonal c000-c111, so greys stay on it. The weights are differences of
// the sorted fractions, so a corner is returned exactly. Ties pick either tetrahedron; the tied
// vertex then has weight exactly 0.
//
// Free of glm and the standard library, like interp/LatticeMapping.h (the kernels include it).

namespace lut::detail {

template <class Ops> struct Tetrahedron {
    using F = typename Ops::Float;
    using M = typename Ops::Mask;
    // Weights of c000, of the max-axis vertex, of the c111-minus-min-axis vertex, of c111.
    F w0, w1, w2, w3;
    M rIsMax, gIsMax; // the axis with the largest fraction: r, else g, else b
    M bIsMin, gIsMin; // the axis with the smallest fraction: b, else g, else r
};

template <class Ops>
inline Tetrahedron<Ops> tetrahedron(typename Ops::Float fr, typename Ops::Float fg,
                                    typename Ops::Float fb) {
    Tetrahedron<Ops> t;
    t.rIsMax = Ops::maskAnd(Ops::greaterEqual(fr, fg), Ops::greaterEqual(fr, fb));
    t.gIsMax = Ops::maskAndNot(t.rIsMax, Ops::greaterEqual(fg, fb));
    t.bIsMin = Ops::maskAnd(Ops::lessEqual(fb, fr), Ops::lessEqual(fb, fg));
    t.gIsMin = Ops::maskAndNot(t.bIsMin, Ops::lessEqual(fg, fr));
    const auto fMax = Ops::max(fr, Ops::max(fg, fb));
    const auto fMin = Ops::min(fr, Ops::min(fg, fb));
    const auto fMid = Ops::max(Ops::min(fr, fg), Ops::min(Ops::max(fr, fg), fb));
    t.w0 = Ops::sub(Ops::splat(1.0f), fMax);
    t.w1 = Ops::sub(fMax, fMid);
    t.w2 = Ops::sub(fMid, fMin);
    t.w3 = fMin;
    return t;
}

} // namespace lut::detail
