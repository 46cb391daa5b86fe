// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: a tiny rasteriser for the pictures the LUT maths draws (plot, heat maps):
// filled rectangles, anti-aliased lines and discs, and text in a built-in 5x7 bitmap font.
// Colours are display-encoded RGB; alpha of the image is set to 1 where drawn.
#include "lut/Image.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <string_view>
#include <vector>

namespace lut::detail {

class Canvas {
public:
    explicit Canvas(Image& image) : m_image(image) {}
    int width() const { return m_image.width(); }
    int height() const { return m_image.height(); }

    void fill(glm::vec3 colour);
    void rect(int x, int y, int w, int h, glm::vec3 colour);  // filled, clipped to the image
    void frame(int x, int y, int w, int h, glm::vec3 colour); // 1-pixel outline
    // Blends colour over the pixel with coverage in [0, 1].
    void blend(int x, int y, glm::vec3 colour, float coverage);
    // Adds colour * coverage to the pixel (clamped to 1): overlapping R, G, B lines add to white.
    void add(int x, int y, glm::vec3 colour, float coverage);
    // A line of the given width (pixels) with anti-aliased edges; coordinates are pixel centres.
    // additive: drawn with add() instead of blend().
    void line(double x0, double y0, double x1, double y1, glm::vec3 colour, double width = 1.5,
              bool additive = false);
    // A connected line through points; each pixel is drawn once with its largest coverage, so
    // joints do not double up (which matters when additive).
    void polyline(const std::vector<glm::dvec2>& points, glm::vec3 colour, double width,
                  bool additive);
    void disc(double cx, double cy, double radius, glm::vec3 colour);

    // Text with its top-left corner at (x, y), each font pixel `scale` pixels square. Lower case
    // draws as upper case; characters the font lacks draw as '?'; '^' is a delta (triangle).
    void text(int x, int y, std::string_view s, glm::vec3 colour, int scale = 2);
    static int textWidth(std::string_view s, int scale = 2) {
        return s.empty() ? 0 : static_cast<int>(s.size()) * 6 * scale - scale;
    }
    static int textHeight(int scale = 2) { return 7 * scale; }

private:
    Image& m_image;
};

} // namespace lut::detail
