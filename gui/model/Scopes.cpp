#include "Scopes.h"

#include "lut/Parallel.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

namespace lut::gui {

namespace {

// Rec.709 luma of 8-bit values in integers: weights x 256 (54, 183, 19), rounded.
inline int luma8(int r, int g, int b) {
    return (54 * r + 183 * g + 19 * b + 128) >> 8;
}

} // namespace

Scopes computeScopes(const QImage& display, int columns) {
    Scopes s;
    if (display.isNull() || display.format() != QImage::Format_RGBX8888)
        return s;
    const int w = display.width(), h = display.height();
    columns = std::max(1, std::min(columns, w));
    std::vector<int> columnOf(static_cast<std::size_t>(w));
    for (int x = 0; x < w; ++x)
        columnOf[static_cast<std::size_t>(x)] =
            static_cast<int>(static_cast<long long>(x) * columns / w);
    const std::size_t countSize = static_cast<std::size_t>(3) * columns * 256;
    // counts[channel][column][level]. The threads split the picture into bands of whole parade
    // columns, so each count has one writer; the histograms are summed at the end.
    std::vector<std::uint32_t> counts(countSize, 0);
    std::vector<int> firstX(static_cast<std::size_t>(columns) + 1, w);
    for (int x = w - 1; x >= 0; --x)
        firstX[static_cast<std::size_t>(columnOf[static_cast<std::size_t>(x)])] = x;
    std::mutex merge;
    parallelFor(columns, 0, [&](int c0, int c1) {
        std::array<std::array<std::uint32_t, 256>, 4> hist{};
        std::uint64_t high = 0, low = 0;
        const int x0 = firstX[static_cast<std::size_t>(c0)];
        const int x1 = firstX[static_cast<std::size_t>(c1)];
        for (int y = 0; y < h; ++y) {
            const uchar* p = display.constScanLine(y) + 4 * x0;
            for (int x = x0; x < x1; ++x, p += 4) {
                const std::size_t col = static_cast<std::size_t>(columnOf[x]);
                ++hist[0][p[0]];
                ++hist[1][p[1]];
                ++hist[2][p[2]];
                ++hist[3][luma8(p[0], p[1], p[2])];
                ++counts[col * 256 + p[0]];
                ++counts[(columns + col) * 256 + p[1]];
                ++counts[(2 * static_cast<std::size_t>(columns) + col) * 256 + p[2]];
                high += p[0] == 255 || p[1] == 255 || p[2] == 255;
                low += p[0] == 0 || p[1] == 0 || p[2] == 0;
            }
        }
        std::lock_guard<std::mutex> lock(merge);
        for (int c = 0; c < 4; ++c)
            for (int i = 0; i < 256; ++i)
                s.histogram[c][i] += hist[c][i];
        s.clippedHigh += high;
        s.clippedLow += low;
    });
    s.pixels = static_cast<std::uint64_t>(w) * h;
    // Brightness ~ log of the count relative to a column's full height, so sparse levels show.
    const double perColumn = double(h) * w / columns;
    const double norm = std::log1p(std::max(1.0, perColumn / 16.0));
    s.parade = QImage(3 * columns, 256, QImage::Format_RGB32);
    s.parade.fill(Qt::black);
    for (int level = 0; level < 256; ++level) {
        auto* row = reinterpret_cast<QRgb*>(s.parade.scanLine(255 - level));
        for (int c = 0; c < 3; ++c)
            for (int col = 0; col < columns; ++col) {
                const std::uint32_t n =
                    counts[(static_cast<std::size_t>(c) * columns + col) * 256 + level];
                if (!n)
                    continue;
                const int v =
                    std::clamp(static_cast<int>(255 * std::log1p(double(n)) / norm), 40, 255);
                row[c * columns + col] = c == 0   ? qRgb(v, v / 5, v / 5)
                                         : c == 1 ? qRgb(v / 5, v, v / 5)
                                                  : qRgb(v / 4, v / 4, v);
            }
    }
    return s;
}

QImage clipOverlay(const QImage& display) {
    QImage out(display.size(), QImage::Format_ARGB32_Premultiplied);
    if (display.isNull() || display.format() != QImage::Format_RGBX8888) {
        out.fill(Qt::transparent);
        return out;
    }
    const QRgb high = qPremultiply(qRgba(255, 0, 60, 200));
    const QRgb low = qPremultiply(qRgba(0, 90, 255, 200));
    parallelFor(display.height(), 0, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const uchar* p = display.constScanLine(y);
            auto* o = reinterpret_cast<QRgb*>(out.scanLine(y));
            for (int x = 0; x < display.width(); ++x, p += 4)
                o[x] = (p[0] == 255 || p[1] == 255 || p[2] == 255) ? high
                       : (p[0] == 0 || p[1] == 0 || p[2] == 0)     ? low
                                                                   : 0u;
        }
    });
    return out;
}

} // namespace lut::gui
