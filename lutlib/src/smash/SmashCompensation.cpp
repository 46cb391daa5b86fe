// SPDX-License-Identifier: Apache-2.0
#include "lut/smash/SmashCompensation.h"

#include "lut/smash/SmashGrading.h"

#include <algorithm>

namespace lut {

Lut3D smashWithoutBrighten(const Lut3D& lut) {
    Lut3D out = lut;
    for (int b = 0; b < lut.size(); ++b)
        for (int g = 0; g < lut.size(); ++g)
            for (int r = 0; r < lut.size(); ++r)
                out.at(r, g, b) = smashBrightenInverse(lut.at(r, g, b), lut.latticeInput(r, g, b));
    return out;
}

double smashWithoutBrightenError(const Lut3D& lut, Interpolation method) {
    if (method != Interpolation::Nearest || lut.size() < 2)
        return 0.0;
    const glm::vec3 span = lut.domainMax() - lut.domainMin();
    const double step = std::max({span.x, span.y, span.z}) / (lut.size() - 1);
    return double(kSmashBrightenScale) * (1.0 - double(kSmashBrightenMix)) * step / 2;
}

} // namespace lut
