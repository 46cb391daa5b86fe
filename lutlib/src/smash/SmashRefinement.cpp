// SPDX-License-Identifier: Apache-2.0
// The least-squares refinement of a game LUT over samples; see SmashRefinement.h.
#include "smash/SmashRefinement.h"

#include "lut/Parallel.h"
#include "lut/smash/GameDisplay.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace lut::detail {

namespace {

// Samples grouped by cell (CSR): start[cell] .. start[cell + 1] index into order.
struct CellIndex {
    std::vector<std::uint32_t> start;
    std::vector<std::uint32_t> order;
};

CellIndex groupByCell(const GameSamples& sm) {
    const std::size_t m = static_cast<std::size_t>(sm.lutSize() - 1);
    CellIndex idx;
    idx.start.assign(m * m * m + 1, 0);
    for (std::size_t p = 0; p < sm.size(); ++p)
        ++idx.start[sm.cellIndex(p) + 1];
    for (std::size_t c = 1; c < idx.start.size(); ++c)
        idx.start[c] += idx.start[c - 1];
    idx.order.resize(sm.size());
    std::vector<std::uint32_t> fill(idx.start.begin(), idx.start.end() - 1);
    for (std::size_t p = 0; p < sm.size(); ++p)
        idx.order[fill[sm.cellIndex(p)]++] = static_cast<std::uint32_t>(p);
    return idx;
}

// Calls fn(p, weight) for every sample in the cells around lattice entry (i, j, k).
template <class Fn>
void forSamplesAround(const GameSamples& sm, const CellIndex& idx, int i, int j, int k, Fn&& fn) {
    const int m = sm.lutSize() - 1;
    for (int ck = std::max(k - 1, 0); ck <= std::min(k, m - 1); ++ck)
        for (int cj = std::max(j - 1, 0); cj <= std::min(j, m - 1); ++cj)
            for (int ci = std::max(i - 1, 0); ci <= std::min(i, m - 1); ++ci) {
                const std::size_t cell =
                    static_cast<std::size_t>(ci) +
                    static_cast<std::size_t>(m) * (cj + static_cast<std::size_t>(m) * ck);
                for (std::uint32_t q = idx.start[cell]; q < idx.start[cell + 1]; ++q) {
                    const std::size_t p = idx.order[q];
                    fn(p, sm.cornerWeight(p, i - ci, j - cj, k - ck));
                }
            }
}
constexpr double kEdgeTolerance = 1e-6;  // wanted this close to white or black is white/black
constexpr double kMaxStep = 4.0 / 255.0; // per Gauss-Seidel update
constexpr double kRidge = 1e-6;          // towards the exact entry, for unconstrained entries
constexpr double kMinSlope = 0.02;       // display slope floor (weights stay positive)
constexpr int kOuterRounds = 4;          // re-weightings (the display is not linear in the entry)
constexpr int kInnerSweeps = 6;          // Gauss-Seidel sweeps per weighting
constexpr int kMaxIntegerSweeps = 4;

// One channel: the display-space least squares solved as weighted least squares in LUT space
// (each sample's weight the squared secant slope of the display between the current value and the
// one that shows the wanted colour, so the weighted LUT-space residual is the display residual),
// re-weighted a few times; then the 8-bit search on the true display error.
void refineChannel(const GameSamples& sm, const CellIndex& idx, const Lut3D& exact, int c,
                   Lut3D& out) {
    const int n = sm.lutSize();
    const std::size_t count = sm.size();
    std::vector<double> target(count), weight(count);
    std::vector<signed char> side(count); // +1: only too dark counts (white), -1: only too bright
    for (std::size_t p = 0; p < count; ++p) {
        const double t = sm.wanted(p, c);
        target[p] = lutForShown(t, sm.s(p, c));
        // (a float blend of white entries may miss 1 by a rounding)
        side[p] = t >= 1.0 - kEdgeTolerance ? 1 : t <= kEdgeTolerance ? -1 : 0;
    }
    const std::vector<double> ex = lutChannel(exact, c);
    std::vector<double> v(ex.size());
    for (std::size_t i = 0; i < v.size(); ++i)
        v[i] = clampUnit(ex[i]);
    std::vector<double> cur(count);
    for (std::size_t p = 0; p < count; ++p)
        cur[p] = sm.trilinear(v, p);

    for (int round = 0; round < kOuterRounds; ++round) {
        for (std::size_t p = 0; p < count; ++p) {
            const double s = sm.s(p, c), d = cur[p] - target[p];
            double slope = std::fabs(d) > 1e-6 ? (gameShown(cur[p], s) - sm.wanted(p, c)) / d
                                               : gameShownSlope(target[p], s);
            slope = std::max(slope, kMinSlope);
            weight[p] = slope * slope;
        }
        for (int sweep = 0; sweep < kInnerSweeps; ++sweep) {
            double largest = 0.0;
            for (int k = 0; k < n; ++k)
                for (int j = 0; j < n; ++j)
                    for (int i = 0; i < n; ++i) {
                        const std::size_t e =
                            static_cast<std::size_t>(i) +
                            static_cast<std::size_t>(n) * (j + static_cast<std::size_t>(n) * k);
                        double num = kRidge * (v[e] - ex[e]), den = kRidge;
                        forSamplesAround(sm, idx, i, j, k, [&](std::size_t p, double w) {
                            const double r = cur[p] - target[p];
                            if ((side[p] > 0 && r >= 0.0) || (side[p] < 0 && r <= 0.0))
                                return;
                            num += weight[p] * w * r;
                            den += weight[p] * w * w;
                        });
                        // a step at most kMaxStep: the weights are from the round's start, and
                        // a long step past the white or black point would overshoot
                        const double step = std::clamp(-num / den, -kMaxStep, kMaxStep);
                        const double next = clampUnit(v[e] + step);
                        const double delta = next - v[e];
                        if (delta == 0.0)
                            continue;
                        v[e] = next;
                        largest = std::max(largest, std::fabs(delta));
                        forSamplesAround(sm, idx, i, j, k,
                                         [&](std::size_t p, double w) { cur[p] += w * delta; });
                    }
            if (largest < 1e-6)
                break;
        }
    }

    // 8 bits: start from the nearest values and move single entries by one step while the true
    // squared display error over the samples falls.
    std::vector<int> q(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
        q[i] = static_cast<int>(std::lround(v[i] * 255.0));
        v[i] = q[i] / 255.0;
    }
    // (gameShownTabulated: the search evaluates the display a few million times)
    auto err = [&](std::size_t p, double value) {
        const double d = gameShownTabulated(value, sm.s(p, c)) - sm.wanted(p, c);
        return d * d;
    };
    std::vector<double> errNow(count);
    for (std::size_t p = 0; p < count; ++p) {
        cur[p] = sm.trilinear(v, p);
        errNow[p] = err(p, cur[p]);
    }
    std::vector<char> active(v.size(), 1), nextActive(v.size(), 0);
    for (int sweep = 0; sweep < kMaxIntegerSweeps; ++sweep) {
        bool changed = false;
        std::fill(nextActive.begin(), nextActive.end(), 0);
        for (int k = 0; k < n; ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const std::size_t e =
                        static_cast<std::size_t>(i) +
                        static_cast<std::size_t>(n) * (j + static_cast<std::size_t>(n) * k);
                    if (!active[e])
                        continue;
                    double gain[2] = {0.0, 0.0};
                    const int steps[2] = {-1, 1};
                    forSamplesAround(sm, idx, i, j, k, [&](std::size_t p, double w) {
                        for (int d = 0; d < 2; ++d)
                            gain[d] += err(p, cur[p] + w * steps[d] / 255.0) - errNow[p];
                    });
                    int best = -1;
                    for (int d = 0; d < 2; ++d) {
                        const int nq = q[e] + steps[d];
                        if (nq < 0 || nq > 255 || gain[d] >= -1e-15)
                            continue;
                        if (best < 0 || gain[d] < gain[best])
                            best = d;
                    }
                    if (best < 0)
                        continue;
                    q[e] += steps[best];
                    const double delta = steps[best] / 255.0;
                    v[e] = q[e] / 255.0;
                    forSamplesAround(sm, idx, i, j, k, [&](std::size_t p, double w) {
                        cur[p] += w * delta;
                        errNow[p] = err(p, cur[p]);
                    });
                    changed = true;
                    for (int dk = -1; dk <= 1; ++dk)
                        for (int dj = -1; dj <= 1; ++dj)
                            for (int di = -1; di <= 1; ++di) {
                                const int a = i + di, b = j + dj, g = k + dk;
                                if (a < 0 || b < 0 || g < 0 || a >= n || b >= n || g >= n)
                                    continue;
                                nextActive[static_cast<std::size_t>(a) +
                                           static_cast<std::size_t>(n) *
                                               (b + static_cast<std::size_t>(n) * g)] = 1;
                            }
                }
        if (!changed)
            break;
        active.swap(nextActive);
    }
    for (std::size_t i = 0; i < v.size(); ++i)
        out.entries()[i][c] = static_cast<float>(q[i] / 255.0);
}

} // namespace

Lut3D refineSmashLut(const GameSamples& sm, const Lut3D& exact, int nthreads) {
    Lut3D out(sm.lutSize());
    out.setTitle(exact.title());
    const CellIndex idx = groupByCell(sm);
    parallelFor(3, nthreads, [&](int c0, int c1) {
        for (int c = c0; c < c1; ++c)
            refineChannel(sm, idx, exact, c, out);
    });
    return out;
}

} // namespace lut::detail
