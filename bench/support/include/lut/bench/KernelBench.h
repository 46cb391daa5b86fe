// SPDX-License-Identifier: Apache-2.0
#pragma once
// What `lutkit bench` and bench/lutkit_bench measure: a smooth analytic grade, the LUTs sampled
// from it, a synthetic 4K-like frame, and the error and speed of a sampler on that frame.
// (OpenColorIO's side of the comparison lives with the callers: lutlib does not link OCIO.)
#include "lut/ErrorStats.h"
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"
#include "lut/interp/Sampler.h"

#include <functional>
#include <glm/vec3.hpp>

namespace lut {

// A smooth grade over [0,1]^3 that a LUT can only approximate: a filmic contrast curve per
// channel, a saturation boost around luminance that rolls off in the highlights, and a little
// channel crosstalk (a "warm" mix).
// Defined in float64 so the reference is not itself an interpolation.
glm::dvec3 analyticGrade(glm::dvec3 rgb);

// A LUT of edge `size` over [0,1] sampled from analyticGrade at its lattice points.
Lut3D sampleAnalyticGrade(int size);

// A deterministic synthetic frame in [0,1] that behaves like graded footage for a LUT kernel:
// a sky gradient, saturated objects, skin-like tones, near-white highlights and fine grain, so
// neighbouring pixels hit neighbouring LUT cells but not always the same one. Alpha = 1.
Image makeBenchFrame(int width, int height, int nthreads = 0);

// analyticGrade of every pixel of `frame` (alpha copied), computed once per frame.
Image analyticReference(const Image& frame, int nthreads = 0);

// Error of `graded` (the frame after a sampler) against `reference` over R, G, B.
ErrorStats frameError(const Image& graded, const Image& reference, int nthreads = 0);

// Copies `src` into `dst` (same size) on up to nthreads threads, split by rows: the memory
// bandwidth yardstick the kernels are compared with.
void parallelCopy(const Image& src, Image& dst, int nthreads = 0);

// Smallest wall time of `run` over `reps` runs (at least 1), calling `prepare` untimed first.
double bestSeconds(int reps, const std::function<void()>& prepare,
                   const std::function<void()>& run);

} // namespace lut
