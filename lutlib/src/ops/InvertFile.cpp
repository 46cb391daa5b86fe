// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/InvertFile.h"

#include "lut/Error.h"
#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"
#include "ops/OpsDetail.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace lut {

namespace {

// splitmix64 in [0, 1): a fixed sequence of held-out targets.
double unitRandom(std::uint64_t i) {
    std::uint64_t z = (i + 1) * 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) / 9007199254740992.0;
}

// |f(inverse(y)) - y| at the centres of the inverse's cells and at 100000 pseudo-random targets.
void measureHeldOut(const Sampler& forward, const Lut3D& inverse, FileInvertResult& out,
                    int nthreads) {
    const auto back = makeSampler(inverse, Interpolation::Tetrahedral);
    const glm::vec3 lo = inverse.domainMin(), hi = inverse.domainMax();
    const int cells = inverse.size() - 1;
    const int used = std::min(cells, 64);
    constexpr int kRandom = 100000;
    const int grid = used * used * used;
    ErrorAccumulator total;
    std::mutex m;
    parallelForDynamic(grid + kRandom, nthreads, 4096, [&](int i0, int i1) {
        ErrorAccumulator acc;
        for (int i = i0; i < i1; ++i) {
            glm::vec3 y;
            if (i < grid) {
                const int idx[3] = {i % used, (i / used) % used, i / (used * used)};
                for (int c = 0; c < 3; ++c) {
                    const int cell = static_cast<int>(static_cast<long>(idx[c]) * cells / used);
                    y[c] = static_cast<float>(lo[c] + (static_cast<double>(hi[c]) - lo[c]) *
                                                          (cell + 0.5) / cells);
                }
            } else {
                const std::uint64_t k = static_cast<std::uint64_t>(i - grid);
                for (int c = 0; c < 3; ++c)
                    y[c] = static_cast<float>(lo[c] + (static_cast<double>(hi[c]) - lo[c]) *
                                                          unitRandom(3 * k + c));
            }
            const glm::vec3 reached = forward.sample(back->sample(y));
            for (int c = 0; c < 3; ++c)
                acc.add(reached[c], y[c]);
        }
        std::lock_guard<std::mutex> lock(m);
        total.merge(acc);
    });
    out.heldOutResidual = total.result();
    out.heldOut = static_cast<std::size_t>(grid) + kRandom;
}

} // namespace

FileInvertResult invert(const LutFile& file, const InvertOptions& options) {
    if (!file.cube)
        throw Error("invert: the LUT file holds no 3D table");
    FileInvertResult out;
    out.table = invert(*file.cube, options);
    if (file.shaper) {
        const Lut1D& s = *file.shaper;
        const int n = s.size();
        std::vector<std::unique_ptr<detail::PiecewiseLinearInverse>> inv;
        for (int c = 0; c < 3; ++c) {
            std::vector<double> xs(static_cast<std::size_t>(n)), ys(static_cast<std::size_t>(n));
            for (int i = 0; i < n; ++i) {
                xs[static_cast<std::size_t>(i)] =
                    s.domainMin()[c] +
                    (static_cast<double>(s.domainMax()[c]) - s.domainMin()[c]) * i / (n - 1);
                ys[static_cast<std::size_t>(i)] = detail::sanitizeValue(s[i][c]);
            }
            inv.push_back(std::make_unique<detail::PiecewiseLinearInverse>(xs, ys));
            out.shaperFolds += inv.back()->nonMonotoneSegments();
        }
        for (glm::vec3& e : out.table.lut.entries())
            for (int c = 0; c < 3; ++c)
                e[c] = static_cast<float>((*inv[static_cast<std::size_t>(c)])(e[c]).x);
    }
    const auto forward = makeSampler(file, Interpolation::Tetrahedral);
    measureHeldOut(*forward, out.table.lut, out, options.nthreads);
    return out;
}

} // namespace lut
