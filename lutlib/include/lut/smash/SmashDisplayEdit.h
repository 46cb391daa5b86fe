// SPDX-License-Identifier: Apache-2.0
#pragma once
// The Smash Ultimate LUT for an edit made on the game's picture: what the editor's Smash export
// writes (gui/model/ExportTarget). The edit is a LUT on display colours, the colours a screenshot
// holds (piecewise sRGB), as a modder grades a screenshot; the game LUT is the one whose picture
// is that edit of the picture the game showed with `gameLut` (neutral when null):
//
//   for every lattice input s = (i/15, j/15, k/15) of the 16^3 game LUT, in double precision:
//     r  = ((G(s) - s) * 0.99961 + s) * 1.3703      the game's grading + brighten with G = gameLut
//     d  = srgbEncode(min(1, r^2.2))                 the display colour it shows (clipped: what a
//                                                    screenshot holds; every s > 0.73 of the
//                                                    neutral game shows white)
//     d' = clamp(edit(d))                            the edit (sampled with editInterpolation)
//     L  = ((srgbDecode(d')^(1/2.2)) / 1.3703 - s) / 0.99961 + s     smashBrightenInverse
//     and where d' is white, L = max(L, G(s))        every entry from L up shows white: G's own
//                                                    when it does (the one rule above white,
//                                                    lut/smash/SmashAuthoring.h)
//
// so the game shows edit(d) at every lattice point (docs/specs/smash-pipeline.md, "The Smush
// compensation", composed with the game's own picture). A neutral edit gives gameLut back (the
// identity for a neutral game LUT) up to float rounding. Between lattice points the game
// interpolates L trilinearly, which is not the composition evaluated there; the preview shows the
// truth because it runs the game's pass with L itself. Entries are not clamped: values the game
// cannot reach stay outside [0,1] so callers can count them (lut/ops/Clipping.h); the nutexb
// writer clamps and rounds.
//
// This is lut/smash/SmashAuthoring.h's exact composition (authorSmashLutForEdit), what the round
// trip, `convert --target smash` and the editor ship; use authorSmashLutForEdit directly for the
// refinement and the error report. It differs from smashGameLut (lut/smash/SmashCompensation.h),
// which treats the edit as the whole gamma-space picture without the game's brighten step.
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"

namespace lut {

Lut3D smashLutForDisplayEdit(const Lut3D& edit, const Lut3D* gameLut = nullptr,
                             Interpolation editInterpolation = Interpolation::Trilinear);

} // namespace lut
