// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib's LUT maths (ops/): the pieces diff, compose, smooth, invert and plot share.
#include "lut/ErrorStats.h"
#include "lut/Limits.h"
#include "lut/Lut3D.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <functional>
#include <vector>

namespace lut::detail {

// NaN -> 0, +-Inf and |v| > limits::kMaxColorValue (the largest half float, lut/Limits.h) -> +-it.
// Beyond it pow() and cbrt() in the colour maths would overflow.
inline float sanitizeValue(float v) {
    if (v != v)
        return 0.0f;
    constexpr float m = limits::kMaxColorValue;
    return v < -m ? -m : v > m ? m : v;
}

// A copy of `lut` with every entry sanitized; `replaced` counts the entries that changed.
Lut3D sanitizedCopy(const Lut3D& lut, std::size_t& replaced);

// The tetrahedral interpolant of a LUT in double precision, with its Jacobian: the same cells,
// tetrahedra and clamp-to-domain as lut::Sampler (lut/interp/Sampler.h), so a solution found here
// is a solution for the sampler to float rounding. The table must be finite (sanitize first).
class TetraEval {
public:
    explicit TetraEval(const Lut3D& lut);
    // Value at `in` (clamped to the domain). `jacobian`, when given, receives d(out)/d(in) of the
    // tetrahedron `in` lies in (columns = input channels), zero along clamped channels.
    glm::dvec3 operator()(glm::dvec3 in, glm::dmat3* jacobian = nullptr) const;
    glm::dvec3 domainMin() const { return m_lo; }
    glm::dvec3 domainMax() const { return m_hi; }
    const Lut3D& lut() const { return *m_lut; }

private:
    const Lut3D* m_lut;
    int m_n;
    glm::dvec3 m_lo, m_hi, m_scale;
};

// Probe points for an operation's mean change: `probes` points per axis spanning [lo, hi]
// (both ends included). A grid of 2(N-1)+1 points per axis hits every lattice point and every cell
// centre of an N lattice, where interpolation errors peak; above 129 points per axis a grid of
// about 128 whose spacing is coprime with the lattice's, so probes sample the cells' insides.
int probeCount(int latticeSize);

// The inverse of the piecewise-linear curve through (xs[i], ys[i]) (xs increasing) at y. The
// curve's direction is that of its end points; y is looked up on its running maximum (running
// minimum when decreasing), so the answer is an exact first preimage wherever the curve reaches
// y after its first entry; values it reaches only by dipping back before the first entry are
// found by a scan. Unreached y gives the x of the closest value (reached = false).
struct CurveInverse {
    double x = 0.0;
    bool reached = false;
};
class PiecewiseLinearInverse {
public:
    PiecewiseLinearInverse(std::vector<double> xs, std::vector<double> ys);
    CurveInverse operator()(double y) const;
    // Segments that are not strictly monotone in the curve's direction.
    std::size_t nonMonotoneSegments() const { return m_nonMonotone; }

private:
    std::vector<double> m_x, m_s, m_max; // m_s = direction * ys, m_max its running maximum
    double m_dir = 1.0;
    std::size_t m_argMin = 0, m_argMax = 0, m_nonMonotone = 0;
};

// Seconds since `start` (a steady_clock time point stored as nanoseconds).
double secondsSince(long long startNanos);
long long nowNanos();

} // namespace lut::detail
