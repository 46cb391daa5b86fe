// SPDX-License-Identifier: Apache-2.0
#include "ops/Canvas.h"
#include "lut/Math.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace lut::detail {

namespace {

struct Glyph {
    char ch;
    const char* rows; // 7 rows of 5 pixels, '#' = ink, separated by spaces
};

// clang-format off
constexpr Glyph kGlyphs[] = {
    {'0', ".###. #...# #..## #.#.# ##..# #...# .###."},
    {'1', "..#.. .##.. ..#.. ..#.. ..#.. ..#.. .###."},
    {'2', ".###. #...# ....# ...#. ..#.. .#... #####"},
    {'3', "##### ...#. ..#.. ...#. ....# #...# .###."},
    {'4', "...#. ..##. .#.#. #..#. ##### ...#. ...#."},
    {'5', "##### #.... ####. ....# ....# #...# .###."},
    {'6', "..##. .#... #.... ####. #...# #...# .###."},
    {'7', "##### ....# ...#. ..#.. .#... .#... .#..."},
    {'8', ".###. #...# #...# .###. #...# #...# .###."},
    {'9', ".###. #...# #...# .#### ....# ...#. .##.."},
    {'A', ".###. #...# #...# ##### #...# #...# #...#"},
    {'B', "####. #...# #...# ####. #...# #...# ####."},
    {'C', ".###. #...# #.... #.... #.... #...# .###."},
    {'D', "###.. #..#. #...# #...# #...# #..#. ###.."},
    {'E', "##### #.... #.... ####. #.... #.... #####"},
    {'F', "##### #.... #.... ####. #.... #.... #...."},
    {'G', ".###. #...# #.... #.### #...# #...# .####"},
    {'H', "#...# #...# #...# ##### #...# #...# #...#"},
    {'I', ".###. ..#.. ..#.. ..#.. ..#.. ..#.. .###."},
    {'J', "..### ...#. ...#. ...#. ...#. #..#. .##.."},
    {'K', "#...# #..#. #.#.. ##... #.#.. #..#. #...#"},
    {'L', "#.... #.... #.... #.... #.... #.... #####"},
    {'M', "#...# ##.## #.#.# #.#.# #...# #...# #...#"},
    {'N', "#...# #...# ##..# #.#.# #..## #...# #...#"},
    {'O', ".###. #...# #...# #...# #...# #...# .###."},
    {'P', "####. #...# #...# ####. #.... #.... #...."},
    {'Q', ".###. #...# #...# #...# #.#.# #..#. .##.#"},
    {'R', "####. #...# #...# ####. #.#.. #..#. #...#"},
    {'S', ".#### #.... #.... .###. ....# ....# ####."},
    {'T', "##### ..#.. ..#.. ..#.. ..#.. ..#.. ..#.."},
    {'U', "#...# #...# #...# #...# #...# #...# .###."},
    {'V', "#...# #...# #...# #...# #...# .#.#. ..#.."},
    {'W', "#...# #...# #...# #.#.# #.#.# #.#.# .#.#."},
    {'X', "#...# #...# .#.#. ..#.. .#.#. #...# #...#"},
    {'Y', "#...# #...# .#.#. ..#.. ..#.. ..#.. ..#.."},
    {'Z', "##### ....# ...#. ..#.. .#... #.... #####"},
    {'.', "..... ..... ..... ..... ..... .##.. .##.."},
    {',', "..... ..... ..... ..... .##.. ..#.. .#..."},
    {'=', "..... ..... ##### ..... ##### ..... ....."},
    {'-', "..... ..... ..... ##### ..... ..... ....."},
    {'+', "..... ..#.. ..#.. ##### ..#.. ..#.. ....."},
    {':', "..... .##.. .##.. ..... .##.. .##.. ....."},
    {'/', "..... ....# ...#. ..#.. .#... #.... ....."},
    {'(', "...#. ..#.. .#... .#... .#... ..#.. ...#."},
    {')', ".#... ..#.. ...#. ...#. ...#. ..#.. .#..."},
    {'%', "##... ##..# ...#. ..#.. .#... #..## ...##"},
    {'?', ".###. #...# ....# ...#. ..#.. ..... ..#.."},
    {'_', "..... ..... ..... ..... ..... ..... #####"},
    {'<', "...#. ..#.. .#... #.... .#... ..#.. ...#."},
    {'>', ".#... ..#.. ...#. ....# ...#. ..#.. .#..."},
    {'^', "..... ..#.. ..#.. .#.#. .#.#. #...# #####"},
    {'*', "..... ..#.. #.#.# .###. #.#.# ..#.. ....."},
    {'\'', "..#.. ..#.. .#... ..... ..... ..... ....."},
    {';', "..... .##.. .##.. ..... .##.. ..#.. .#..."},
    {'|', "..#.. ..#.. ..#.. ..#.. ..#.. ..#.. ..#.."},
};
// clang-format on

const char* glyphRows(char c) {
    const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    for (const Glyph& g : kGlyphs)
        if (g.ch == u)
            return g.rows;
    return glyphRows('?');
}

double segmentDistance(double px, double py, double x0, double y0, double x1, double y1) {
    const double dx = x1 - x0, dy = y1 - y0;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((px - x0) * dx + (py - y0) * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return lut::math::hypot(px - (x0 + t * dx), py - (y0 + t * dy));
}

} // namespace

void Canvas::fill(glm::vec3 colour) {
    rect(0, 0, width(), height(), colour);
}

void Canvas::rect(int x, int y, int w, int h, glm::vec3 colour) {
    const int x0 = std::max(0, x), y0 = std::max(0, y);
    const int x1 = std::min(width(), x + w), y1 = std::min(height(), y + h);
    for (int yy = y0; yy < y1; ++yy)
        for (int xx = x0; xx < x1; ++xx) {
            float* p = m_image.pixel(xx, yy);
            p[0] = colour.r;
            p[1] = colour.g;
            p[2] = colour.b;
            p[3] = 1.0f;
        }
}

void Canvas::frame(int x, int y, int w, int h, glm::vec3 colour) {
    rect(x, y, w, 1, colour);
    rect(x, y + h - 1, w, 1, colour);
    rect(x, y, 1, h, colour);
    rect(x + w - 1, y, 1, h, colour);
}

void Canvas::blend(int x, int y, glm::vec3 colour, float coverage) {
    if (x < 0 || y < 0 || x >= width() || y >= height() || !(coverage > 0.0f))
        return;
    const float a = std::min(1.0f, coverage);
    float* p = m_image.pixel(x, y);
    for (int c = 0; c < 3; ++c)
        p[c] = p[c] + a * (colour[c] - p[c]);
    p[3] = 1.0f;
}

void Canvas::add(int x, int y, glm::vec3 colour, float coverage) {
    if (x < 0 || y < 0 || x >= width() || y >= height() || !(coverage > 0.0f))
        return;
    const float a = std::min(1.0f, coverage);
    float* p = m_image.pixel(x, y);
    for (int c = 0; c < 3; ++c)
        p[c] = std::min(1.0f, p[c] + a * colour[c]);
    p[3] = 1.0f;
}

void Canvas::line(double x0, double y0, double x1, double y1, glm::vec3 colour, double thickness,
                  bool additive) {
    if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1))
        return;
    const double r = 0.5 * thickness;
    const int bx0 = static_cast<int>(std::floor(std::min(x0, x1) - r - 1));
    const int bx1 = static_cast<int>(std::ceil(std::max(x0, x1) + r + 1));
    const int by0 = static_cast<int>(std::floor(std::min(y0, y1) - r - 1));
    const int by1 = static_cast<int>(std::ceil(std::max(y0, y1) + r + 1));
    for (int y = std::max(0, by0); y <= std::min(height() - 1, by1); ++y)
        for (int x = std::max(0, bx0); x <= std::min(width() - 1, bx1); ++x) {
            const double d = segmentDistance(x, y, x0, y0, x1, y1);
            const float coverage = static_cast<float>(std::clamp(r + 0.5 - d, 0.0, 1.0));
            if (additive)
                add(x, y, colour, coverage);
            else
                blend(x, y, colour, coverage);
        }
}

