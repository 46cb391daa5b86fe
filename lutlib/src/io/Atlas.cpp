// SPDX-License-Identifier: Apache-2.0
#include "lut/io/Atlas.h"

#include "lut/Error.h"

#include <cmath>
#include <string>

namespace lut {

namespace {

std::string sizeText(int w, int h) {
    return std::to_string(w) + "x" + std::to_string(h);
}

void checkStripLayout(LutLayout layout) {
    if (layout == LutLayout::Hald)
        throw Error("an atlas stacks strips: the hald layout is not one (use unreal, unity, "
                    "reshade, unity-32 or smush)");
}

} // namespace

AtlasShape atlasShape(int width, int height, LutLayout layout) {
    checkStripLayout(layout);
    const int n = static_cast<int>(std::lround(std::sqrt(static_cast<double>(width))));
    if (n < 2 || n > 256 || n * n != width)
        throw Error("a " + sizeText(width, height) +
                    " picture is not an atlas of strips: its width must be N^2 for an N^3 LUT "
                    "(1024 for 32^3, 256 for 16^3)");
    if (const std::string problem = layoutSizeProblem(layout, n); !problem.empty())
        throw Error("a " + sizeText(width, height) + " atlas holds " + std::to_string(n) +
                    "^3 rows: " + problem);
    if (height < n || height % n != 0)
        throw Error("a " + sizeText(width, height) + " atlas of " + std::to_string(n) +
                    "-pixel rows (" + std::to_string(n) + "^3 LUTs) is " +
                    std::to_string(height / n) + " rows and " + std::to_string(height % n) +
                    " pixels: row " + std::to_string(height / n) +
                    " is cut short (the height must be a multiple of " + std::to_string(n) + ")");
    return {layout, n, height / n};
}

Image atlasImage(const std::vector<Lut3D>& rows, LutLayout layout) {
    checkStripLayout(layout);
    if (rows.empty())
        throw Error("an atlas needs at least one row");
    const int n = rows.front().size();
    if (const std::string problem = layoutSizeProblem(layout, n); !problem.empty())
        throw Error(problem);
    for (std::size_t k = 1; k < rows.size(); ++k)
        if (rows[k].size() != n)
            throw Error("atlas row " + std::to_string(k) + " is " + std::to_string(rows[k].size()) +
                        "^3, row 0 is " + std::to_string(n) +
                        "^3: every row of an atlas has one size");
    Image img(n * n, n * static_cast<int>(rows.size()));
    for (std::size_t k = 0; k < rows.size(); ++k)
        drawLut(rows[k], layout, img.view(), 0, static_cast<int>(k) * n);
    return img;
}

Lut3D atlasRow(const ImageView& atlas, const AtlasShape& shape, int row) {
    if (row < 0 || row >= shape.rows)
        throw Error("the atlas has rows 0.." + std::to_string(shape.rows - 1) + ", not row " +
                    std::to_string(row));
    return lutFromImage(atlas, shape.layout, shape.size, 0, row * shape.size);
}

} // namespace lut
