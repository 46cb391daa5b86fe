// SPDX-License-Identifier: Apache-2.0
#pragma once
// Turning an OpenColorIO processor read from a file into a LutFile (OcioReader.cpp): exactly when
// the file is one of the shapes lut::formats::OcioStructure names, else by sampling the whole
// processor at the size asked for (default 33, or the file's largest 3D grid if larger) with the
// error that costs measured against the processor between the lattice points.
#include "lut/LutFile.h"
#include "ocio/OcioFacts.h"
#include "ocio/OcioStructure.h"

#include <string>

namespace lut::formats {

// The lattice edge used for a chain when none is asked for.
constexpr int kDefaultChainSize = 33;
// The 1D table length used for a per-channel chain (no channel crosstalk) when no size is asked.
constexpr int kDefaultCurveLength = 4096;

// Fills out.shaper / out.cube (and a diagnostic for every lossy step). size 0 = the file's own
// lattice where it has exactly one, else the defaults above.
void sampleProcessor(const std::string& path, const OCIO::ConstProcessorRcPtr& processor,
                     const OcioStructure& structure, const ProcessorFacts& facts, int size,
                     LutFile& out);

// NaN/Inf entries (some files map inputs to them) replaced by 0, with a warning.
void replaceNonFinite(const std::string& path, LutFile& file);

} // namespace lut::formats
