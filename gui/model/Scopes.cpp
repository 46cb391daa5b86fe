// SPDX-License-Identifier: Apache-2.0
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

// Brightness of a count relative to `norm` (log scale, so sparse levels show), 0 for none.
inline int countBrightness(std::uint32_t n, double norm, int floor) {
    return n ? std::clamp(static_cast<int>(255 * std::log1p(double(n)) / norm), floor, 255) : 0;
}

// countBrightness for every count up to `largest` (at most 65536 entries), computed once per
// frame: the same expression, so the same values, without a log per occupied cell of the three
// pictures (a third of the scopes' time on a 960x540 drag frame). Larger counts are computed.
class BrightnessTable {
public:
    BrightnessTable(std::uint32_t largest, double norm, int floor) : m_norm(norm), m_floor(floor) {
        m_values.resize(std::min<std::uint32_t>(largest, 65535u) + 1u);
        for (std::size_t n = 0; n < m_values.size(); ++n)
            m_values[n] = static_cast<unsigned char>(
                countBrightness(static_cast<std::uint32_t>(n), norm, floor));
    }
    int operator()(std::uint32_t n) const {
        return n < m_values.size() ? m_values[n] : countBrightness(n, m_norm, m_floor);
    }

private:
    std::vector<unsigned char> m_values;
    double m_norm;
    int m_floor;
};

inline int waveformLevelOf(int r, int g, int b) {
    return (13933 * r + 46871 * g + 4732 * b + 32768) >> 16;
}

inline int vectorscopeCellOf(int r, int g, int b) {
    const int u = -7509 * r - 25259 * g + 32768 * b; // 255 * 65536 * Cb
    const int v = 32768 * r - 29763 * g - 3005 * b;  // 255 * 65536 * Cr
    const int col = std::min(kVectorscopeSize - 1, (u + 8355840) / 65280);
    const int row = kVectorscopeSize - 1 - std::min(kVectorscopeSize - 1, (v + 8355840) / 65280);
    return row * kVectorscopeSize + col;
}

} // namespace

int waveformLevel(int r, int g, int b) {
    return waveformLevelOf(r, g, b);
}

int vectorscopeCell(int r, int g, int b) {
    return vectorscopeCellOf(r, g, b);
}

