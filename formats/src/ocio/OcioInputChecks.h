// SPDX-License-Identifier: Apache-2.0
#pragma once
// Files that would make OpenColorIO 2.1 (the version lutkit is built with) loop or allocate
// without end, refused before OCIO sees them. Each check names the defect it avoids and was found
// by fuzz_ocio (tests/fuzz/OcioFuzzTarget.h); the inputs are in tests/data/fuzz-regress/ocio/.
#include <string>

namespace lut::formats {

// Throws lut::ParseError naming the line when path (a file OCIO is about to read) holds a
// construct OCIO mishandles; returns otherwise. The files a CTF/CLF references
// (<Reference path="..."/>: OCIO opens them too) are checked in turn (checkOcioFile), and a
// reference back to a file on the way is refused as a cycle.
void checkOcioInput(const std::string& path);

// A file OpenColorIO opens on lutkit's behalf (a config's FileTransform, a file a CTF
// references), held to the rules of a file on the command line: a regular file (no FIFO or
// device, even through a symbolic link), at most lut::limits::kMaxLutFileBytes, then
// checkOcioInput. Throws lut::Error naming the file.
void checkOcioFile(const std::string& path);

} // namespace lut::formats
