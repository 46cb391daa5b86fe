// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Resample.h"

#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/ErrorBound.h"

#include <chrono>

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

ResampleResult resampleWithError(const Lut3D& source, int size, Interpolation method,
                                 int nthreads) {
    const auto t0 = std::chrono::steady_clock::now();
    ResampleResult result{resample(source, size, method, nthreads), {}};
    const auto t1 = std::chrono::steady_clock::now();
    const auto exact = makeSampler(source, method);
    result.error = boundLatticeError(
        result.lut, method,
        [&](const glm::vec3* in, glm::vec3* out, std::size_t n) {
            for (std::size_t i = 0; i < n; ++i)
                out[i] = exact->sample(in[i]);
        },
        latticeBreaks(source, method), nthreads);
    result.error.seconds = std::chrono::duration<double>(t1 - t0).count();
    return result;
}

} // namespace lut
