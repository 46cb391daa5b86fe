// SPDX-License-Identifier: Apache-2.0
#pragma once
// What lut::formats::bake samples (lut/formats/Bake.h): the function, what it is called, the
// colour space its input is in (to choose a shaper) and an input range a source file has.
#include "lut/formats/Bake.h"
#include "ocio/OcioMeasure.h"

#include <optional>
#include <utility>

namespace lut::formats {

struct BakeSource {
    RgbFunction truth; // thread-safe
    std::string what;
    std::string configUsed;
    std::optional<ColorConfig> config; // config bakes and LUTs with conversions
    std::string inputSpace;            // resolved name ("" when not known)
    std::optional<ColorSpaceInfo> inputInfo;
    std::optional<std::pair<glm::vec3, glm::vec3>> ownRange; // a source file's input range
    bool shaped = false;   // ownRange is a 1D shaper's before a 3D table (not a table's own)
    bool crosstalk = true; // false: the function works on each channel alone
    // Where the truth kinks, per axis in input coordinates (a LUT file with no conversion before
    // it: its lattice planes, shaper entries and crossings; lut::fileBreaks); empty = unknown.
    std::optional<LutFile> kinksOf;
    Diagnostics diagnostics;
};

// Throws ColorOptionError when the options name no source or several, or unknown names;
// lut::Error for unreadable files. Refuses an output that is one of the inputs.
BakeSource makeBakeSource(const BakeOptions& options, const std::string& output);

} // namespace lut::formats
