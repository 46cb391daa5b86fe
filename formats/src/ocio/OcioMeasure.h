#pragma once
// Measuring a table against the function it stands for (OpenColorIO's processor, or a chain of
// conversions around a LUT): both evaluated on a grid of probe points that falls between the
// lattice points, as every lossy step of lutkit reports its error.
#include "lut/ErrorStats.h"
#include "lut/LutFile.h"
#include "lut/interp/Sampler.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <functional>
#include <memory>

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
    int perAxis = 33;      // points per axis (>= 2)
    bool greyOnly = false; // perAxis points on the grey axis (per-channel tables)
    // Probe coordinates u in [0,1]^3 to inputs; null = domainMin + (domainMax - domainMin) u.
    RgbFunction toInput;
    glm::vec3 domainMin{0.0f}, domainMax{1.0f};
};

// The probe count per axis that puts a probe at every cell centre of an N^3 lattice (2N - 1)
// while there are at most `cap` per axis.
int probesFor(int latticeSize, int cap = 97);

// |candidate(x) - truth(x)| over the probe grid (points where truth is NaN or infinite are
// skipped). error.seconds = the time it took.
ErrorStats measureAgainst(const RgbFunction& candidate, const RgbFunction& truth,
                          const ProbeGrid& grid, int nthreads = 0);

} // namespace lut::formats
