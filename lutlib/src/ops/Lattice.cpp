// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Lattice.h"

#include "lut/Error.h"
#include "lut/Math.h"
#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <vector>

namespace lut {

namespace {

constexpr double kGridPoints = 3.0e5; // about 67 per axis
constexpr int kRandomPoints = 100000;

// A fixed sequence in [0, 1): splitmix64.
double unitRandom(std::uint64_t i) {
    std::uint64_t z = (i + 1) * 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) / 9007199254740992.0;
}

} // namespace

LatticeResult sampleOnLattice(const LutFile& file, const LatticeRequest& q) {
    if (!file.cube && !file.shaper)
        throw Error("the LUT file holds no table");
    const auto t0 = std::chrono::steady_clock::now();
    const int size = q.size > 0 ? q.size : file.cube ? file.cube->size() : 33;
    const glm::vec3 lo = q.domainMin.value_or(file.inputDomainMin());
    const glm::vec3 hi = q.domainMax.value_or(file.inputDomainMax());
    LatticeResult res;
    res.lut = Lut3D(size);
    res.lut.setDomain(lo, hi); // throws for a bad domain
    res.lut.setTitle(file.cube ? file.cube->title() : file.shaper->title());
    if (file.cube)
        res.lut.comments() = file.cube->comments();
    const auto exact = makeSampler(file, q.fileMethod);
    Lut3D& out = res.lut;
    parallelFor(size, q.nthreads, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b)
            for (int g = 0; g < size; ++g)
                for (int r = 0; r < size; ++r)
                    out.at(r, g, b) = exact->sample(out.latticeInput(r, g, b));
    });

    // Held-out inputs: a grid inside every cell, then pseudo-random points over the domain.
    const auto read = makeSampler(out, q.readWith);
    // Per axis: every cell (at most perAxis of them, evenly spread, on the largest lattices), each
    // at perCell fractions.
    const int cells = size - 1;
    const int perAxis = static_cast<int>(lut::math::cbrt(kGridPoints));
    const int used = std::min(cells, perAxis);
    const int perCell = std::max(1, perAxis / cells);
    const int axis = used * perCell;
    std::vector<float> coord[3];
    for (int c = 0; c < 3; ++c) {
        coord[c].resize(static_cast<std::size_t>(axis));
        for (int i = 0; i < axis; ++i) {
            const int cell = static_cast<int>(static_cast<long>(i / perCell) * cells / used);
            const double u = (cell + (i % perCell + 0.5) / perCell) / cells;
            coord[c][static_cast<std::size_t>(i)] =
                static_cast<float>(lo[c] + (static_cast<double>(hi[c]) - lo[c]) * u);
        }
    }
    ErrorAccumulator total;
    std::mutex m;
    auto compare = [&](ErrorAccumulator& acc, glm::vec3 x) {
        const glm::vec3 want = exact->sample(x), got = read->sample(x);
        for (int c = 0; c < 3; ++c)
            acc.add(got[c], want[c]);
    };
    parallelForDynamic(axis, q.nthreads, 1, [&](int b0, int b1) {
        ErrorAccumulator acc;
        for (int b = b0; b < b1; ++b)
            for (int g = 0; g < axis; ++g)
                for (int r = 0; r < axis; ++r)
                    compare(acc, glm::vec3(coord[0][static_cast<std::size_t>(r)],
                                           coord[1][static_cast<std::size_t>(g)],
                                           coord[2][static_cast<std::size_t>(b)]));
        std::lock_guard<std::mutex> lock(m);
        total.merge(acc);
    });
    parallelForDynamic(kRandomPoints, q.nthreads, 4096, [&](int i0, int i1) {
        ErrorAccumulator acc;
        for (int i = i0; i < i1; ++i) {
            glm::vec3 x;
            for (int c = 0; c < 3; ++c)
                x[c] = static_cast<float>(lo[c] +
                                          (static_cast<double>(hi[c]) - lo[c]) *
                                              unitRandom(3 * static_cast<std::uint64_t>(i) + c));
            compare(acc, x);
        }
        std::lock_guard<std::mutex> lock(m);
        total.merge(acc);
    });
    res.error = total.result();
    res.heldOut = static_cast<std::size_t>(axis) * axis * axis + kRandomPoints;
    res.error.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
}

} // namespace lut
