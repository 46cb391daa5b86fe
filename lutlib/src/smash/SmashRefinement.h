// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: the least-squares refinement of a game LUT (lut/smash/SmashAuthoring.h)
// over the colours of GameSamples.h.
#include "lut/Lut3D.h"
#include "smash/GameSamples.h"

namespace lut::detail {

// The least-squares refinement (SmashAuthoring.h): per channel, the entries minimising the squared
// display error over the samples, started from `exact` (clamped), weighted by the display's slope
// at the wanted colour, one-sided where the wanted colour is black or white (anything darker than
// black or brighter than white shows the same), a tiny ridge towards `exact` for entries no sample
// constrains; then rounded to 8-bit values by a coordinate search on the true display error.
// Returns entries that are multiples of 1/255 in [0,1].
Lut3D refineSmashLut(const GameSamples& samples, const Lut3D& exact, int nthreads);

} // namespace lut::detail
