#pragma once
// Shared bits of the editor tests: sample paths and the float64 reference for an exposure edit.
#include "lut/Lut3D.h"

#include <QString>

#include <cmath>

namespace lut::gui::test {

inline QString samplePath(const char* name) {
    return QStringLiteral(LUTKIT_SAMPLES_DIR "/") + QString::fromLatin1(name);
}

// Exposure in stops on an encoded value, written out independently of lutlib:
// decode with gamma 2.2, multiply by 2^stops, encode.
inline double exposureRef(double e, double stops) {
    const double lin = (e < 0 ? -std::pow(-e, 2.2) : std::pow(e, 2.2)) * std::pow(2.0, stops);
    return lin < 0 ? -std::pow(-lin, 1 / 2.2) : std::pow(lin, 1 / 2.2);
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
