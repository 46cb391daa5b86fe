// SPDX-License-Identifier: Apache-2.0
#include "HueRanges.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace lut::gui {

const std::array<HueRange, 6>& hueRanges() {
    static const std::array<HueRange, 6> ranges = {{{"reds", "Reds", 0.0},
                                                    {"yellows", "Yellows", 60.0},
                                                    {"greens", "Greens", 120.0},
                                                    {"cyans", "Cyans", 180.0},
                                                    {"blues", "Blues", 240.0},
                                                    {"magentas", "Magentas", 300.0}}};
    return ranges;
}

const HueRange* hueRangeByKey(const char* key) {
    for (const HueRange& r : hueRanges())
        if (std::strcmp(r.key, key) == 0)
            return &r;
    return nullptr;
}

double wrapDegrees(double h) {
    double w = std::fmod(h, 360.0);
    if (w < 0.0)
        w += 360.0;
    return w >= 360.0 ? 0.0 : w;
}

double hueDistanceUp(double from, double to) {
    return wrapDegrees(to - from);
}

std::vector<glm::dvec2> withLocalPoint(std::vector<glm::dvec2> points, glm::dvec2 p,
                                       glm::dvec2 anchorValues, int* index, double halfWidth) {
    p.x = wrapDegrees(p.x);
    auto near = [&](double a, double b) {
        const double d = hueDistanceUp(a, b);
        return std::min(d, 360.0 - d) < kHuePointGap;
    };
    // A point at (about) this hue already: it is the one set (at its own hue).
    auto same = std::find_if(points.begin(), points.end(),
                             [&](const glm::dvec2& q) { return near(q.x, p.x); });
    if (same != points.end()) {
        p.x = same->x;
        points.erase(same);
    }
    // The nearest other point on each side (going up and going down the hue circle): where none
    // is within the half width, a neutral anchor keeps the rest of the curve as it is.
    double up = 360.0, down = 360.0;
    for (const glm::dvec2& q : points) {
        up = std::min(up, hueDistanceUp(p.x, q.x));
        down = std::min(down, hueDistanceUp(q.x, p.x));
    }
    if (up > halfWidth)
        points.push_back({wrapDegrees(p.x + halfWidth), anchorValues.y});
    if (down > halfWidth)
        points.push_back({wrapDegrees(p.x - halfWidth), anchorValues.x});
    points.push_back(p);
    std::sort(points.begin(), points.end(),
              [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x; });
    // Two anchors may meet (a half width of 180): keep one.
    points.erase(std::unique(points.begin(), points.end(),
                             [](const glm::dvec2& a, const glm::dvec2& b) { return a.x == b.x; }),
                 points.end());
    if (index) {
        *index = -1;
        for (std::size_t i = 0; i < points.size(); ++i)
            if (points[i].x == p.x)
                *index = static_cast<int>(i);
    }
    return points;
}

} // namespace lut::gui
