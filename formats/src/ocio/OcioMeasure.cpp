// SPDX-License-Identifier: Apache-2.0
#include "ocio/OcioMeasure.h"

#include "lut/ops/ErrorBound.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace lut::formats {

LutFileFunction::LutFileFunction(const LutFile& file)
    : m_file(std::make_shared<const LutFile>(file)) {
    if (m_file->cube)
        m_sampler = makeSampler(*m_file->cube, Interpolation::Tetrahedral);
}

void LutFileFunction::operator()(float* rgb, std::size_t count) const {
    for (std::size_t i = 0; i < count; ++i) {
        glm::vec3 v(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]);
        if (m_file->shaper)
            v = m_file->shaper->apply(v);
        if (m_sampler)
            v = m_sampler->sample(v);
        rgb[3 * i] = v.x;
        rgb[3 * i + 1] = v.y;
        rgb[3 * i + 2] = v.z;
    }
}

RgbFunction LutFileFunction::function() const {
    LutFileFunction self = *this;
    return [self](float* rgb, std::size_t n) { self(rgb, n); };
}

int probesFor(int latticeSize, int cap) {
    return std::max(2, std::min(2 * latticeSize - 1, cap));
}

ErrorStats measureAgainst(const RgbFunction& candidate, const RgbFunction& truth,
                          const ProbeGrid& grid, int nthreads) {
    const auto t0 = std::chrono::steady_clock::now();
    BoundOptions o;
    o.greyOnly = grid.greyOnly;
    o.cells = grid.cells > 0
                  ? grid.cells
                  : std::max(1, (std::max(2, grid.perAxis) - 1) / (grid.greyOnly ? 4 : 2));
    o.budget = grid.budget;
    o.nthreads = nthreads;
    o.breaks = grid.breaks;
    // The box is u in [0,1]^3, mapped to inputs as the probe grid says.
    const ErrorStats e = boundError(
        [&](const glm::dvec3* u, glm::dvec3* diff, std::size_t n) {
            std::vector<float> in(3 * n), a, b;
            for (std::size_t i = 0; i < n; ++i)
                for (int c = 0; c < 3; ++c)
                    in[3 * i + static_cast<std::size_t>(c)] =
                        grid.toInput
                            ? static_cast<float>(u[i][c])
                            : static_cast<float>(grid.domainMin[c] +
                                                 (double(grid.domainMax[c]) - grid.domainMin[c]) *
                                                     u[i][c]);
            if (grid.toInput)
                grid.toInput(in.data(), n);
            a = in;
            b = in;
            candidate(a.data(), n);
            truth(b.data(), n);
            for (std::size_t i = 0; i < n; ++i)
                for (int c = 0; c < 3; ++c) {
                    const std::size_t k = 3 * i + static_cast<std::size_t>(c);
                    diff[i][c] = !std::isfinite(b[k])   ? NAN // no truth there: skipped
                                 : !std::isfinite(a[k]) ? INFINITY
                                                        : double(b[k]) - double(a[k]);
                }
        },
        o);
    ErrorStats out = e;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

} // namespace lut::formats
