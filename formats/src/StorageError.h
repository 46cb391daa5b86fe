// SPDX-License-Identifier: Apache-2.0
#pragma once
// What writing a LUT file and reading it back changed (lutkit convert's `storage` line): the
// table handed to the writer against what the file reads back as, a bound over every input.
#include "lut/ErrorStats.h"
#include "lut/LutFile.h"

namespace lut::formats {

// Both evaluated as files (the shaper, then the table, lut/interp/Sampler.h). maxAbs bounds the
// difference over every input of the written file's domain (bounded = true):
//   - one lattice and one shaper shape: the largest entry difference, plus the table's steepest
//     slope times the shaper's largest stored change;
//   - shapers of other lengths (a .csp prelut OpenColorIO reads as a smooth curve of 65536
//     entries) over one table: the shapers compared between every kink of either, each
//     difference times the table's steepest slope along that axis over the cells the two shaped
//     inputs span, plus the largest entry difference;
//   - otherwise lut::boundError on the two files.
// meanAbs is a mean over 65,536 pseudo-random inputs of the domain (sampledMax the largest seen).
ErrorStats storageError(const LutFile& written, const LutFile& back);

} // namespace lut::formats
