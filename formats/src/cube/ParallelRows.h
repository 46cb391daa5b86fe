// SPDX-License-Identifier: Apache-2.0
#pragma once
// The parallel row reader: the data rows of a big plain .cube parsed on all cores. Only a fast
// path: whenever the data is not plain, it gives up and the sequential parser (CubeParser), which
// owns every message and line number, reads the rows again.
#include <cstddef>

namespace lut::formats::cube {

// Where data row i goes: the shaper's rows first, then the cube's.
struct RowTarget {
    float* first;
    std::size_t firstRows;
    float* second;
    float* row(std::size_t i) const {
        return i < firstRows ? first + 3 * i : second + 3 * (i - firstRows);
    }
};

// Parses [begin, end) into target when it is nothing but data rows and blank lines, exactly
// `rows` of them, every one a plain three-number line (CubeLexer's fastRow): one pass counts the
// rows per chunk, a second parses each chunk into its place. Anything else (comments, keywords, a
// wrong row count, odd numbers, long lines) returns false, as does a machine with one core.
bool parallelRows(const char* begin, const char* end, std::size_t rows, const RowTarget& target);

} // namespace lut::formats::cube