void vectorscopeCbCr(int r, int g, int b, double* cb, double* cr) {
    const double rp = r / 255.0, gp = g / 255.0, bp = b / 255.0;
    const double y = 0.2126 * rp + 0.7152 * gp + 0.0722 * bp;
    *cb = (bp - y) / 1.8556;
    *cr = (rp - y) / 1.5748;
}

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
    // counts[channel][column][level], and the waveform's [column][level]. The threads split the
    // picture into bands of whole parade columns, so each count has one writer; the histograms
    // and the vectorscope are summed at the end.
    std::vector<std::uint32_t> counts(countSize, 0);
    s.columns = columns;
    s.waveform.assign(static_cast<std::size_t>(columns) * 256, 0);
    constexpr std::size_t kCells = std::size_t(kVectorscopeSize) * kVectorscopeSize;
    s.vectorscope.assign(kCells, 0);
    std::vector<int> firstX(static_cast<std::size_t>(columns) + 1, w);
    for (int x = w - 1; x >= 0; --x)
        firstX[static_cast<std::size_t>(columnOf[static_cast<std::size_t>(x)])] = x;
    std::mutex merge;
    parallelFor(columns, 0, [&](int c0, int c1) {
        std::array<std::array<std::uint32_t, 256>, 4> hist{};
        std::vector<std::uint32_t> vector(kCells, 0);
        std::uint64_t high = 0, low = 0;
        const uchar* bits = display.constBits();
        const std::size_t stride = static_cast<std::size_t>(display.bytesPerLine());
        std::uint32_t* const waveform = s.waveform.data();
        const int x0 = firstX[static_cast<std::size_t>(c0)];
        const int x1 = firstX[static_cast<std::size_t>(c1)];
        for (int y = 0; y < h; ++y) {
            const uchar* p = bits + stride * static_cast<std::size_t>(y) + 4 * x0;
            for (int x = x0; x < x1; ++x, p += 4) {
                // The samples in registers first: a count's store could otherwise change them
                // (bytes alias everything), and each was read again after each store.
                const int r = p[0], g = p[1], b = p[2];
                const std::size_t col = static_cast<std::size_t>(columnOf[x]);
                ++hist[0][r];
                ++hist[1][g];
                ++hist[2][b];
                ++hist[3][luma8(r, g, b)];
                ++counts[col * 256 + static_cast<std::size_t>(r)];
                ++counts[(columns + col) * 256 + static_cast<std::size_t>(g)];
                ++counts[(2 * static_cast<std::size_t>(columns) + col) * 256 +
                         static_cast<std::size_t>(b)];
                ++waveform[col * 256 + static_cast<std::size_t>(waveformLevelOf(r, g, b))];
                ++vector[static_cast<std::size_t>(vectorscopeCellOf(r, g, b))];
                high += r == 255 || g == 255 || b == 255;
                low += r == 0 || g == 0 || b == 0;
            }
        }
        std::lock_guard<std::mutex> lock(merge);
        for (int c = 0; c < 4; ++c)
            for (int i = 0; i < 256; ++i)
                s.histogram[c][i] += hist[c][i];
        s.clippedHigh += high;
        s.clippedLow += low;
        for (std::size_t i = 0; i < kCells; ++i)
            s.vectorscope[i] += vector[i];
    });
    s.pixels = static_cast<std::uint64_t>(w) * h;
    // Brightness ~ log of the count relative to a column's full height, so sparse levels show.
    const double perColumn = double(h) * w / columns;
    const double norm = std::log1p(std::max(1.0, perColumn / 16.0));
    // A column holds at most h * (widest column) pixels: the table covers every count.
    std::uint32_t widest = 0;
    for (int c = 0; c < columns; ++c)
        widest =
            std::max(widest, static_cast<std::uint32_t>(firstX[static_cast<std::size_t>(c) + 1] -
                                                        firstX[static_cast<std::size_t>(c)]));
    const BrightnessTable columnBrightness(static_cast<std::uint32_t>(h) * widest, norm, 40);
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
                const int v = columnBrightness(n);
                row[c * columns + col] = c == 0   ? qRgb(v, v / 5, v / 5)
                                         : c == 1 ? qRgb(v / 5, v, v / 5)
                                                  : qRgb(v / 4, v / 4, v);
            }
    }
    // The waveform in the colour of a waveform monitor's trace.
    s.waveformImage = QImage(columns, 256, QImage::Format_RGB32);
    s.waveformImage.fill(Qt::black);
    for (int level = 0; level < 256; ++level) {
        auto* row = reinterpret_cast<QRgb*>(s.waveformImage.scanLine(255 - level));
        for (int col = 0; col < columns; ++col) {
            const int v = columnBrightness(
                s.waveform[static_cast<std::size_t>(col) * 256 + static_cast<std::size_t>(level)]);
            if (v)
                row[col] = qRgb(v * 3 / 4, v, v * 3 / 4);
        }
    }
    // The vectorscope: each occupied cell in its own hue (the hue of its Cb, Cr direction).
    const int n = kVectorscopeSize;
    const double perCell = std::max(1.0, double(h) * w / (n * n / 8.0));
    const double vnorm = std::log1p(perCell);
    // Most occupied cells hold few pixels: a short table, and a log for the crowded ones.
    const BrightnessTable cellBrightness(
        static_cast<std::uint32_t>(std::min<std::uint64_t>(s.pixels, 4095u)), vnorm, 70);
    s.vectorscopeImage = QImage(n, n, QImage::Format_RGB32);
    s.vectorscopeImage.fill(Qt::black);
    for (int row = 0; row < n; ++row) {
        auto* line = reinterpret_cast<QRgb*>(s.vectorscopeImage.scanLine(row));
        for (int col = 0; col < n; ++col) {
            const std::uint32_t count = s.vectorscope[static_cast<std::size_t>(row) * n + col];
            if (!count)
                continue;
            const int v = cellBrightness(count);
            // The colour of this direction: Y' 0.5 with the cell's Cb and Cr, back to R'G'B'.
            const double cb = (col + 0.5) / n - 0.5, cr = (n - 1 - row + 0.5) / n - 0.5;
            const double r = 0.5 + 1.5748 * cr, b = 0.5 + 1.8556 * cb;
            const double g = (0.5 - 0.2126 * r - 0.0722 * b) / 0.7152;
            auto ch = [v](double c) {
                return std::clamp(static_cast<int>(v * (0.35 + 0.65 * std::clamp(c, 0.0, 1.0))), 0,
                                  255);
            };
            line[col] = qRgb(ch(r), ch(g), ch(b));
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
    const int w = display.width(); // not a call per pixel
    uchar* const outBits = out.bits();
    const std::size_t outStride = static_cast<std::size_t>(out.bytesPerLine());
    parallelFor(display.height(), 0, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const uchar* p = display.constScanLine(y);
            auto* o = reinterpret_cast<QRgb*>(outBits + outStride * static_cast<std::size_t>(y));
            for (int x = 0; x < w; ++x, p += 4)
                o[x] = (p[0] == 255 || p[1] == 255 || p[2] == 255) ? high
                       : (p[0] == 0 || p[1] == 0 || p[2] == 0)     ? low
                                                                   : 0u;
        }
    });
    return out;
}

} // namespace lut::gui
