// SPDX-License-Identifier: Apache-2.0
#pragma once
// Shared by the formats whose files imply a fixed [0,1] domain and store no shaper (LUT images,
// Hald, nutexb): turn any LutFile into a plain N^3 table over [0,1], saying what that cost.
#include "lut/ErrorStats.h"
#include "lut/LutFile.h"
#include "lut/formats/DisplayRange.h"

#include <cstddef>
#include <string>

namespace lut::formats {

// size 0 = keep the table's own size. Bakes a shaper, re-samples a non-default domain onto
// [0,1] (inputs outside it take the edge value) and resamples to `size` (tetrahedral), adding
// one diagnostic for each of those steps to diags.
// A file with a shaper: the shaper, then the table, evaluated exactly at the lattice over [0,1]
// (lut::sampleOnLattice), the error measured between lattice points said in the diagnostic and
// returned in shaperError when given.
Lut3D prepareUnitLut(const LutFile& file, int size, const std::string& path, Diagnostics& diags,
                     ErrorStats* shaperError = nullptr);

// Channel values outside [0,1] (NaN included): what an integer writer will clamp.
std::size_t countOutOfUnitRange(const Lut3D& lut);

// Adds "<count> channel values outside 0..1 were clamped" (warning) when count > 0.
void addClampDiagnostic(std::size_t count, int bits, const std::string& path, Diagnostics& diags);

// Adds "quantised to <bits> bits: <error>" (info) when rounding to nearest changes any in-range
// value (clamping is reported apart by addClampDiagnostic).
void addQuantizationDiagnostic(const Lut3D& lut, int bits, const std::string& path,
                               Diagnostics& diags);

Diagnostic makeDiagnostic(Diagnostic::Severity severity, const std::string& path,
                          std::string message);

} // namespace lut::formats
