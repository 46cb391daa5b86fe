// SPDX-License-Identifier: Apache-2.0
#include "lut/interp/Interpolation.h"

#include "lut/Error.h"

namespace lut {

const char* toString(Interpolation m) {
    switch (m) {
    case Interpolation::Nearest:
        return "nearest";
    case Interpolation::Trilinear:
        return "trilinear";
    case Interpolation::Tetrahedral:
        return "tetrahedral";
    }
    return "?";
}

Interpolation parseInterpolation(std::string_view name) {
    if (name == "nearest")
        return Interpolation::Nearest;
    if (name == "trilinear" || name == "linear")
        return Interpolation::Trilinear;
    if (name == "tetrahedral" || name == "tetra")
        return Interpolation::Tetrahedral;
    throw Error("unknown interpolation '" + std::string(name) +
                "' (expected nearest, trilinear or tetrahedral)");
}

} // namespace lut
