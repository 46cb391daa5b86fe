// SPDX-License-Identifier: Apache-2.0
#pragma once
// What an OpenColorIO config makes OCIO do on lutkit's behalf, checked when the config is loaded
// (ColorConfig::load), before any processor is built:
//  - every file a FileTransform of the config names (colour spaces, looks, view and named
//    transforms), resolved as OCIO resolves it (search path, context), is held to the rules of a
//    file on the command line (checkOcioFile): a regular file, no FIFO or device even through a
//    symbolic link (OCIO would block on a FIFO, or read /dev/zero until memory runs out), at most
//    lut::limits::kMaxLutFileBytes, its content checked (checkOcioInput);
//  - colour spaces, looks, view and named transforms whose transforms refer to each other in a
//    cycle are refused naming the cycle: OCIO 2.1 follows the references without end (SIGSEGV,
//    its stack exhausted, in `lutkit bake`).
#include "ocio/OcioSession.h"

#include <string>

namespace lut::formats {

// Throws lut::Error "CONFIG: ..." naming the file, colour space or look at fault.
void checkOcioConfig(const OCIO::ConstConfigRcPtr& config, const std::string& configPath);

} // namespace lut::formats
