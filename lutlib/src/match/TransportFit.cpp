// SPDX-License-Identifier: Apache-2.0
// Sliced transport and the monotone lattice fit of its displacements: see match/TransportFit.h.
#include "match/TransportFit.h"

#include "lut/Math.h"
#include "lut/Parallel.h"
#include "lut/match/HistogramMatch.h"
#include "ops/LatticeLeastSquares.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace lut::detail {

namespace {

// ---- 1. Sliced transport ----

// Rotation number k of a fixed sequence: the first is the identity, then frames from a
// low-discrepancy sequence of unit quaternions (deterministic everywhere).
glm::dmat3 rotation(int k) {
    if (k == 0)
        return glm::dmat3(1.0);
    auto frac = [](double x) { return x - std::floor(x); };
    const double u1 = frac(0.5 + k * 0.6180339887498949);
    const double u2 = frac(0.5 + k * 0.7548776662466927);
    const double u3 = frac(0.5 + k * 0.5698402909980532);
    constexpr double twoPi = 6.283185307179586;
    // Shoemake's uniform quaternion from three numbers in [0, 1)
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    const double qx = a * lut::math::sin(twoPi * u2), qy = a * lut::math::cos(twoPi * u2);
    const double qz = b * lut::math::sin(twoPi * u3), qw = b * lut::math::cos(twoPi * u3);
    glm::dmat3 m;
    m[0] = {1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy + qz * qw), 2 * (qx * qz - qy * qw)};
    m[1] = {2 * (qx * qy - qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz + qx * qw)};
    m[2] = {2 * (qx * qz + qy * qw), 2 * (qy * qz - qx * qw), 1 - 2 * (qx * qx + qy * qy)};
    return m;
}

ChannelHistogram projectionHistogram(const std::vector<glm::dvec3>& values,
                                     const std::vector<float>& weights, const glm::dvec3& axis) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& v : values) {
        const double p = glm::dot(v, axis);
        lo = std::min(lo, p);
        hi = std::max(hi, p);
    }
    if (!(hi - lo > 1e-9)) {
        lo -= 1e-3;
        hi += 1e-3;
    }
    ChannelHistogram h(lo, hi, 2048);
    for (std::size_t i = 0; i < values.size(); ++i)
        h.add(glm::dot(values[i], axis), weights.empty() ? 1.0 : weights[i]);
    return h;
}

// Moves `y` towards `ref` along the axes of `rounds` rotations; returns the displacement.
void slicedTransport(std::vector<glm::dvec3>& y, const std::vector<float>& yWeights,
                     const std::vector<glm::dvec3>& ref, const std::vector<float>& refWeights,
                     int rounds, int nthreads) {
    for (int k = 0; k < rounds; ++k) {
        const glm::dmat3 r = rotation(k);
        std::array<ChannelCurve, 3> curves;
        parallelFor(3, nthreads, [&](int a0, int a1) {
            for (int a = a0; a < a1; ++a) {
                const glm::dvec3 axis = r[a];
                const ChannelHistogram hs = projectionHistogram(y, yWeights, axis);
                const ChannelHistogram hr = projectionHistogram(ref, refWeights, axis);
                CurveLimits limits;
                limits.minSlope = 1.0 / 32.0;
                limits.maxSlope = 32.0;
                limits.smoothing = (hs.quantile(0.999) - hs.quantile(0.001)) / 512.0;
                curves[static_cast<std::size_t>(a)] = matchHistograms(hs, hr, limits);
            }
        });
        parallelFor(static_cast<int>(y.size()), nthreads, [&](int b, int e) {
            for (int i = b; i < e; ++i) {
                glm::dvec3& v = y[static_cast<std::size_t>(i)];
                glm::dvec3 move(0.0);
                for (int a = 0; a < 3; ++a) {
                    const double p = glm::dot(v, r[a]);
                    move += (curves[static_cast<std::size_t>(a)](p) - p) * r[a];
                }
                v += move;
            }
        });
    }
}

// ---- 2. The lattice fit ----

// The regularised lattice least squares, shared with roundtrip/Fit.cpp.
constexpr int kStencil = kLatticeStencil;
using Edge = LatticeEdge;
using LatticeSystem = LatticeLeastSquares;

void solveCg(const LatticeSystem& sys, const std::vector<double>& rhs, std::vector<double>& x,
             int maxIterations, double tolerance) {
    solveJacobiCg(sys, rhs, x, maxIterations, tolerance);
}

