// SPDX-License-Identifier: Apache-2.0
#pragma once
// What Smash Ultimate shows with a game LUT, as an edit of the picture the neutral game shows:
// the LUT on display colours d (what a screenshot holds, piecewise sRGB) whose entry at d is the
// colour the game shows with `gameLut` for the LUT input s at which the neutral game shows d:
//
//     s_c = the input for which the neutral game shows d_c (per channel; s <= 1/1.3703, where
//           the neutral game reaches white)
//     entry(d) = smashShownColour(s, gameLut)      (lut/smash/SmashAuthoring.h: the game's
//                                                   grading + brighten + display, clipped)
//
// The inverse view of the exact composition (authorSmashLutForEdit, lut/smash/SmashAuthoring.h):
// a game LUT made from an edit shows that edit here, to the authoring error. This is how a .nutexb
// is judged by the look it gives (lutkit check, the quiet check after writing one): the table's own
// numbers are compensated for the brighten pass (compressed under 0.73 and clipped there).
#include "lut/Lut3D.h"

namespace lut {

Lut3D smashShownEdit(const Lut3D& gameLut, int size = 33);

} // namespace lut
