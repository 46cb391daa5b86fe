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

} // namespace lut::formats
