// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a LUT operation (compose, mix, smooth; lut/ops/Compose.h, Smooth.h) returns: the LUT and
// the error it introduced, measured as each function documents.
#include "lut/ErrorStats.h"
#include "lut/Lut3D.h"

#include <cstddef>

namespace lut {

struct OpResult {
    Lut3D lut;
    ErrorStats error;                 // error.seconds = the time the operation took
    std::size_t sanitizedEntries = 0; // input entries that were NaN/Inf or beyond +-65504
};

} // namespace lut
