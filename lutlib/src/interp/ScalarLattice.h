#pragma once
// Internal to lutlib: the scalar forms of the lattice mapping (interp/LatticeMapping.h) and the
// tetrahedral blend (interp/Tetrahedral.h), for the scalar samplers and the round trip's
// PatchFunction. Never included by the SIMD kernels (it uses glm and <cmath>).
#include "interp/LatticeMapping.h"
#include "interp/Tetrahedral.h"

#include <glm/vec3.hpp>

#include <cmath>

namespace lut::detail {

// One float per lane, for locateAxis and tetrahedron.
struct ScalarOps {
    using Float = float;
    using Int = int;
    using Mask = bool;
    static float splat(float v) { return v; }
    static float add(float a, float b) { return a + b; }
    static float sub(float a, float b) { return a - b; }
    static float mul(float a, float b) { return a * b; }
    static float abs(float a) { return std::fabs(a); }
    static float min(float a, float b) { return b < a ? b : a; }
    static float max(float a, float b) { return a > b ? a : b; }
    static float maxWithZero(float a) { return a > 0.0f ? a : 0.0f; } // NaN -> 0
    // Half up; t >= 0 here.
    static float roundNearest(float t) { return static_cast<float>(static_cast<int>(t + 0.5f)); }
    static bool lessEqual(float a, float b) { return a <= b; }
    static bool greaterEqual(float a, float b) { return a >= b; }
    static bool maskAnd(bool a, bool b) { return a && b; }
    static bool maskAndNot(bool a, bool b) { return !a && b; }
    static float select(bool m, float a, float b) { return m ? a : b; }
    static int truncate(float t) { return static_cast<int>(t); }
    static int minInt(int a, int b) { return b < a ? b : a; }
    static float toFloat(int i) { return static_cast<float>(i); }
};

// The cell (0..N-2) and fraction of an input, per channel.
inline void locate(const LatticeMapping& m, glm::vec3 in, int cell[3], float frac[3]) {
    const float top = static_cast<float>(m.size - 1);
    for (int c = 0; c < 3; ++c)
        locateAxis<ScalarOps>(in[c], m.offset[c], m.scale[c], m.snapBias[c], top, m.size - 2,
                              cell[c], frac[c]);
}

// The tetrahedral blend of the cell at (r, g, b) with fractions (fr, fg, fb); e(r, g, b) returns
// the entry at a lattice point.
template <class Entry>
glm::vec3 tetrahedralBlend(const Entry& e, int r, int g, int b, float fr, float fg, float fb) {
    const Tetrahedron<ScalarOps> t = tetrahedron<ScalarOps>(fr, fg, fb);
    const bool bIsMax = !t.rIsMax && !t.gIsMax, rIsMin = !t.bIsMin && !t.gIsMin;
    const glm::vec3 cMax = e(r + t.rIsMax, g + t.gIsMax, b + bIsMax);
    const glm::vec3 cMid = e(r + 1 - rIsMin, g + 1 - t.gIsMin, b + 1 - t.bIsMin);
    return t.w0 * e(r, g, b) + t.w1 * cMax + t.w2 * cMid + t.w3 * e(r + 1, g + 1, b + 1);
}

} // namespace lut::detail
