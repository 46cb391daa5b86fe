// SPDX-License-Identifier: Apache-2.0
#pragma once
// LUTs that cancel Smash Ultimate's brighten step (docs/specs/smash-pipeline.md section 2 and
// "The Smush compensation"): the game grades with r = ((L(s) - s) * 0.99961 + s) * 1.3703 in
// gamma space, so a LUT shipped as edited shows about 2x brighter in linear light. Both functions
// below solve the brighten step for L per lattice point (smashBrightenInverse); they differ in
// what they start from and what they are for:
//   smashGameLut          authoring: the 16^3 LUT to ship so the game shows an edited look
//                         (the editor's export with game compensation; `convert --target smash`);
//   smashWithoutBrighten  preview: the LUT that makes the unchanged grading pass show a LUT with
//                         no brighten step (the editor's Brighten toggle).
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"

namespace lut {

// `edited` maps a gamma-space input s to the gamma-space colour the modder wants on screen (any
// size, domain [0,1]). Returns the kSmashLutSize^3 LUT L with
//     GetPostProcessingResult(pow(s, 2.2)) == pow(edited(s), 2.2)
// at every lattice input s = i/15, where edited(s) is `edited` sampled with `editInterpolation`
// (the lattice of a 33^3 edit does not hold the points i/15). Entries are not clamped: values
// the game cannot reach stay outside [0,1] so callers can report them (the writer quantises).
// Between lattice points the game interpolates L trilinearly, which is not the compensation of
// the edit evaluated there.
Lut3D smashGameLut(const Lut3D& edited, Interpolation editInterpolation = Interpolation::Trilinear);

// The LUT L' (same size and domain as `lut`) with smashBrighten(L'(s), s) == L(s) at every
// lattice point: the Smash grading pass run with L' shows L with no brighten step, i.e.
// pow(L(s), 2.2) for s = pow(x, 0.454545) in [0,1]. Between lattice points:
//   trilinear, tetrahedral  exact (up to float rounding): L' is affine in (L, s) and both
//                           interpolations reproduce affine functions;
//   nearest                 the pass sees L(s_n) + 1.3703 * (1 - 0.99961) * (s - s_n) with s_n the
//                           nearest lattice input: off by at most smashWithoutBrightenError
//                           (1.8e-5 in gamma space for 16^3, a 200th of an 8-bit step).
// Above 1 the sampler clamps s while the brighten step keeps 0.039% of it, as the game's does.
Lut3D smashWithoutBrighten(const Lut3D& lut);
// The largest gamma-space difference between what the grading pass shows with
// smashWithoutBrighten(lut) and lut itself, for inputs in the LUT's domain: 0 for trilinear and
// tetrahedral, 1.3703 * 0.00039 * half the largest lattice step for nearest.
double smashWithoutBrightenError(const Lut3D& lut, Interpolation method);

} // namespace lut
