// SPDX-License-Identifier: Apache-2.0
#pragma once
// Undoes the PNG row filters (https://www.w3.org/TR/png/#9Filters) for the reader's fast path
// (PngCodec.cpp): None, Sub, Up, Average and Paeth on bytes, `bpp` bytes per pixel (1..8).
#include <cstddef>

namespace lut::formats {

// Row `filtered` (n bytes, without its filter byte) with filter `type` and the row above `up`
// (zeros for the first row) -> `out`. False for an unknown filter type.
bool unfilterRow(unsigned type, const unsigned char* filtered, const unsigned char* up,
                 unsigned char* out, std::size_t n, std::size_t bpp);

} // namespace lut::formats
