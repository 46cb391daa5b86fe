#pragma once
// Factories of the built-in formats (internal to formats/). One per format file.
#include "lut/io/Format.h"

#include <memory>
#include <vector>

namespace lut::formats {
// .cube, Adobe and Resolve dialects (CubeFormat.cpp).
std::unique_ptr<Format> makeCubeFormat();
// OpenColorIO bridge (OcioFormat.cpp): one reader for every extension OCIO reads but .cube,
// and one writer per format OCIO's Baker bakes.
std::unique_ptr<Format> makeOcioReadFormat();
std::vector<std::unique_ptr<Format>> makeOcioBakeFormats();

// LUT images in named layouts (StripFormat.cpp), Hald images (HaldFormat.cpp), nutexb volumes
// (NutexbFormat.cpp).
std::unique_ptr<Format> makeStripFormat();
std::unique_ptr<Format> makeHaldFormat();
std::unique_ptr<Format> makeNutexbFormat();

} // namespace lut::formats
