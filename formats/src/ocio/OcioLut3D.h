// SPDX-License-Identifier: Apache-2.0
#pragma once
// A lutkit table as OpenColorIO's Lut3DTransform, in one place: how the writers hand a table to
// OpenColorIO (OcioWriters.cpp) and how the benchmarks' peer runs one (bench/support's
// OcioLutProcessor, through lutkit::formats_internal). Test oracles build their own on purpose.
#include "lut/Lut3D.h"

#include <OpenColorIO/OpenColorIO.h>

namespace lut::formats {

// setValue with the red, green and blue lattice indices explicitly: no storage order to agree
// on. The table's domain is not part of a Lut3DTransform (callers add a range fit).
OCIO_NAMESPACE::Lut3DTransformRcPtr makeLut3DTransform(const Lut3D& lut,
                                                       OCIO_NAMESPACE::Interpolation interp);

} // namespace lut::formats
