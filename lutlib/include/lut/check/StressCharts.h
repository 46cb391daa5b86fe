// SPDX-License-Identifier: Apache-2.0
#pragma once
// The stress charts colourists run through a LUT to judge it by eye, as pictures of input
// colours (sRGB-encoded, in [0, 1]): what `lutkit chart` writes for grading in other tools, and
// what the check's report picture (lut/check/CheckPicture.h) shows before and after the LUT.
//
//  - grey: a ramp from black (left) to white (right), every column one grey;
//  - hue-saturation: HSV hue 0..360 left to right, saturation 1 (top) to 0 (bottom), value 1;
//  - hue-lightness: HSL hue 0..360 left to right, lightness 1 (top) to 0 (bottom), saturation 1:
//    with hue-saturation, every colour on the surface of the RGB cube;
//  - skin: the skin line (lut/check/CheckLut.h: through the ColorChecker's dark and light skin)
//    from dark (left) to light (right), its chroma from 1.4 times (top) to 0.4 times (bottom)
//    the line's around the same Rec.709 luma;
//  - slices: five slices of the cube side by side at blue 0, 0.25, 0.5, 0.75 and 1, red to the
//    right and green upwards in each, a black gap between them.
#include "lut/Image.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace lut {

enum class StressChart { Grey, HueSaturation, HueLightness, Skin, Slices };

struct StressChartInfo {
    StressChart chart;
    const char* name; // "grey", "hue-saturation", "hue-lightness", "skin", "slices"
    const char* description;
    int width, height; // the size `lutkit chart` writes by default
};
const std::vector<StressChartInfo>& stressCharts();
// The chart of that name, or nullopt.
std::optional<StressChart> stressChartByName(const std::string& name);

// The input colour at pixel (x, y) of a chart of the given size (alpha 1 everywhere, gaps black).
glm::vec3 stressChartColour(StressChart chart, int width, int height, int x, int y);
Image stressChart(StressChart chart, int width, int height);
// Every chart in the order above, `width` wide at its default proportions, one under the other
// with a black gap of 16 pixels: one picture to grade in another tool.
Image stressChartSheet(int width);

// Where colour (sRGB-encoded, [0, 1]) shows in a chart of that size: the pixel whose colour is
// nearest (largest channel difference), or nullopt when none is within `tolerance`.
std::optional<glm::ivec2> locateInChart(StressChart chart, int width, int height, glm::vec3 colour,
                                        float tolerance);

} // namespace lut