void Canvas::polyline(const std::vector<glm::dvec2>& points, glm::vec3 colour, double thickness,
                      bool additive) {
    if (points.size() < 2)
        return;
    const double r = 0.5 * thickness;
    double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
    for (const auto& p : points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            return;
        minX = std::min(minX, p.x);
        minY = std::min(minY, p.y);
        maxX = std::max(maxX, p.x);
        maxY = std::max(maxY, p.y);
    }
    const int x0 = std::max(0, static_cast<int>(std::floor(minX - r - 1)));
    const int y0 = std::max(0, static_cast<int>(std::floor(minY - r - 1)));
    const int x1 = std::min(width() - 1, static_cast<int>(std::ceil(maxX + r + 1)));
    const int y1 = std::min(height() - 1, static_cast<int>(std::ceil(maxY + r + 1)));
    if (x1 < x0 || y1 < y0)
        return;
    const int w = x1 - x0 + 1;
    std::vector<float> coverage(static_cast<std::size_t>(w) * static_cast<std::size_t>(y1 - y0 + 1),
                                0.0f);
    for (std::size_t i = 1; i < points.size(); ++i) {
        const glm::dvec2 a = points[i - 1], b = points[i];
        const int sx0 = std::max(x0, static_cast<int>(std::floor(std::min(a.x, b.x) - r - 1)));
        const int sx1 = std::min(x1, static_cast<int>(std::ceil(std::max(a.x, b.x) + r + 1)));
        const int sy0 = std::max(y0, static_cast<int>(std::floor(std::min(a.y, b.y) - r - 1)));
        const int sy1 = std::min(y1, static_cast<int>(std::ceil(std::max(a.y, b.y) + r + 1)));
        for (int y = sy0; y <= sy1; ++y)
            for (int x = sx0; x <= sx1; ++x) {
                const double d = segmentDistance(x, y, a.x, a.y, b.x, b.y);
                float& c = coverage[static_cast<std::size_t>(y - y0) * static_cast<std::size_t>(w) +
                                    static_cast<std::size_t>(x - x0)];
                c = std::max(c, static_cast<float>(std::clamp(r + 0.5 - d, 0.0, 1.0)));
            }
    }
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const float c =
                coverage[static_cast<std::size_t>(y - y0) * static_cast<std::size_t>(w) +
                         static_cast<std::size_t>(x - x0)];
            if (additive)
                add(x, y, colour, c);
            else
                blend(x, y, colour, c);
        }
}

