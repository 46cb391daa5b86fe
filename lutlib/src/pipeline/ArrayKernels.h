// SPDX-License-Identifier: Apache-2.0
#pragma once
// Flat-array forms of the pipeline's per-pixel math, with an AVX2 + FMA path chosen at run time.
// The AVX2 path performs the same IEEE operations in the same order as the scalar functions of
// FastMath.h (every multiply-add is an explicit fma on both sides, and lutlib is built with
// -ffp-contract=off), so both give bit-identical results: the path never changes a frame.
#include "core/FastMath.h"

#include <cstddef>

namespace lut::detail {

// out[i] = powFast(in[i], p); in == out allowed.
void powArray(float p, const float* in, float* out, std::size_t n);
// out[i] = srgbEncodeFast(in[i]) (finite input); in == out allowed.
void srgbEncodeArray(const float* in, float* out, std::size_t n);

// The Smash grading pass (docs/specs/smash-pipeline.md section 2) on `count` RGBA pixels, in two
// halves around the LUT lookup, so any sampler can do the lookup in between:
//   smashEncodePixels: s = (x^0.454545 per channel, x.alpha), written to both s and l (the caller
//                      then runs the sampler on l in place);
//   smashFinishPixels: r = ((l - s) * 0.99961 + s) * 1.3703 per channel, then with
//                      a = clamp(alpha, 0, 1): a <= 0 leaves x, a >= 1 gives r^2.2, else
//                      x (1 - a) + r^2.2 a; fusedDisplay also applies the sRGB encode (a >= 1
//                      through smashDisplayFast in one power). Alpha is kept. x is rewritten.
// x must be sanitized (finite). x, s and l hold 4 * count floats.
void smashEncodePixels(const float* x, float* s, float* l, std::size_t count);
void smashFinishPixels(float* x, const float* s, const float* l, std::size_t count,
                       bool fusedDisplay);

// Adds a bloom row to `width` RGBA pixels: pixel k gets row4[4 i0[k] ..] + (row4[4 i1[k] ..] -
// row4[4 i0[k] ..]) * t[k] (row4 holds RGB0 texels), skipping exact zeros so that adding nothing
// leaves the bits alone.
void addBloomRow(float* rgba, int width, const float* row4, const int* i0, const int* i1,
                 const float* t);

const char* arrayKernelIsa();

} // namespace lut::detail
