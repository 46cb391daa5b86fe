#pragma once
// Files that would make OpenColorIO 2.1 (the version lutkit is built with) loop or allocate
// without end, refused before OCIO sees them. Each check names the defect it avoids and was found
// by fuzz_ocio (tests/fuzz/OcioFuzzTarget.h); the inputs are in tests/data/fuzz-regress/ocio/.
#include <string>

namespace lut::formats {

// Throws lut::ParseError naming the line when path (a file OCIO is about to read) holds a
// construct OCIO mishandles; returns otherwise.
void checkOcioInput(const std::string& path);

} // namespace lut::formats
