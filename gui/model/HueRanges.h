// SPDX-License-Identifier: Apache-2.0
#pragma once
// Local influence for the hue curves (lut/ops/Curve.h, periodic over 0..360 degrees) and the six
// hue ranges colourists pick from. A curve through its points alone gives a lone point a
// constant: one point on hue vs saturation moved every hue (red dropped with yellow). So a point
// the editor adds comes with its hue range: neutral anchors (the curve's own value there) at
// x - halfWidth and x + halfWidth, unless a point already lies nearer on that side. The curve is
// monotone between points and flat between equal ones (Fritsch-Carlson), so the edit changes
// only hues strictly between the point's neighbours: within halfWidth of it.
//
// The six ranges are centred on the HSV hues of the primaries and secondaries (as in Photoshop's
// Hue/Saturation and Resolve's hue curves): reds 0, yellows 60, greens 120, cyans 180, blues
// 240, magentas 300 degrees; a range's half width (60) reaches its neighbours' centres, so moving
// the yellows leaves pure red and pure green as they are. No Qt: plain C++ over lutlib.
#include <glm/vec2.hpp>

#include <array>
#include <vector>

namespace lut::gui {

struct HueRange {
    const char* key;   // "reds", "yellows", ... (scripts)
    const char* label; // "Reds", ...
    double centre;     // degrees
};
const std::array<HueRange, 6>& hueRanges();
// The range named `key`, or null.
const HueRange* hueRangeByKey(const char* key);

constexpr double kHueRangeHalfWidth = 60.0;
// Points closer than this (degrees) are one point: a new point there moves the old one.
constexpr double kHuePointGap = 1.0;

// The hue curve `points` after setting the point `p` (a new one, or the one within kHuePointGap,
// which keeps its hue) with local influence: neutral anchors where no other point lies within
// the half width on a side. `valueAt` is the curve's current value at a hue (the anchors keep
// it, so the rest of the curve stays). `*index` receives the point's index in the result (sorted
// by hue, hues in [0, 360)). Every edit of a hue point goes through here: a point that had no
// near neighbour (a lone point, or an anchor being moved) gets its anchors first.
template <class ValueAt>
std::vector<glm::dvec2> withLocalPoint(std::vector<glm::dvec2> points, glm::dvec2 p,
                                       ValueAt valueAt, int* index,
                                       double halfWidth = kHueRangeHalfWidth);
// The non-template core: `anchorValues` are the curve's values at x - halfWidth and x +
// halfWidth.
std::vector<glm::dvec2> withLocalPoint(std::vector<glm::dvec2> points, glm::dvec2 p,
                                       glm::dvec2 anchorValues, int* index, double halfWidth);
// Hue wrapped into [0, 360) and the distance going up (right) / down (left) from a to b.
double wrapDegrees(double h);
double hueDistanceUp(double from, double to);

template <class ValueAt>
std::vector<glm::dvec2> withLocalPoint(std::vector<glm::dvec2> points, glm::dvec2 p,
                                       ValueAt valueAt, int* index, double halfWidth) {
    return withLocalPoint(std::move(points), p,
                          glm::dvec2(valueAt(p.x - halfWidth), valueAt(p.x + halfWidth)), index,
                          halfWidth);
}

} // namespace lut::gui
