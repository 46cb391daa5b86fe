#include "lut/ops/Resample.h"

#include "lut/Parallel.h"
#include "lut/Quantize.h"
#include "lut/interp/Sampler.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>

namespace lut {

Lut3D resample(const Lut3D& source, int size, Interpolation method, int nthreads) {
    Lut3D out(size);
    out.setDomain(source.domainMin(), source.domainMax());
    out.setTitle(source.title());
    out.comments() = source.comments();
    if (size == source.size()) {
        out.entries() = source.entries();
        return out;
    }
    const auto sampler = makeSampler(source, method);
    parallelFor(size, nthreads, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b)
            for (int g = 0; g < size; ++g)
                for (int r = 0; r < size; ++r)
                    out.at(r, g, b) = sampler->sample(out.latticeInput(r, g, b));
    });
    return out;
}

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

ResampleResult resampleWithError(const Lut3D& source, int size, Interpolation method,
                                 int nthreads) {
    const auto t0 = std::chrono::steady_clock::now();
    ResampleResult result{resample(source, size, method, nthreads), {}};
    const auto t1 = std::chrono::steady_clock::now();
    result.error = compareLuts(source, result.lut, method);
    result.error.seconds = std::chrono::duration<double>(t1 - t0).count();
    return result;
}

ErrorStats quantize8(Lut3D& lut) {
    const auto t0 = std::chrono::steady_clock::now();
    ErrorAccumulator acc;
    for (auto& v : lut.entries())
        for (int c = 0; c < 3; ++c) {
            const float q = fromUnorm8(toUnorm8(v[c]));
            acc.add(v[c], q);
            v[c] = q;
        }
    ErrorStats s = acc.result();
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return s;
}

} // namespace lut
