// SPDX-License-Identifier: Apache-2.0
#pragma once
// Pictures of where two LUTs differ: ΔE2000 (lut/ops/ColorDifference.h) per pixel of an image, or
// over slices of the cube, mapped through a dark-to-bright colour ramp (black 0 -> purple -> red
// -> orange -> pale yellow at `maxDeltaE` and above), so larger differences are brighter.
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/Progress.h"
#include "lut/interp/Interpolation.h"

#include <glm/vec3.hpp>

#include <vector>

namespace lut {

struct HeatMapOptions {
    double maxDeltaE = 10.0; // ΔE2000 at the top of the ramp; <= 0 = the largest difference found
    Interpolation method = Interpolation::Tetrahedral;
    int nthreads = 0;
    // Rows done so far; a cancel stops the map (CancelledError) within a row.
    const Progress* progress = nullptr;
};

// The ramp colour for t in [0, 1] (clamped; NaN = 0): display-encoded RGB.
glm::vec3 heatMapColor(double t);

struct HeatMap {
    Image image;            // RGBA, alpha 1
    double maxDeltaE = 0.0; // the ΔE the top of the ramp stands for
    double largestDeltaE = 0.0;
};

// One heat pixel per image pixel: ΔE between A and B applied to that pixel's RGB.
HeatMap diffHeatMap(const Lut3D& a, const Lut3D& b, const ImageView& image,
                    const HeatMapOptions& options = {});

// Where the slices are in diffHeatMapSlices' picture.
struct HeatMapSliceLayout {
    int x = 0, y = 0, size = 0; // the square's top-left pixel and edge
    float blue = 0.0f;          // the blue input of this slice (fraction of the domain)
};

// `slices` squares side by side, slice k at blue = k / (slices - 1) of A's domain; in each, red
// input grows to the right and green input upwards (pixel (x, y) of a square of edge S stands for
// red x / (S - 1), green 1 - y / (S - 1)). A label above each square and a ramp legend with its
// scale below. `slices` 1..16, `cellPixels` 16..1024.
HeatMap diffHeatMapSlices(const Lut3D& a, const Lut3D& b, const HeatMapOptions& options = {},
                          int slices = 5, int cellPixels = 128,
                          std::vector<HeatMapSliceLayout>* layout = nullptr);

} // namespace lut
