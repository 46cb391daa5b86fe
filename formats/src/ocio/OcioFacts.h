// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the OpenColorIO reader reports about a file besides its table: the tables and other ops
// in the processor, the bit depth the file stored, its title and comments.
#include "ocio/OcioSession.h"

#include <string>
#include <vector>

namespace lut::formats {

struct ProcessorFacts {
    unsigned long gridSize = 0; // largest 3D grid in the processor (0 = none)
    unsigned long length1d = 0; // longest 1D table (0 = none)
    bool halfDomain = false;    // a 1D table indexed by half floats (not a ramp over [0,1])
    int lut1dCount = 0;
    int lut3dCount = 0;
    int otherCount = 0;
    int bitDepth = 0;
    std::string title;
    std::vector<std::string> comments;

    // "1 1D LUT, 1 3D LUT, 7 other ops"
    std::string opsText() const;
};

ProcessorFacts inspectProcessor(const OCIO::ConstProcessorRcPtr& processor);

// The one CPU processor lutkit samples and measures OpenColorIO's files, chains and conversions
// with (convert's reader, bake, the colour conversions baked around a LUT): the processor as it
// stands, unoptimised (OPTIMIZATION_NONE, what OCIO_OPTIMIZATION_FLAGS=0 gives OCIO's own
// tools). OCIO 2.1's optimiser simplifies some chains wrongly -- a Gamma pair of opposite styles,
// CDL nodes in a CTF, inverse LUT pairs, up to 0.34 apart -- so convert and bake never differ by
// it. (The per-pixel conversions of apply and preview keep OCIO's default optimisation: speed.)
OCIO::ConstCPUProcessorRcPtr faithfulCpu(const OCIO::ConstProcessorRcPtr& processor);

} // namespace lut::formats
