#include "lut/ops/CompareLuts.h"

#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"

#include <algorithm>
#include <mutex>

namespace lut {

ErrorStats compareLuts(const Lut3D& a, const Lut3D& b, Interpolation method, int probes) {
    if (probes <= 0)
        probes = std::min(97, 2 * std::max(a.size(), b.size()) + 1);
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
    return total.result();
}

} // namespace lut
