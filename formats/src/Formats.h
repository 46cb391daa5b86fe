// SPDX-License-Identifier: Apache-2.0
#pragma once
// Factories of the built-in formats (internal to formats/). One per format file.
#include "lut/io/Format.h"

#include <memory>
#include <vector>

namespace lut::formats {
// .cube, Adobe and Resolve dialects (cube/CubeFormat.cpp).
std::unique_ptr<Format> makeCubeFormat();
// OpenColorIO bridge: one reader for every extension OCIO reads but .cube (OcioReader.cpp), and
// one writer per format OCIO's Baker bakes (OcioWriters.cpp). .spi3d, which OCIO reads but cannot
// bake, is read and written by lutkit (Spi3dFormat.cpp), registered before the OCIO reader.
std::unique_ptr<Format> makeOcioReadFormat();
std::vector<std::unique_ptr<Format>> makeOcioBakeFormats();
std::unique_ptr<Format> makeSpi3dFormat();

// LUT images in named layouts (StripFormat.cpp), Hald images (HaldFormat.cpp), nutexb volumes
// (NutexbFormat.cpp).
std::unique_ptr<Format> makeStripFormat();
std::unique_ptr<Format> makeHaldFormat();
std::unique_ptr<Format> makeNutexbFormat();

} // namespace lut::formats
