// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: the colours over which Smash authoring measures and refines a game LUT
// (lut/smash/SmashAuthoring.h): inputs s of the game's LUT with the display colour wanted
// there, located in the LUT's cells, and the game's error over them. The least-squares
// refinement fitted on them is in SmashRefinement.h.
#include "lut/Lut3D.h"
#include "lut/smash/GameError.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace lut::detail {

class GameSamples {
public:
    explicit GameSamples(int lutSize) : m_n(lutSize) {}
    int lutSize() const { return m_n; }
    std::size_t size() const { return m_s.size() / 3; }
    void reserve(std::size_t count);
    // s in [0,1]^3 (clamped), wanted display colour (clamped to [0,1]).
    void add(const glm::dvec3& s, const glm::dvec3& wanted);

    double s(std::size_t p, int c) const { return m_s[3 * p + c]; }
    double wanted(std::size_t p, int c) const { return m_t[3 * p + c]; }
    // The cell (lower corner per axis, 0..n-2) and the fractions inside it.
    int corner(std::size_t p, int axis) const { return m_corner[3 * p + axis]; }
    double fraction(std::size_t p, int axis) const { return m_f[3 * p + axis]; }
    // Linear cell index (r fastest) over the (n-1)^3 cells.
    std::uint32_t cellIndex(std::size_t p) const;
    // Trilinear weight of the corner (dx, dy, dz) of sample p's cell.
    // (inline: the refinement's sweeps call these for every sample around every entry)
    double cornerWeight(std::size_t p, int dx, int dy, int dz) const {
        const double fx = fraction(p, 0), fy = fraction(p, 1), fz = fraction(p, 2);
        return (dx ? fx : 1.0 - fx) * (dy ? fy : 1.0 - fy) * (dz ? fz : 1.0 - fz);
    }
    // The trilinear value of channel values v (r fastest, lutSize()^3) at sample p.
    double trilinear(const std::vector<double>& v, std::size_t p) const {
        const int i = corner(p, 0), j = corner(p, 1), k = corner(p, 2);
        const auto n = static_cast<std::size_t>(m_n);
        double acc = 0.0;
        for (int dz = 0; dz < 2; ++dz)
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx)
                    acc += cornerWeight(p, dx, dy, dz) *
                           v[static_cast<std::size_t>(i + dx) + n * (j + dy + n * (k + dz))];
        return acc;
    }

private:
    int m_n;
    std::vector<double> m_s, m_t, m_f;
    std::vector<std::uint16_t> m_corner;
};

// Channel c of every entry of lut (r fastest), in double.
std::vector<double> lutChannel(const Lut3D& lut, int c);

// What the game shows at each sample with `lut` (values as given: round them first to measure the
// 8-bit nutexb) against the wanted colour, in 8-bit display steps over every channel value.
// perSample (optional) receives the error of every channel value, 3 per sample.
GameError gameErrorOver(const GameSamples& samples, const Lut3D& lut, int nthreads,
                        std::vector<double>* perSample = nullptr);

} // namespace lut::detail
