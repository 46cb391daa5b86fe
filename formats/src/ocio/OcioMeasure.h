// SPDX-License-Identifier: Apache-2.0
#pragma once
// Measuring a table against the function it stands for (OpenColorIO's processor, or a chain of
// conversions around a LUT): both evaluated at held-out points between the lattice points, the
// maximum a bound over every input (lut/ops/ErrorBound.h), as every lossy step of lutkit reports
// its error.
#include "lut/ErrorStats.h"
#include "lut/LutFile.h"
#include "lut/interp/Sampler.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace lut::formats {

// Rewrites `count` packed RGB triplets in place; called from several threads at once.
using RgbFunction = std::function<void(float* rgb, std::size_t count)>;

// A LutFile as a function: its shaper (linear), then its cube (tetrahedral), as lutkit applies it.
class LutFileFunction {
public:
    explicit LutFileFunction(const LutFile& file);
    void operator()(float* rgb, std::size_t count) const;
    RgbFunction function() const;

private:
    std::shared_ptr<const LutFile> m_file;
    std::shared_ptr<const Sampler> m_sampler;
};

struct ProbeGrid {
    // How finely the candidate's lattice divides the box: its cells per axis (entries - 1 for a
    // 1D table). 0: from perAxis, read as 2 cells + 1 points (4 for greyOnly) per lattice cell.
    int cells = 0;
    int perAxis = 33;      // points per axis (>= 2), when cells is 0
    bool greyOnly = false; // the grey axis only (per-channel tables)
    // Points evaluated, about: more give a tighter bound, fewer a quicker one.
    std::size_t budget = 300'000;
    // Probe coordinates u in [0,1]^3 to inputs; null = domainMin + (domainMax - domainMin) u.
    RgbFunction toInput;
    glm::vec3 domainMin{0.0f}, domainMax{1.0f};
    // Where the truth kinks, per axis in u (a LUT file's planes and shaper entries): planes of
    // the bound's grid, so that its slope term sees both sides of each.
    std::array<std::vector<double>, 3> breaks;
};

// The probe count per axis that puts a probe at every cell centre of an N^3 lattice (2N - 1)
// while there are at most `cap` per axis.
int probesFor(int latticeSize, int cap = 97);

// |candidate(x) - truth(x)| over the box: maxAbs a bound over every input of it (held-out points
// between the lattice points plus the slope between them; points where truth is NaN or infinite
// are skipped), meanAbs the mean over those points. error.seconds = the time it took.
ErrorStats measureAgainst(const RgbFunction& candidate, const RgbFunction& truth,
                          const ProbeGrid& grid, int nthreads = 0);

} // namespace lut::formats
