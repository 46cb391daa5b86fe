// SPDX-License-Identifier: Apache-2.0
#pragma once
// Cinespace .csp written by hand when the table has a shaper or an input range other than [0,1]
// (OcioWriters.cpp uses OCIO's Baker otherwise). The .csp prelut is a per-channel list of input
// points and output values; OpenColorIO reads it as a smooth (cubic Hermite) curve through those
// points, resampled to 65536 entries: a straight shaper (an input range) comes back exactly, and
// a curved one is written with its segments cut into straight pieces (4096 points at least) so the
// cubic stays close to them (lutkit convert measures what is left when it reads the file back).
#include "lut/LutFile.h"

#include <string>

namespace lut::formats {

// The file's text. size 0 = the cube's own size; otherwise the cube is resampled (tetrahedral,
// reported in diags). `path` names the file in messages.
std::string cspWithShaperBytes(const std::string& path, const LutFile& file, int size,
                               Diagnostics& diags);

} // namespace lut::formats
