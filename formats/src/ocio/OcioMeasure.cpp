#include "ocio/OcioMeasure.h"

#include "lut/Parallel.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
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
    const int p = std::max(2, grid.perAxis);
    const std::size_t total =
        grid.greyOnly ? static_cast<std::size_t>(p) : static_cast<std::size_t>(p) * p * p;
    const float inv = 1.0f / static_cast<float>(p - 1);
    constexpr std::size_t kChunk = 4096;
    const int chunks = static_cast<int>((total + kChunk - 1) / kChunk);
    std::mutex m;
    ErrorAccumulator all;
    parallelForDynamic(chunks, nthreads, 1, [&](int c0, int c1) {
        ErrorAccumulator acc;
        std::vector<float> in, a, b;
        for (int c = c0; c < c1; ++c) {
            const std::size_t begin = static_cast<std::size_t>(c) * kChunk;
            const std::size_t n = std::min(kChunk, total - begin);
            in.resize(3 * n);
            for (std::size_t i = 0; i < n; ++i) {
                const std::size_t k = begin + i;
                glm::vec3 u;
                if (grid.greyOnly) {
                    u = glm::vec3(static_cast<float>(k) * inv);
                } else {
                    const std::size_t pp = static_cast<std::size_t>(p);
                    u = glm::vec3(static_cast<float>(k % pp), static_cast<float>((k / pp) % pp),
                                  static_cast<float>(k / (pp * pp))) *
                        inv;
                }
                if (!grid.toInput)
                    u = grid.domainMin + (grid.domainMax - grid.domainMin) * u;
                in[3 * i] = u.x;
                in[3 * i + 1] = u.y;
                in[3 * i + 2] = u.z;
            }
            if (grid.toInput)
                grid.toInput(in.data(), n);
            a = in;
            b = in;
            candidate(a.data(), n);
            truth(b.data(), n);
            for (std::size_t i = 0; i < 3 * n; ++i)
                if (std::isfinite(b[i]))
                    acc.add(a[i], b[i]);
        }
        std::lock_guard lock(m);
        all.merge(acc);
    });
    ErrorStats e = all.result();
    e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return e;
}

} // namespace lut::formats
