// SPDX-License-Identifier: Apache-2.0
#pragma once
// An error figure that bounds the truth: the difference between a function and its lattice
// approximation over the whole of a box, estimated on points the approximation did not use.
//
// A lattice stands for its function exactly at its points (or nearly) and interpolates between
// them, so its error peaks between the points, where nothing was fitted: at cell centres for a
// smooth function, next to a kink or a steep step anywhere in the cell. The figure is built as
//   1. the difference at held-out points: the centres of the boxes of a grid `perCell` times
//      finer than the lattice along each axis, its planes joined by `breaks` (where the functions
//      kink or jump: another lattice's planes), so no point lies on a lattice plane (where the
//      error vanishes);
//   2. plus, at each such point q, what the difference can add within q's box: along each axis
//      the steepest slope between neighbouring points (change / distance) over q's 3x3x3
//      neighbourhood, times half the box's width, summed over the axes. For a function that is
//      piecewise linear at the grid's scale (every LUT interpolant, and any smooth function) this
//      is the slope term of a Lipschitz bound; a kink inside a box is covered by the slope of the
//      pieces on either side, a step by its height. When the difference is constant inside each
//      box (nearest-neighbour lattices, every jump among the breaks) there is no slope term and
//      the maximum is exact;
// and maxAbs is the largest of |difference| + slope term over every point and channel, so it
// covers every input in the box, not only the points measured (docs/accuracy.md, with the tests
// that measure the truth on independent random inputs against it).
#include "lut/ErrorStats.h"
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace lut {

// exact(x) - approximate(x) at `count` points: in[i] -> diff[i], per channel. NaN in a channel
// skips that value (the exact function has none there), +-Inf is an infinite error. Called from
// several threads at once.
using DifferenceFn = std::function<void(const glm::dvec3* in, glm::dvec3* diff, std::size_t count)>;

struct BoundOptions {
    // The box, in the coordinates in which the approximation's lattice is uniform.
    glm::dvec3 lo{0.0}, hi{1.0};
    int cells = 1;         // lattice cells per axis (lattice size - 1)
    bool greyOnly = false; // one dimension: the points (t, t, t), t from lo.x to hi.x
    // More planes of the grid per axis, in the box's coordinates (those outside it are ignored).
    std::array<std::vector<double>, 3> breaks;
    bool constantBetweenBreaks = false; // the difference is constant inside each box
    // Held-out points per cell per axis; 0 = as many as `budget` points allow (at least 1).
    int perCell = 0;
    std::size_t budget = 300000; // points evaluated on the grid, about (3D: (cells * perCell)^3)
    int nthreads = 0;            // 0 = all cores
    // When given: |difference| at every grid point (3 per point, NaN where skipped), red fastest,
    // for statistics beyond the mean (the grid's points only, not the refinement's).
    std::vector<float>* values = nullptr;
};

// The bound described above: maxAbs bounds |exact - approximate| everywhere in the box
// (bounded = true), sampledMax is the largest difference seen, meanAbs the mean over the points
// (a midpoint rule, so the mean over the box), count the channel values compared.
ErrorStats boundError(const DifferenceFn& difference, const BoundOptions& options);

using Breaks = std::array<std::vector<double>, 3>;
// Where a lattice's interpolant kinks (its lattice planes; trilinear and tetrahedral) or jumps
// (halfway between them; nearest), per axis, in its domain's coordinates.
Breaks latticeBreaks(const Lut3D& lut, Interpolation method);
void addBreaks(Breaks& into, const Breaks& more);

// The usual case: `approx` (evaluated with `method`) against a function given at points of its
// domain, bounded over that domain; `exact` also kinks or jumps at `breaks`. exact(in, out, n)
// writes n values (float, as the samplers compute them).
using BatchFn = std::function<void(const glm::vec3* in, glm::vec3* out, std::size_t count)>;
ErrorStats boundLatticeError(const Lut3D& approx, Interpolation method, const BatchFn& exact,
                             const Breaks& breaks, int nthreads = 0);

} // namespace lut
