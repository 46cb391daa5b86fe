// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <string>
#include <string_view>

namespace lut {

enum class Interpolation { Nearest, Trilinear, Tetrahedral };

const char* toString(Interpolation);
// Parses "nearest", "trilinear" (or "linear"), "tetrahedral" (or "tetra"); throws lut::Error.
Interpolation parseInterpolation(std::string_view name);

} // namespace lut
