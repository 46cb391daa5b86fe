// SPDX-License-Identifier: Apache-2.0
// The samples and the game's error over them; see GameSamples.h.
#include "smash/GameSamples.h"

#include "lut/Parallel.h"
#include "lut/smash/GameDisplay.h"

#include <algorithm>
#include <cmath>

namespace lut::detail {

void GameSamples::reserve(std::size_t count) {
    m_s.reserve(3 * count);
    m_t.reserve(3 * count);
    m_f.reserve(3 * count);
    m_corner.reserve(3 * count);
}

void GameSamples::add(const glm::dvec3& s, const glm::dvec3& wanted) {
    for (int c = 0; c < 3; ++c) {
        const double sc = clampUnit(s[c]);
        const double x = sc * (m_n - 1);
        const int i = std::min(static_cast<int>(x), m_n - 2);
        m_s.push_back(sc);
        m_t.push_back(clampUnit(wanted[c]));
        m_corner.push_back(static_cast<std::uint16_t>(i));
        m_f.push_back(x - i);
    }
}

std::uint32_t GameSamples::cellIndex(std::size_t p) const {
    const std::uint32_t m = static_cast<std::uint32_t>(m_n - 1);
    return m_corner[3 * p] + m * (m_corner[3 * p + 1] + m * m_corner[3 * p + 2]);
}

std::vector<double> lutChannel(const Lut3D& lut, int c) {
    std::vector<double> v(lut.entryCount());
    for (std::size_t i = 0; i < v.size(); ++i)
        v[i] = lut.entries()[i][c];
    return v;
}

GameError gameErrorOver(const GameSamples& sm, const Lut3D& lut, int nthreads,
                        std::vector<double>* perSample) {
    const std::size_t count = sm.size();
    std::vector<double> steps(3 * count);
    const std::vector<double> ch[3] = {lutChannel(lut, 0), lutChannel(lut, 1), lutChannel(lut, 2)};
    const int chunks = static_cast<int>(std::min<std::size_t>(count, 4096));
    parallelFor(chunks, nthreads, [&](int c0, int c1) {
        const std::size_t p0 =
            count * static_cast<std::size_t>(c0) / static_cast<std::size_t>(chunks);
        const std::size_t p1 =
            count * static_cast<std::size_t>(c1) / static_cast<std::size_t>(chunks);
        for (std::size_t p = p0; p < p1; ++p)
            for (int c = 0; c < 3; ++c) {
                const double shown = gameShown(sm.trilinear(ch[c], p), sm.s(p, c));
                steps[3 * p + c] = (shown - sm.wanted(p, c)) * 255.0;
            }
    });
    if (perSample) {
        perSample->resize(steps.size());
        for (std::size_t i = 0; i < steps.size(); ++i)
            (*perSample)[i] = std::fabs(steps[i]);
    }
    return summariseSteps(steps);
}

} // namespace lut::detail
