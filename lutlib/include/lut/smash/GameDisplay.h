// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the game displays, in double precision, for authoring game LUTs (the round trip's extract
// and its patch lattice, the Smash compensation of an edit, the measures): the smash room's one
// display model, public so the round trip reads it through this header. In lut::detail (the
// names are short and lutlib's own; match's working space has its own srgbDecodeExtended). Built on
// the pipeline's constants (lut/smash/SmashConstants.h, docs/specs/smash-pipeline.md sections 2 and
// 3), so the float pipeline and this model cannot drift apart. Kept in double because authoring
// runs it once per lattice point or sample and the checks compare against it.

namespace lut::detail {

// The piecewise sRGB curve on [0, 1]; NaN and values <= 0 give 0, values >= 1 give 1.
double srgbEncodeUnit(double linear);
double srgbDecodeUnit(double encoded);
// The same curve mirrored for negatives and continued (power segment) above 1; NaN -> 0.
double srgbEncodeExtended(double linear);
double srgbDecodeExtended(double encoded);
// Clamp to [0, 1], NaN -> 0.
double clampUnit(double v);

// What the game displays (display-encoded, clamped) for the gamma-space input s when its LUT
// returned lutOut at s: srgb(min(1, (((lutOut - s) * mix + s) * scale)^2.2)).
double gameShown(double lutOut, double s);
// The same from a table (within 1e-6, 0.0003 8-bit steps): for measuring over many inputs.
double gameShownTabulated(double lutOut, double s);
// The same without the display's clip at 1 (srgbEncodeExtended above 1).
double gameShownUnclipped(double lutOut, double s);
// d gameShown / d lutOut (0 where the display clips or the brightened value is <= 0).
double gameShownSlope(double lutOut, double s);
// The LUT output that makes the game display `display` (display-encoded, may leave [0,1]) for the
// input s: the inverse of gameShownUnclipped in lutOut,
//     L = (srgbDecode(display)^(1/2.2) / scale - s) / mix + s.
double lutForShown(double display, double s);

// The display value the unedited game shows for its lattice input i/15 with a neutral LUT:
// brighten (x1.3703 in gamma space), decode with 2.2, clip, encode with the sRGB curve. Inputs
// i >= 11 all clip to white.
double gameDisplayLatticeValue(int index);

} // namespace lut::detail
