// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: the scalar forms of the lattice mapping (interp/LatticeMapping.h) and the
// tetrahedral blend (interp/Tetrahedral.h), for the scalar samplers and the round trip's
// PatchFunction. Never included by the SIMD kernels (it uses glm and <cmath>).
#include "interp/LatticeMapping.h"
#include "interp/Tetrahedral.h"

#include <glm/vec3.hpp>

#include <cmath>

namespace lut::detail {

// One value per lane, for locateAxis and tetrahedron: float for the samplers, double for the
// solvers in ops/.
template <class T> struct BasicScalarOps {
    using Float = T;
    using Int = int;
    using Mask = bool;
    static T splat(float v) { return v; }
    static T add(T a, T b) { return a + b; }
    static T sub(T a, T b) { return a - b; }
    static T mul(T a, T b) { return a * b; }
    static T abs(T a) { return std::fabs(a); }
    static T min(T a, T b) { return b < a ? b : a; }
    static T max(T a, T b) { return a > b ? a : b; }
    static T maxWithZero(T a) { return a > T(0) ? a : T(0); } // NaN -> 0
    // Half up; t >= 0 here.
    static T roundNearest(T t) { return static_cast<T>(static_cast<int>(t + T(0.5))); }
    static bool lessEqual(T a, T b) { return a <= b; }
    static bool greaterEqual(T a, T b) { return a >= b; }
    static bool maskAnd(bool a, bool b) { return a && b; }
    static bool maskAndNot(bool a, bool b) { return !a && b; }
    static T select(bool m, T a, T b) { return m ? a : b; }
    static int truncate(T t) { return static_cast<int>(t); }
    static int minInt(int a, int b) { return b < a ? b : a; }
    static T toFloat(int i) { return static_cast<T>(i); }
};
using ScalarOps = BasicScalarOps<float>;

// The cell (0..N-2) and fraction of an input, per channel.
inline void locate(const LatticeMapping& m, glm::vec3 in, int cell[3], float frac[3]) {
    const float top = static_cast<float>(m.size - 1);
    for (int c = 0; c < 3; ++c)
        locateAxis<ScalarOps>(in[c], m.offset[c], m.scale[c], m.snapBias[c], top, m.size - 2,
                              cell[c], frac[c]);
}

// The lattice mapping in double without the snapping, for solvers that need the map continuous
// (ops/Invert): the same cells and clamping as locateAxis otherwise. `clamped` says the input
// was outside the open domain (t not in (0, N-1)): the map is flat along that channel there.
inline void locateContinuous(double x, double offset, double scale, int size, int& cell,
                             double& frac, bool& clamped) {
    double t = std::isnan(x) ? 0.0 : (x - offset) * scale;
    clamped = !(t > 0.0 && t < size - 1);
    t = t > 0.0 ? (t < size - 1 ? t : static_cast<double>(size - 1)) : 0.0;
    cell = static_cast<int>(t) < size - 2 ? static_cast<int>(t) : size - 2;
    frac = t - cell;
}

// The axes of a tetrahedron in the order its path c000 -> c111 steps along them: the one with
// the largest fraction first (0 = r, 1 = g, 2 = b).
struct TetrahedronAxes {
    int max, mid, min;
};
template <class T> TetrahedronAxes axesOf(const Tetrahedron<BasicScalarOps<T>>& t) {
    const int max = t.rIsMax ? 0 : t.gIsMax ? 1 : 2;
    const int min = t.bIsMin ? 2 : t.gIsMin ? 1 : 0;
    return {max, 3 - max - min, min};
}

// The tetrahedral blend of the cell at (r, g, b) with fractions (fr, fg, fb); e(r, g, b) returns
// the entry at a lattice point.
template <class Entry>
glm::vec3 tetrahedralBlend(const Entry& e, int r, int g, int b, float fr, float fg, float fb) {
    const Tetrahedron<ScalarOps> t = tetrahedron<ScalarOps>(fr, fg, fb);
    const TetrahedronAxes axes = axesOf(t);
    int a[3] = {r, g, b};             // c000 + the max axis
    int c[3] = {r + 1, g + 1, b + 1}; // c111 - the min axis
    ++a[axes.max];
    --c[axes.min];
    return t.w0 * e(r, g, b) + t.w1 * e(a[0], a[1], a[2]) + t.w2 * e(c[0], c[1], c[2]) +
           t.w3 * e(r + 1, g + 1, b + 1);
}

} // namespace lut::detail