// Isotonic regression (pool adjacent violators, equal weights) of values[k] - gap * k, so the
// result rises by at least `gap` per step. Returns how many values moved.
std::size_t isotonic(std::vector<double>& values, double gap) {
    const std::size_t n = values.size();
    std::vector<double> level(n), weight(n);
    std::vector<std::size_t> count(n);
    std::size_t blocks = 0;
    for (std::size_t k = 0; k < n; ++k) {
        level[blocks] = values[k] - gap * static_cast<double>(k);
        weight[blocks] = 1.0;
        count[blocks] = 1;
        ++blocks;
        while (blocks > 1 && level[blocks - 2] > level[blocks - 1]) {
            const double w = weight[blocks - 2] + weight[blocks - 1];
            level[blocks - 2] =
                (level[blocks - 2] * weight[blocks - 2] + level[blocks - 1] * weight[blocks - 1]) /
                w;
            weight[blocks - 2] = w;
            count[blocks - 2] += count[blocks - 1];
            --blocks;
        }
    }
    std::size_t moved = 0, k = 0;
    for (std::size_t b = 0; b < blocks; ++b)
        for (std::size_t j = 0; j < count[b]; ++j, ++k) {
            const double v = level[b] + gap * static_cast<double>(k);
            if (std::fabs(v - values[k]) > 1e-12)
                ++moved;
            values[k] = v;
        }
    return moved;
}

} // namespace

