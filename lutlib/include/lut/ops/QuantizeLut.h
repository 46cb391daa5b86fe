// SPDX-License-Identifier: Apache-2.0
#pragma once
// Rounding a LUT's entries to what an 8-bit file stores, with the error it introduced.
#include "lut/ErrorStats.h"
#include "lut/Lut3D.h"

namespace lut {

// Rounds every entry to the nearest 8-bit step (clamped to [0,1], lut/Quantize.h) in place and
// reports the error and its cost (ErrorStats::seconds).
ErrorStats quantize8(Lut3D& lut);
// The table an 8-bit file holds (a .nutexb, an 8-bit strip): every entry rounded to nearest,
// clamped to [0,1] (lut/Quantize.h), as a copy.
Lut3D quantized8(Lut3D lut);

} // namespace lut
