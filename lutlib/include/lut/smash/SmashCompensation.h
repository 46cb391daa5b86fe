// SPDX-License-Identifier: Apache-2.0
#pragma once
// The LUT that cancels Smash Ultimate's brighten step (docs/specs/smash-pipeline.md section 2 and
// "The Smush compensation"): the game grades with r = ((L(s) - s) * 0.99961 + s) * 1.3703 in
// gamma space, so a LUT shipped as is shows about 2x brighter in linear light.
// smashWithoutBrighten solves the brighten step for L per lattice point (smashBrightenInverse)
// for the preview: the LUT that makes the unchanged grading pass show a LUT with no brighten
// step (the editor's Brighten toggle, gui/model/PreviewRenderer). The game LUT that ships an edit
// is authored by lut/smash/SmashAuthoring.h (authorSmashLutForEdit).
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"

namespace lut {

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