void Canvas::disc(double cx, double cy, double radius, glm::vec3 colour) {
    if (!std::isfinite(cx) || !std::isfinite(cy))
        return;
    const int x0 = static_cast<int>(std::floor(cx - radius - 1));
    const int x1 = static_cast<int>(std::ceil(cx + radius + 1));
    const int y0 = static_cast<int>(std::floor(cy - radius - 1));
    const int y1 = static_cast<int>(std::ceil(cy + radius + 1));
    for (int y = std::max(0, y0); y <= std::min(height() - 1, y1); ++y)
        for (int x = std::max(0, x0); x <= std::min(width() - 1, x1); ++x) {
            const double d = lut::math::hypot(x - cx, y - cy);
            blend(x, y, colour, static_cast<float>(std::clamp(radius + 0.5 - d, 0.0, 1.0)));
        }
}

void Canvas::text(int x, int y, std::string_view s, glm::vec3 colour, int scale) {
    int pen = x;
    for (char c : s) {
        if (c != ' ') {
            const char* rows = glyphRows(c);
            for (int row = 0; row < 7; ++row)
                for (int col = 0; col < 5; ++col)
                    if (rows[row * 6 + col] == '#')
                        rect(pen + col * scale, y + row * scale, scale, scale, colour);
        }
        pen += 6 * scale;
    }
}

} // namespace lut::detail
