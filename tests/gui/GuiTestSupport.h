// SPDX-License-Identifier: Apache-2.0
#pragma once
// Shared bits of the editor tests: sample paths, the float64 reference for an exposure edit, a
// tiny PNG that holds a huge picture, a screenshot-like picture in memory.
#include "TestPaths.h"
#include "lut/Lut3D.h"
#include "lut/formats/ImageIO.h"

#include <QByteArray>
#include <QFile>
#include <QString>

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lut::gui::test {

inline QString samplePath(const char* name) {
    return QString::fromUtf8(LUTKIT_SAMPLES_DIR) + QLatin1Char('/') + QString::fromLatin1(name);
}

// An 8-bit picture with gradients and noise, as hard to diff and encode as a screenshot.
inline formats::LoadedImage noisyPicture(int w, int h) {
    formats::LoadedImage l;
    l.image = Image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = l.image.pixel(x, y);
            const unsigned n = (unsigned(x) * 73856093u) ^ (unsigned(y) * 19349663u);
            const unsigned k = (n ^ (n >> 13)) * 0x5bd1e995u;
            // 8-bit values, as a screenshot's PNG holds.
            p[0] = float(std::min(255u, x * 240u / unsigned(w) + (k & 15))) / 255.0f;
            p[1] = float(std::min(255u, y * 240u / unsigned(h) + ((k >> 4) & 15))) / 255.0f;
            p[2] = float((k >> 8) & 255) / 255.0f;
            p[3] = 1.0f;
        }
    l.info.width = w;
    l.info.height = h;
    l.info.channels = 3;
    l.info.bitDepth = 8;
    l.info.format = "png";
    return l;
}

// Exposure in stops on an encoded value, written out independently of lutlib:
// decode with gamma 2.2, multiply by 2^stops, encode.
inline double exposureRef(double e, double stops) {
    const double lin = (e < 0 ? -std::pow(-e, 2.2) : std::pow(e, 2.2)) * std::pow(2.0, stops);
    return lin < 0 ? -std::pow(-lin, 1 / 2.2) : std::pow(lin, 1 / 2.2);
}

// An RGB PNG of w x h black pixels (tests that use it link ZLIB::ZLIB): every row is a filter byte
// and zeros, so deflate packs it ~1000:1 (8192x8192 is ~200 KB holding 201 MB of samples, a 1 GB
// float frame when read).
inline bool writeBlackPng(const QString& path, int w, int h) {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return false;
    auto be32 = [](quint32 v) {
        const char b[4] = {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
        return QByteArray(b, 4);
    };
    auto chunk = [&](const char* type, const QByteArray& data) {
        QByteArray body = QByteArray(type, 4) + data;
        f.write(be32(quint32(data.size())));
        f.write(body);
        f.write(be32(quint32(
            crc32(0, reinterpret_cast<const Bytef*>(body.constData()), uInt(body.size())))));
    };
    f.write("\x89PNG\r\n\x1a\n", 8);
    chunk("IHDR", be32(quint32(w)) + be32(quint32(h)) + QByteArray("\x08\x02\x00\x00\x00", 5));
    z_stream z{};
    if (deflateInit(&z, 9) != Z_OK)
        return false;
    const std::vector<unsigned char> row(static_cast<std::size_t>(w) * 3 + 1, 0);
    QByteArray idat;
    std::vector<unsigned char> out(1 << 16);
    for (int y = 0; y <= h; ++y) {
        z.next_in = const_cast<Bytef*>(row.data());
        z.avail_in = y < h ? uInt(row.size()) : 0;
        const int flush = y < h ? Z_NO_FLUSH : Z_FINISH;
        do {
            z.next_out = out.data();
            z.avail_out = uInt(out.size());
            deflate(&z, flush);
            idat.append(reinterpret_cast<const char*>(out.data()),
                        qsizetype(out.size() - z.avail_out));
        } while (z.avail_out == 0);
    }
    deflateEnd(&z);
    chunk("IDAT", idat);
    chunk("IEND", {});
    return f.error() == QFile::NoError;
}

// Largest |a - b| over every channel of two LUTs of the same size (infinity if sizes differ).
inline double maxDiff(const Lut3D& a, const Lut3D& b) {
    if (a.size() != b.size())
        return INFINITY;
    double m = 0;
    for (std::size_t i = 0; i < a.entryCount(); ++i)
        for (int c = 0; c < 3; ++c)
            m = std::max(m, std::abs(double(a.entries()[i][c]) - double(b.entries()[i][c])));
    return m;
}

} // namespace lut::gui::test