TransportFitResult fitTransport(const std::vector<glm::vec3>& u, const std::vector<float>& weights,
                                const std::vector<glm::vec3>& start, const SampleSet& reference,
                                const glm::dvec3& uMin, const glm::dvec3& uMax,
                                const std::function<glm::dvec3(const glm::dvec3&)>& base,
                                const TransportFitOptions& o) {
    TransportFitResult res;
    const int n = std::max(2, o.size);
    res.size = n;
    const std::size_t count = static_cast<std::size_t>(n) * n * n;
    res.residual.assign(count, glm::vec3(0.0f));
    if (u.empty())
        return res;

    // 1. sliced transport of the samples
    std::vector<glm::dvec3> y(start.begin(), start.end());
    std::vector<glm::dvec3> ref(reference.values.begin(), reference.values.end());
    slicedTransport(y, weights, ref, reference.weights, o.rounds, o.nthreads);
    double totalWeight = 0.0, moved = 0.0;
    for (std::size_t i = 0; i < y.size(); ++i) {
        totalWeight += weights[i];
        const glm::dvec3 d = y[i] - glm::dvec3(start[i]);
        moved += weights[i] * glm::dot(d, d);
    }
    res.movedRms = std::sqrt(moved / std::max(totalWeight, 1e-300) / 3.0);

    // 2. the lattice fit; weights scaled to sum to the sample count
    const double scale = static_cast<double>(u.size()) / std::max(totalWeight, 1e-300);
    const double lambda = o.smoothness * static_cast<double>(u.size()) / static_cast<double>(count);
    LatticeSystem sys(n, lambda, o.ridge * lambda);
    std::vector<std::vector<double>> rhs(3, std::vector<double>(count, 0.0));
    const int cells = n - 1;
    std::vector<double>& data = sys.data();
    for (std::size_t i = 0; i < u.size(); ++i) {
        int base0[3];
        double f[3];
        for (int c = 0; c < 3; ++c) {
            const double range = uMax[c] - uMin[c];
            double p = range > 0.0 ? (u[i][c] - uMin[c]) / range * cells : 0.0;
            p = std::clamp(p, 0.0, static_cast<double>(cells));
            base0[c] = std::min(static_cast<int>(p), cells - 1);
            f[c] = p - base0[c];
        }
        double w[8];
        std::size_t node[8];
        for (int a = 0; a < 8; ++a) {
            const int dr = a & 1, dg = (a >> 1) & 1, db = (a >> 2) & 1;
            w[a] = (dr ? f[0] : 1.0 - f[0]) * (dg ? f[1] : 1.0 - f[1]) * (db ? f[2] : 1.0 - f[2]);
            node[a] = static_cast<std::size_t>((base0[0] + dr) +
                                               n * ((base0[1] + dg) + n * (base0[2] + db)));
        }
        const double sw = weights[i] * scale;
        const glm::dvec3 d = y[i] - glm::dvec3(start[i]);
        for (int a = 0; a < 8; ++a) {
            if (w[a] == 0.0)
                continue;
            double* row = &data[node[a] * kStencil];
            for (int b = 0; b < 8; ++b) {
                const int dr = (b & 1) - (a & 1), dg = ((b >> 1) & 1) - ((a >> 1) & 1),
                          db = ((b >> 2) & 1) - ((a >> 2) & 1);
                row[(dr + 1) + 3 * (dg + 1) + 9 * (db + 1)] += sw * w[a] * w[b];
            }
            for (int c = 0; c < 3; ++c)
                rhs[static_cast<std::size_t>(c)][node[a]] += sw * w[a] * d[c];
        }
    }

    // the base map at the lattice nodes
    std::vector<glm::dvec3> baseAt(count);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::dvec3 t = glm::dvec3(r, g, b) / static_cast<double>(cells);
                baseAt[static_cast<std::size_t>(r + n * (g + n * b))] =
                    base(uMin + (uMax - uMin) * t);
            }

    const double kappa = 1000.0 * lambda + 1.0;
    int penaltyRounds[3] = {0, 0, 0};
    std::size_t fixes[3] = {0, 0, 0};
    std::vector<std::vector<double>> sol(3, std::vector<double>(count, 0.0));
    parallelFor(3, o.nthreads, [&](int c0, int c1) {
        for (int c = c0; c < c1; ++c) {
            LatticeSystem s = sys; // own penalty set per channel
            std::vector<double>& x = sol[static_cast<std::size_t>(c)];
            const std::size_t stride = c == 0   ? 1
                                       : c == 1 ? static_cast<std::size_t>(n)
                                                : static_cast<std::size_t>(n) * n;
            const double gap = o.minSlope * (uMax[c] - uMin[c]) / cells;
            std::vector<Edge> active;
            std::vector<std::uint8_t> isActive(count, 0);
            for (int round = 0; round < 9; ++round) {
                std::vector<double> b = rhs[static_cast<std::size_t>(c)];
                for (const Edge& e : active) {
                    b[e.hi] += kappa * e.gap;
                    b[e.lo] -= kappa * e.gap;
                }
                s.setPenalty(kappa, active);
                solveCg(s, b, x, 3000, 1e-7);
                // new violations of base + r rising by `gap` along the axis
                bool added = false;
                for (std::size_t i = 0; i < count; ++i) {
                    const std::size_t coord = c == 0   ? i % n
                                              : c == 1 ? (i / n) % n
                                                       : i / (static_cast<std::size_t>(n) * n);
                    if (coord + 1 >= static_cast<std::size_t>(n) || isActive[i])
                        continue;
                    const std::size_t j = i + stride;
                    const double g = gap - (baseAt[j][c] - baseAt[i][c]);
                    if (x[j] - x[i] < g - 1e-9) {
                        active.push_back(
                            {static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), g});
                        isActive[i] = 1;
                        added = true;
                    }
                }
                if (!added)
                    break;
                penaltyRounds[c] = round + 1;
            }
            // isotonic clean-up along each line of the axis
            std::vector<double> line(static_cast<std::size_t>(n));
            for (std::size_t start0 = 0; start0 < count; ++start0) {
                const std::size_t coord = c == 0   ? start0 % n
                                          : c == 1 ? (start0 / n) % n
                                                   : start0 / (static_cast<std::size_t>(n) * n);
                if (coord != 0)
                    continue;
                for (int k = 0; k < n; ++k) {
                    const std::size_t i = start0 + static_cast<std::size_t>(k) * stride;
                    line[static_cast<std::size_t>(k)] = baseAt[i][c] + x[i];
                }
                fixes[c] += isotonic(line, gap);
                for (int k = 0; k < n; ++k) {
                    const std::size_t i = start0 + static_cast<std::size_t>(k) * stride;
                    x[i] = line[static_cast<std::size_t>(k)] - baseAt[i][c];
                }
            }
        }
    });
    res.penaltyRounds = std::max({penaltyRounds[0], penaltyRounds[1], penaltyRounds[2]});
    res.isotonicFixes = fixes[0] + fixes[1] + fixes[2];
    for (std::size_t i = 0; i < count; ++i)
        res.residual[i] = glm::vec3(static_cast<float>(sol[0][i]), static_cast<float>(sol[1][i]),
                                    static_cast<float>(sol[2][i]));
    return res;
}

} // namespace lut::detail
