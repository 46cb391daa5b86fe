#pragma once
// Internal to lutlib: the colours over which Smash authoring measures and refines a game LUT
// (lut/smash/SmashAuthoring.h): inputs s of the game's LUT with the display colour wanted
// there, located in the LUT's cells; the game's error over them; the least-squares refinement.
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

private:
    int m_n;
    std::vector<double> m_s, m_t, m_f;
    std::vector<std::uint16_t> m_corner;
};

// What the game shows at each sample with `lut` (values as given: round them first to measure the
// 8-bit nutexb) against the wanted colour, in 8-bit display steps over every channel value.
// perSample (optional) receives the error of every channel value, 3 per sample.
GameError gameErrorOver(const GameSamples& samples, const Lut3D& lut, int nthreads,
                        std::vector<double>* perSample = nullptr);

// The least-squares refinement (SmashAuthoring.h): per channel, the entries minimising the squared
// display error over the samples, started from `exact` (clamped), weighted by the display's slope
// at the wanted colour, one-sided where the wanted colour is black or white (anything darker than
// black or brighter than white shows the same), a tiny ridge towards `exact` for entries no sample
// constrains; then rounded to 8-bit values by a coordinate search on the true display error.
// Returns entries that are multiples of 1/255 in [0,1].
Lut3D refineSmashLut(const GameSamples& samples, const Lut3D& exact, int nthreads);

} // namespace lut::detail
