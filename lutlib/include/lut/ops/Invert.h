// SPDX-License-Identifier: Apache-2.0
#pragma once
// Inverting a LUT: a table that undoes it where it can be undone, and a report of where it
// cannot. Never NaN: NaN entries count as 0 and infinities as +-65504.
//
// 3D (Lut3D): for each lattice point y of the inverse, solve A(x) = y for x in A's domain, with A
// the tetrahedral interpolant (the same cells and tetrahedra as lut::Sampler). Newton steps on
// the piecewise-affine interpolant (exact inside a tetrahedron, so a few steps suffice), with a
// backtracking line search and x kept in the domain, tried from up to three starts: the solution
// of the previous point of the row, the per-channel inverse of A's neutral-axis curves, and the
// nearest of a coarse grid of A's outputs. Where none reaches the target (y outside A's gamut, or
// A flat there) a damped least-squares search (Levenberg-Marquardt, projected onto the domain)
// from the best point found gives the x whose A(x) is closest to y, and the point is reported as
// unreachable. A is one-to-one exactly when no tetrahedron of any cell is flat or folded
// (Jacobian determinant <= 0); such cells are counted too, since there the inverse is not unique.
//
// 1D (Lut1D), per channel: a monotone curve (increasing or decreasing) is inverted exactly
// (piecewise linear, as Lut1D interpolates); a non-monotone one through its running maximum (or
// minimum), so the answer is the first preimage; targets outside the curve's range get the end
// point and are reported unreachable.
#include "lut/ErrorStats.h"
#include "lut/Lut1D.h"
#include "lut/Lut3D.h"
#include "lut/ops/Regions.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <functional>
#include <vector>

namespace lut {

struct InvertOptions {
    int size = 0; // edge of the inverse (3D) or its entry count (1D); 0 = the source's
    // The inverse's domain: false = A's domain; true = the bounding box of A's entries, so every
    // output of A has an inverse entry (where that box is not degenerate).
    bool outputRangeDomain = false;
    double tolerance = 1e-5; // a target is reached when max |A(x) - y| over channels <= this
    int maxIterations = 40;  // per start
    int nthreads = 0;        // 0 = all cores
    // 3D: the target each lattice input p of the inverse stands for (a 1D shaper S before the
    // inverse: S^-1(p), lut/ops/InvertShaper.h); empty = p itself. When set, the report's
    // residual and roundTrip are left empty: they belong to the shaper and table together.
    std::function<glm::dvec3(glm::dvec3)> targetOf;
};

struct UnreachedPoint {
    glm::vec3 target{0.0f};   // y: the inverse's lattice input
    glm::vec3 solution{0.0f}; // x: the inverse's entry
    glm::vec3 reached{0.0f};  // A(x), as close to y as A gets
    double residual = 0.0;    // max |A(x) - y| over channels
};

struct InvertReport {
    std::size_t points = 0;      // lattice points (3D) or entries x channels (1D) solved
    std::size_t unreachable = 0; // of these, without an exact preimage (least-squares answer)
    RegionCounts unreachableByRegion{}; // where, by target colour (3D; tone band and hue)
    std::vector<UnreachedPoint> worst;  // up to 16, largest residual first
    std::size_t leastSquares = 0;       // points Newton could not solve from any start (3D)
    // 3D: cells of A with a flat or folded tetrahedron; 1D: segments (over all channels) that
    // are not strictly monotone in the curve's direction.
    std::size_t foldedCells = 0;
    double maxResidual = 0.0; // max |A(inverse entry) - target| over the lattice points
    double meanResidual = 0.0;
    // |A(inverse(y)) - y| over every y of the inverse's domain, between its lattice points too
    // (the inverse interpolated as it will be applied): maxAbs a bound (lut/ops/ErrorBound.h).
    ErrorStats residual;
    // |inverse(A(x)) - x| over every x of A's domain: how close compose(A, inverse) is to the
    // identity; maxAbs a bound as for residual.
    ErrorStats roundTrip;
    std::size_t sanitizedEntries = 0;
    double seconds = 0.0;

    bool invertible() const { return unreachable == 0 && foldedCells == 0; }
};

struct InvertResult {
    Lut3D lut;
    InvertReport report;
};
struct InvertResult1D {
    Lut1D lut;
    InvertReport report;
};

InvertResult invert(const Lut3D& a, const InvertOptions& options = {});
InvertResult1D invert(const Lut1D& a, const InvertOptions& options = {});

} // namespace lut
