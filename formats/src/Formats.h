#pragma once
// Factories of the built-in formats (internal to formats/). One per format file.
#include "lut/Format.h"

#include <memory>

namespace lut::formats {
// .cube, Adobe and Resolve dialects (CubeFormat.cpp).
std::unique_ptr<Format> makeCubeFormat();

// LUT images in named layouts (StripFormat.cpp), Hald images (HaldFormat.cpp), nutexb volumes
// (NutexbFormat.cpp).
std::unique_ptr<Format> makeStripFormat();
std::unique_ptr<Format> makeHaldFormat();
std::unique_ptr<Format> makeNutexbFormat();

} // namespace lut::formats
