// SPDX-License-Identifier: Apache-2.0
#pragma once
// What an OpenColorIO processor holds, seen as lutkit's LutFile: a plain 3D table, a 1D shaper
// then a 3D table, or per-channel 1D tables, each over an input range (the domain) set by the
// scale-and-offset ops (Matrix, Range) in front of the table. When a file is exactly one of these
// shapes, reading it loses nothing: the lattice points hold exactly what OCIO computes there, and
// lutkit's interpolation between them is OCIO's (linear 1D, tetrahedral 3D). Anything else (CDLs,
// logs, several tables in a chain, a 1D table after the cube) is a chain that no single table holds
// exactly: the reader samples the whole processor and says what that cost.
#include "ocio/OcioSession.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace lut::formats {

struct OcioStructure {
    enum class Kind {
        Chain,      // anything else: sample the whole processor
        Cube,       // [scale/offset]* Lut3D [scale/offset]*
        ShaperCube, // [scale/offset]* Lut1D [scale/offset]* Lut3D [scale/offset]*
        Curves      // [scale/offset]* Lut1D [scale/offset]* (per channel)
    };
    Kind kind = Kind::Chain;
    glm::vec3 domainMin{0.0f}, domainMax{1.0f}; // the input range of the first table
    unsigned long length1d = 0;                 // the Lut1D's entries (ShaperCube, Curves)
    unsigned long gridSize = 0;                 // the Lut3D's edge (Cube, ShaperCube)
    // ShaperCube: the processor from the input to the cube's [0,1] coordinates (the shaper) and
    // the one from there to the output (the cube). Cube/Curves: `rest` is the whole processor.
    OCIO::ConstProcessorRcPtr shaper;
    OCIO::ConstProcessorRcPtr rest;
};

// Recognises the shapes above in processor's transforms (evaluating the scale-and-offset parts
// numerically, so bit-depth scalings and directions are what OCIO computes). The caller holds an
// OcioSession.
OcioStructure analyseProcessor(const OCIO::ConstConfigRcPtr& config,
                               const OCIO::ConstProcessorRcPtr& processor);

// Applies a CPU processor to `count` packed RGB float triplets in place, in parallel (OCIO's CPU
// processors may be used from several threads at once).
void applyRgb(const OCIO::ConstCPUProcessorRcPtr& cpu, float* rgb, std::size_t count,
              int nthreads = 0);

// The same for RGBA.
void applyRgba(const OCIO::ConstCPUProcessorRcPtr& cpu, float* rgba, std::size_t count);

} // namespace lut::formats
