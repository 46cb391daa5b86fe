// SPDX-License-Identifier: Apache-2.0
#include "lut/Lut1D.h"

#include "lut/Error.h"
#include "lut/Limits.h"

#include <cmath>

namespace lut {

Lut1D::Lut1D(int size) {
    if (size < limits::kMin1DSize || size > limits::kMax1DSize)
        throw Error("1D LUT size " + std::to_string(size) + " is out of range " +
                    std::to_string(limits::kMin1DSize) + ".." + std::to_string(limits::kMax1DSize));
    m_entries.assign(static_cast<std::size_t>(size), glm::vec3(0.0f));
}

Lut1D Lut1D::identity(int size) {
    Lut1D l(size);
    for (int i = 0; i < size; ++i)
        l[i] =
            glm::vec3(i == size - 1 ? 1.0f : static_cast<float>(i) / static_cast<float>(size - 1));
    return l;
}

void Lut1D::setDomain(glm::vec3 min, glm::vec3 max) {
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(min[c]) || !std::isfinite(max[c]) || !(min[c] < max[c]))
            throw Error("1D LUT domain must be finite with min below max for every channel");
    m_domainMin = min;
    m_domainMax = max;
}

glm::vec3 Lut1D::apply(glm::vec3 in) const {
    glm::vec3 out(0.0f);
    const int n = size();
    if (n == 0)
        return in;
    for (int c = 0; c < 3; ++c) {
        double x = in[c];
        if (std::isnan(x))
            x = m_domainMin[c];
        double t =
            (x - m_domainMin[c]) / (static_cast<double>(m_domainMax[c]) - m_domainMin[c]) * (n - 1);
        if (!(t > 0.0))
            t = 0.0; // also catches -Inf
        if (t > n - 1)
            t = n - 1;
        int i0 = static_cast<int>(t);
        if (i0 > n - 2)
            i0 = n - 2;
        const double f = t - i0;
        const double a = m_entries[static_cast<std::size_t>(i0)][c];
        const double b = m_entries[static_cast<std::size_t>(i0 + 1)][c];
        out[c] = static_cast<float>(f == 0.0 ? a : f == 1.0 ? b : a + (b - a) * f);
    }
    return out;
}

} // namespace lut
