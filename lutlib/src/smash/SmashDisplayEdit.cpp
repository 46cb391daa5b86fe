// SPDX-License-Identifier: Apache-2.0
// The editor's Smash LUT for a display edit: the exact composition of lut/smash/SmashAuthoring.h
// (its one rule above white); see lut/smash/SmashDisplayEdit.h.
#include "lut/smash/SmashDisplayEdit.h"

#include "lut/smash/SmashAuthoring.h"

namespace lut {

Lut3D smashLutForDisplayEdit(const Lut3D& edit, const Lut3D* gameLut,
                             Interpolation editInterpolation) {
    SmashAuthoringOptions o;
    o.gameLut = gameLut;
    o.measure = false;
    return authorSmashLutForEdit(edit, editInterpolation, o).exact;
}

} // namespace lut
