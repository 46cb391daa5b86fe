// SPDX-License-Identifier: Apache-2.0
#pragma once
// The adjustment list: lut::Adjustments as readable text, so the editor can save what it did and
// `lutkit` can apply the same list to a LUT. One adjustment per line, a keyword then numbers:
//
//   # lutkit adjustment list 1
//   exposure 0.5
//   lift 0.01 0 -0.01                   per channel R G B (also gamma, gain)
//   lift.master 0.02                    (also gamma.master, gain.master)
//   curve.master 0,0 0.25,0.2 1,1       x,y control points (also curve.red/green/blue)
//   hue.sat 0,0.2 120,-0.5              hue in degrees,value (also hue.hue, hue.lum)
//   strength 0.8
//
// Keywords: exposure contrast saturation temperature tint lift lift.master gamma gamma.master
// gain gain.master curve.master curve.red curve.green curve.blue hue.hue hue.sat hue.lum
// strength (meanings and ranges in lut/ops/Adjust.h). '#' starts a comment; blank lines are
// ignored; a keyword may appear once; the order of the lines does not matter (the adjustments
// always run in Adjust.h's order). Numbers are decimal or scientific and must be finite.
//
// formatAdjustmentList writes only what differs from the defaults, in Adjust.h's order, each
// number in the shortest form that reads back to the same double, so
// parseAdjustmentList(formatAdjustmentList(a)) == a and applies bit for bit the same.
#include "lut/ops/Adjust.h"

#include <string>
#include <string_view>

namespace lut {

std::string formatAdjustmentList(const Adjustments& a);

// Throws lut::ParseError naming `path`, the line and column and the offending text.
Adjustments parseAdjustmentList(std::string_view text, const std::string& path = "<adjustments>");

} // namespace lut
