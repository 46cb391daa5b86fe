// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/CompareLuts.h"

#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/ErrorBound.h"

#include <algorithm>
#include <cmath>
#include <mutex>

namespace lut {

namespace {

bool sameLattice(const Lut3D& a, const Lut3D& b) {
    return a.size() == b.size() && a.domainMin() == b.domainMin() && a.domainMax() == b.domainMax();
}

// The mean of |a - b| over a probes^3 grid spanning a's domain.
double probeMean(const Lut3D& a, const Lut3D& b, Interpolation method, int probes,
                 std::size_t& count) {
    const auto sa = makeSampler(a, method);
    const auto sb = makeSampler(b, method);
    const glm::vec3 lo = a.domainMin(), hi = a.domainMax();
    std::mutex mutex;
    ErrorAccumulator total;
    parallelFor(probes, 0, [&](int z0, int z1) {
        ErrorAccumulator acc;
        for (int z = z0; z < z1; ++z)
            for (int y = 0; y < probes; ++y)
                for (int x = 0; x < probes; ++x) {
                    const glm::vec3 t(x, y, z);
                    const glm::vec3 in = lo + (hi - lo) * t / static_cast<float>(probes - 1);
                    const glm::vec3 va = sa->sample(in), vb = sb->sample(in);
                    for (int c = 0; c < 3; ++c)
                        acc.add(va[c], vb[c]);
                }
        std::lock_guard lock(mutex);
        total.merge(acc);
    });
    const ErrorStats s = total.result();
    count = s.count;
    return s.meanAbs;
}

} // namespace

ErrorStats compareLuts(const Lut3D& a, const Lut3D& b, Interpolation method, int probes) {
    if (!sameLattice(a, b)) {
        const auto sb = makeSampler(b, method);
        return boundLatticeError(
            a, method,
            [&](const glm::vec3* in, glm::vec3* out, std::size_t n) {
                for (std::size_t i = 0; i < n; ++i)
                    out[i] = sb->sample(in[i]);
            },
            latticeBreaks(b, method));
    }
    // One lattice: every interpolation's value is a blend of entries with weights that depend
    // only on the input, so the difference of the two interpolants is the interpolant of the
    // entries' differences, largest at an entry.
    ErrorStats s;
    for (std::size_t i = 0; i < a.entryCount(); ++i)
        for (int c = 0; c < 3; ++c) {
            double d = std::fabs(double(a.entries()[i][c]) - double(b.entries()[i][c]));
            if (std::isnan(d))
                d = std::isnan(a.entries()[i][c]) && std::isnan(b.entries()[i][c]) ? 0.0 : INFINITY;
            s.maxAbs = std::max(s.maxAbs, d);
        }
    if (probes <= 0)
        probes = std::min(97, 2 * a.size() + 1);
    s.meanAbs = probeMean(a, b, method, probes, s.count);
    s.bounded = true;
    s.sampledMax = s.maxAbs;
    return s;
}

} // namespace lut
