#include "Scopes.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lut::gui {

Scopes computeScopes(const QImage& display, int columns) {
    Scopes s;
    if (display.isNull() || display.format() != QImage::Format_RGBX8888)
        return s;
    const int w = display.width(), h = display.height();
    columns = std::max(1, std::min(columns, w));
    // counts[channel][column][level]
    std::vector<std::uint32_t> counts(static_cast<std::size_t>(3) * columns * 256, 0);
    for (int y = 0; y < h; ++y) {
        const uchar* p = display.constScanLine(y);
        for (int x = 0; x < w; ++x, p += 4) {
            const int col = static_cast<int>(static_cast<long long>(x) * columns / w);
            bool high = false, low = false;
            for (int c = 0; c < 3; ++c) {
                ++s.histogram[c][p[c]];
                ++counts[(static_cast<std::size_t>(c) * columns + col) * 256 + p[c]];
                high = high || p[c] == 255;
                low = low || p[c] == 0;
            }
            const int luma =
                static_cast<int>(std::lround(0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]));
            ++s.histogram[3][std::clamp(luma, 0, 255)];
            s.clippedHigh += high;
            s.clippedLow += low;
        }
    }
    s.pixels = static_cast<std::uint64_t>(w) * h;
    // Brightness ~ log of the count relative to a column's full height, so sparse levels show.
    const double perColumn = double(h) * w / columns;
    const double norm = std::log1p(std::max(1.0, perColumn / 16.0));
    s.parade = QImage(3 * columns, 256, QImage::Format_RGB32);
    s.parade.fill(Qt::black);
    for (int c = 0; c < 3; ++c)
        for (int col = 0; col < columns; ++col)
            for (int level = 0; level < 256; ++level) {
                const std::uint32_t n =
                    counts[(static_cast<std::size_t>(c) * columns + col) * 256 + level];
                if (!n)
                    continue;
                const int v =
                    std::clamp(static_cast<int>(255 * std::log1p(double(n)) / norm), 40, 255);
                const QRgb rgb = c == 0   ? qRgb(v, v / 5, v / 5)
                                 : c == 1 ? qRgb(v / 5, v, v / 5)
                                          : qRgb(v / 4, v / 4, v);
                s.parade.setPixel(c * columns + col, 255 - level, rgb);
            }
    return s;
}

QImage clipOverlay(const QImage& display) {
    QImage out(display.size(), QImage::Format_ARGB32_Premultiplied);
    out.fill(Qt::transparent);
    if (display.isNull() || display.format() != QImage::Format_RGBX8888)
        return out;
    const QRgb high = qPremultiply(qRgba(255, 0, 60, 200));
    const QRgb low = qPremultiply(qRgba(0, 90, 255, 200));
    for (int y = 0; y < display.height(); ++y) {
        const uchar* p = display.constScanLine(y);
        auto* o = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < display.width(); ++x, p += 4) {
            if (p[0] == 255 || p[1] == 255 || p[2] == 255)
                o[x] = high;
            else if (p[0] == 0 || p[1] == 0 || p[2] == 0)
                o[x] = low;
        }
    }
    return out;
}

} // namespace lut::gui
