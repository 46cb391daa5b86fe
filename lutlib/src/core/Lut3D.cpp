// SPDX-License-Identifier: Apache-2.0
#include "lut/Lut3D.h"

#include "lut/Error.h"
#include "lut/Limits.h"

#include <algorithm>
#include <cmath>

namespace lut {

Lut3D::Lut3D(int size) {
    if (size < limits::kMin3DSize || size > limits::kMax3DSize)
        throw Error("3D LUT size " + std::to_string(size) + " is out of range " +
                    std::to_string(limits::kMin3DSize) + ".." + std::to_string(limits::kMax3DSize));
    m_size = size;
    m_entries.assign(static_cast<std::size_t>(size) * size * size, glm::vec3(0.0f));
}

Lut3D Lut3D::identity(int size) {
    Lut3D l(size);
    // i/(N-1) as a correctly rounded division (not i * (1/(N-1)), which is off by an ulp for
    // some i), so entries equal latticeInput() and the last entry is exactly 1.
    std::vector<float> v(static_cast<std::size_t>(size));
    for (int i = 0; i < size; ++i)
        v[static_cast<std::size_t>(i)] = static_cast<float>(i) / static_cast<float>(size - 1);
    for (int b = 0; b < size; ++b)
        for (int g = 0; g < size; ++g)
            for (int r = 0; r < size; ++r)
                l.at(r, g, b) =
                    glm::vec3(v[static_cast<std::size_t>(r)], v[static_cast<std::size_t>(g)],
                              v[static_cast<std::size_t>(b)]);
    return l;
}

static void checkDomain(glm::vec3 min, glm::vec3 max) {
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(min[c]) || !std::isfinite(max[c]))
            throw Error("domain bounds must be finite");
        if (!(min[c] < max[c]))
            throw Error("domain min must be below max for every channel (channel " +
                        std::to_string(c) + ": min " + std::to_string(min[c]) + ", max " +
                        std::to_string(max[c]) + ")");
    }
}

void Lut3D::setDomain(glm::vec3 min, glm::vec3 max) {
    checkDomain(min, max);
    m_domainMin = min;
    m_domainMax = max;
}

bool Lut3D::hasDefaultDomain() const {
    return m_domainMin == glm::vec3(0.0f) && m_domainMax == glm::vec3(1.0f);
}

glm::vec3 Lut3D::latticeInput(int r, int g, int b) const {
    const glm::vec3 idx(static_cast<float>(r), static_cast<float>(g), static_cast<float>(b));
    glm::vec3 out;
    for (int c = 0; c < 3; ++c) {
        const int i = c == 0 ? r : c == 1 ? g : b;
        // Exact at both ends: the last lattice point is exactly domainMax.
        out[c] = i == m_size - 1
                     ? m_domainMax[c]
                     : static_cast<float>(m_domainMin[c] +
                                          (static_cast<double>(m_domainMax[c]) - m_domainMin[c]) *
                                              idx[c] / (m_size - 1));
    }
    return out;
}

float Lut3D::maxDeviationFromIdentity() const {
    double dev = 0.0;
    for (int b = 0; b < m_size; ++b)
        for (int g = 0; g < m_size; ++g)
            for (int r = 0; r < m_size; ++r) {
                const glm::vec3 in = latticeInput(r, g, b);
                const glm::vec3 v = at(r, g, b);
                for (int c = 0; c < 3; ++c) {
                    const double d = std::fabs(static_cast<double>(v[c]) - in[c]);
                    if (std::isnan(d))
                        return INFINITY;
                    dev = std::max(dev, d);
                }
            }
    return static_cast<float>(dev);
}

std::pair<float, float> Lut3D::valueRange() const {
    float lo = INFINITY, hi = -INFINITY;
    for (const auto& v : m_entries)
        for (int c = 0; c < 3; ++c) {
            if (std::isnan(v[c]))
                continue;
            lo = std::min(lo, v[c]);
            hi = std::max(hi, v[c]);
        }
    return {lo, hi};
}

} // namespace lut
