// SPDX-License-Identifier: Apache-2.0
#pragma once
// A picture of a LUT that people can read at a glance (lutkit plot, the editor's LUT view):
//  - left: the per-channel curves along the neutral axis (output R, G, B for input (t, t, t)),
//    drawn additively (where all three coincide the line is white, two make yellow, cyan or
//    magenta), with the identity dashed, grid lines at quarters and labelled axes;
//  - middle: three slices of the cube at blue = 0, 0.5 and 1 (red input to the right, green
//    input upwards), each pixel the LUT's output there;
//  - right: the lattice in 3D: a grid of lattice points drawn where the LUT sends them (at their
//    output colour, coloured by it), inside the wireframe of the identity cube, seen from the
//    side with the neutral axis upright (black at the bottom, white at the top), red to the
//    right and cyan to the left, yellow and green in front, tilted 25 degrees towards the
//    viewer, corners labelled (K R G B C M Y W). A straight isometric view
//    along the cube's diagonal would hide the neutral axis, so the axonometric view turns it
//    upright instead.
// Labels use a built-in 5x7 bitmap font. Outputs are shown clamped to [0, 1]; the curve panel's
// vertical range grows to show outputs down to -1 and up to 2. NaN entries count as 0.
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"

#include <array>

namespace lut {

struct PlotRect {
    int x = 0, y = 0, width = 0, height = 0;
};

// Where each part is, so callers (and tests) can find values in the picture.
struct PlotLayout {
    // Curve plot area: pixel column x = curves.x + t (width - 1) for input fraction t of the
    // domain; row y = curves.y + (height - 1) (1 - (v - curveMin) / (curveMax - curveMin)).
    PlotRect curves;
    double curveMin = 0.0, curveMax = 1.0;
    // Slice k: pixel (x, y) of the square of edge S shows the output for the input fraction
    // (x / (S - 1), 1 - y / (S - 1), sliceBlue[k]) of the domain.
    std::array<PlotRect, 3> slices{};
    std::array<float, 3> sliceBlue{0.0f, 0.5f, 1.0f};
    PlotRect lattice;
};

struct PlotOptions {
    int latticePoints = 9; // lattice points per axis in the 3D view, 2..17
    Interpolation method = Interpolation::Tetrahedral;
};

struct Plot {
    Image image; // RGBA, display-encoded, alpha 1
    PlotLayout layout;
};

Plot plotLut(const Lut3D& lut, const PlotOptions& options = {});

} // namespace lut
