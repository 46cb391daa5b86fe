// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Regions.h"

#include <algorithm>
#include <cmath>

namespace lut {

const char* toString(Region region) {
    switch (region) {
    case Region::Shadows:
        return "shadows";
    case Region::Midtones:
        return "midtones";
    case Region::Highlights:
        return "highlights";
    case Region::Neutrals:
        return "neutrals";
    case Region::Red:
        return "red";
    case Region::Yellow:
        return "yellow";
    case Region::Green:
        return "green";
    case Region::Cyan:
        return "cyan";
    case Region::Blue:
        return "blue";
    case Region::Magenta:
        return "magenta";
    }
    return "?";
}

RegionOf classifyRegion(glm::vec3 input) {
    glm::dvec3 c;
    for (int i = 0; i < 3; ++i)
        c[i] = std::isnan(input[i]) ? 0.0 : std::clamp(static_cast<double>(input[i]), 0.0, 1.0);
    const double y = 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
    RegionOf out{};
    out.tone = y < 1.0 / 3.0   ? Region::Shadows
               : y < 2.0 / 3.0 ? Region::Midtones
                               : Region::Highlights;
    const double mx = std::max({c.x, c.y, c.z});
    const double chroma = mx - std::min({c.x, c.y, c.z});
    if (chroma < 0.1) {
        out.hue = Region::Neutrals;
        return out;
    }
    double h;
    if (mx == c.x)
        h = (c.y - c.z) / chroma;
    else if (mx == c.y)
        h = (c.z - c.x) / chroma + 2.0;
    else
        h = (c.x - c.y) / chroma + 4.0;
    h *= 60.0;
    if (h < 0.0)
        h += 360.0;
    const int sector = static_cast<int>(std::floor((h + 30.0) / 60.0)) % 6;
    out.hue = static_cast<Region>(static_cast<int>(Region::Red) + sector);
    return out;
}

} // namespace lut
