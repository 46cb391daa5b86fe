// SPDX-License-Identifier: Apache-2.0
#pragma once
// LUT atlases: strips of one layout and lattice size stacked top to bottom in one picture, row k
// at pixel rows k N .. k N + N - 1 -- what ReShade's MultiLUT.fx samples (its selector adds
// row / rows to the strip's v coordinate; docs/specs/strip-layouts.md). Pixels only: the files
// are lut/formats/Atlas.h's.
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/io/Layout.h"

#include <vector>

namespace lut {

struct AtlasShape {
    LutLayout layout = LutLayout::Reshade;
    int size = 0; // N: each row is an N^2 x N strip
    int rows = 0;
};

// The rows a width x height picture holds as an atlas of `layout`'s strips: N from the width
// (N^2), rows = height / N. Throws lut::Error when the width is no strip's, the layout is hald,
// the layout's name fixes another N, or the height is not a whole number of rows (naming the
// partial row).
AtlasShape atlasShape(int width, int height, LutLayout layout);

// The atlas picture of `rows` (each the same size, alpha 1). Throws lut::Error for no rows,
// rows of different sizes (naming the first that differs), a hald layout or a size the layout
// does not hold.
Image atlasImage(const std::vector<Lut3D>& rows, LutLayout layout);

// Row `row` of an atlas picture of that shape. Throws lut::Error when the row is not there.
Lut3D atlasRow(const ImageView& atlas, const AtlasShape& shape, int row);

} // namespace lut
