// SPDX-License-Identifier: Apache-2.0
#pragma once
// How well a LUT file (a shaper, then a 3D table) interpolates: the figures `lutkit match`
// reports for the LUT it wrote. Measured on a grid of `grid`^3 points uniform in the working
// encoding (lut/match/WorkingSpace.h) over the domain, outputs compared in the working encoding,
// the file evaluated as `apply` evaluates it (the shaper, then the table with `interp`):
//   own-axis monotonicity  each output channel along its own input axis (red out along red in
//                          ...): the steps where it goes down, the smallest and largest slope;
//                          a slope near 0 crushes levels together (banding), a large one
//                          stretches them apart;
//   grey axis              every output channel along (t, t, t), 256 steps: monotone or not,
//                          and by how much it goes down where it does (from its running
//                          maximum, 8-bit steps);
//   fold-overs             grid cells whose Jacobian (finite differences over the cell's corners)
//                          has a determinant <= 0: colours the LUT folds onto each other;
//   smoothness             the largest second difference along any axis, in 8-bit steps (1/255
//                          of the working encoding).
#include "lut/LutFile.h"
#include "lut/interp/Interpolation.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <memory>
#include <string>

namespace lut {

struct LutQuality {
    int grid = 0;
    std::size_t steps = 0;           // own-axis steps checked
    std::size_t decreasingSteps = 0; // ... where the output went down by more than 1e-6
    double smallestSlope = 0.0;      // own-axis slope (output per input, working units)
    double largestSlope = 0.0;
    bool monotoneAlongGrey = true;
    double smallestGreySlope = 0.0; // the smallest channel slope along the grey axis
    double largestGreyDrop = 0.0;   // the most a channel goes down along grey, 8-bit steps
    std::size_t cells = 0;
    std::size_t foldedCells = 0;          // turned over (the Jacobian's determinant below 0)
    std::size_t flatCells = 0;            // flat to round-off: colours merged, not turned over
    double largestSecondDifference = 0.0; // 8-bit steps
    // "monotone along each channel's axis (slopes 0.42..2.1) and along grey; no fold-overs;
    //  largest second difference 1.3 8-bit steps"
    std::string str() const;
};

LutQuality measureLutQuality(const LutFile& lut, bool linear, const glm::dvec3& domainMin,
                             const glm::dvec3& domainMax,
                             Interpolation interp = Interpolation::Tetrahedral, int grid = 33);

// A LUT file as a function: the shaper (when present), then the table (when present) with
// `interp`. For measuring what `apply` will do with it.
class LutFileSampler {
public:
    explicit LutFileSampler(const LutFile& lut, Interpolation interp = Interpolation::Tetrahedral);
    ~LutFileSampler();
    LutFileSampler(LutFileSampler&&) noexcept;
    glm::vec3 operator()(glm::vec3 in) const;
    // In place on RGBA pixels (alpha untouched), on the calling thread.
    void applyPixels(float* rgba, std::size_t count) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace lut
