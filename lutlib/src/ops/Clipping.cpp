// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Clipping.h"

#include <cmath>

namespace lut {

ClipCount countOutOfRange(const Lut3D& lut, float lo, float hi) {
    ClipCount c;
    c.entries = lut.entryCount();
    // One pass of plain compares: ~36k entries for a 33^3 LUT, no threads needed.
    for (const glm::vec3& e : lut.entries()) {
        bool below = false, above = false, nonFinite = false;
        for (int ch = 0; ch < 3; ++ch) {
            const float v = e[ch];
            if (v < lo) {
                below = true;
                ++c.channelBelow[static_cast<std::size_t>(ch)];
            } else if (v > hi) {
                above = true;
                ++c.channelAbove[static_cast<std::size_t>(ch)];
            }
            if (!std::isfinite(v))
                nonFinite = true;
        }
        c.below += below;
        c.above += above;
        c.nonFinite += nonFinite;
        c.outside += below || above || nonFinite;
    }
    return c;
}

} // namespace lut
