// SPDX-License-Identifier: Apache-2.0
// The regularised lattice least squares that fit and match share (ops/LatticeLeastSquares.h; in
// match_tests, which links lutlib_internal) against the same problem written here as a dense
// float64 matrix and solved by Gaussian elimination: on a 4^3 lattice (64 unknowns), samples at
// random points read trilinearly, the second differences along each axis, the ridge and two penalty
// edges.
#include "ops/LatticeLeastSquares.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

using lut::detail::LatticeEdge;
using lut::detail::LatticeLeastSquares;

namespace {

constexpr int kN = 4;
constexpr int kCount = kN * kN * kN;

int node(int r, int g, int b) {
    return r + kN * (g + kN * b);
}

struct Problem {
    std::vector<std::vector<double>> a; // the dense normal matrix
    std::vector<double> rhs;
    LatticeLeastSquares sys{kN, 0.0, 0.0};
};

// Samples y = a smooth function of the position plus noise, at random points; the dense normal
// equations of the objective in the header, term by term.
Problem makeProblem(double lambda, double mu, double kappa, unsigned seed) {
    Problem p;
    p.a.assign(kCount, std::vector<double>(kCount, 0.0));
    p.rhs.assign(kCount, 0.0);
    p.sys = LatticeLeastSquares(kN, lambda, mu);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double>& data = p.sys.data();
    for (int k = 0; k < 40; ++k) {
        double pos[3];
        int base[3];
        double f[3];
        for (int c = 0; c < 3; ++c) {
            pos[c] = u(rng) * (kN - 1);
            base[c] = std::min(static_cast<int>(pos[c]), kN - 2);
            f[c] = pos[c] - base[c];
        }
        const double y = std::sin(pos[0]) + 0.3 * pos[1] * pos[2] + 0.05 * (u(rng) - 0.5);
        const double w = 0.5 + u(rng);
        int idx[8];
        double t[8];
        for (int c = 0; c < 8; ++c) {
            const int dr = c & 1, dg = (c >> 1) & 1, db = (c >> 2) & 1;
            idx[c] = node(base[0] + dr, base[1] + dg, base[2] + db);
            t[c] = (dr ? f[0] : 1 - f[0]) * (dg ? f[1] : 1 - f[1]) * (db ? f[2] : 1 - f[2]);
        }
        for (int i = 0; i < 8; ++i) {
            for (int j = 0; j < 8; ++j) {
                p.a[idx[i]][idx[j]] += w * t[i] * t[j];
                // the solver's stencil row of node idx[i]: offset of idx[j] from it
                const int dr = (j & 1) - (i & 1), dg = ((j >> 1) & 1) - ((i >> 1) & 1),
                          db = ((j >> 2) & 1) - ((i >> 2) & 1);
                data[static_cast<std::size_t>(idx[i]) * 27 + (dr + 1) + 3 * (dg + 1) +
                     9 * (db + 1)] += w * t[i] * t[j];
            }
            p.rhs[idx[i]] += w * t[i] * y;
        }
    }
    // lambda * sum of (v[i-s] - 2 v[i] + v[i+s])^2 over interior nodes of each axis
    for (int axis = 0; axis < 3; ++axis)
        for (int b = 0; b < kN; ++b)
            for (int g = 0; g < kN; ++g)
                for (int r = 0; r < kN; ++r) {
                    const int at[3] = {r, g, b};
                    if (at[axis] < 1 || at[axis] > kN - 2)
                        continue;
                    int lo[3] = {r, g, b}, hi[3] = {r, g, b};
                    --lo[axis];
                    ++hi[axis];
                    const int idx[3] = {node(lo[0], lo[1], lo[2]), node(r, g, b),
                                        node(hi[0], hi[1], hi[2])};
                    const double d[3] = {1.0, -2.0, 1.0};
                    for (int i = 0; i < 3; ++i)
                        for (int j = 0; j < 3; ++j)
                            p.a[idx[i]][idx[j]] += lambda * d[i] * d[j];
                }
    // mu * |v - prior|^2, prior = 0.25 everywhere
    for (int i = 0; i < kCount; ++i) {
        p.a[i][i] += mu;
        p.rhs[i] += mu * 0.25;
    }
    // kappa * (v[hi] - v[lo] - gap)^2
    std::vector<LatticeEdge> edges = {
        {static_cast<std::uint32_t>(node(1, 1, 1)), static_cast<std::uint32_t>(node(2, 1, 1)), 0.4},
        {static_cast<std::uint32_t>(node(0, 2, 3)), static_cast<std::uint32_t>(node(0, 3, 3)),
         -0.1}};
    if (kappa > 0.0) {
        for (const LatticeEdge& e : edges) {
            p.a[e.hi][e.hi] += kappa;
            p.a[e.lo][e.lo] += kappa;
            p.a[e.hi][e.lo] -= kappa;
            p.a[e.lo][e.hi] -= kappa;
            p.rhs[e.hi] += kappa * e.gap;
            p.rhs[e.lo] -= kappa * e.gap;
        }
        p.sys.setPenalty(kappa, edges);
    }
    return p;
}

// Gaussian elimination with partial pivoting.
std::vector<double> denseSolve(std::vector<std::vector<double>> a, std::vector<double> b) {
    const int n = static_cast<int>(b.size());
    for (int k = 0; k < n; ++k) {
        int piv = k;
        for (int i = k + 1; i < n; ++i)
            if (std::fabs(a[i][k]) > std::fabs(a[piv][k]))
                piv = i;
        std::swap(a[k], a[piv]);
        std::swap(b[k], b[piv]);
        for (int i = k + 1; i < n; ++i) {
            const double m = a[i][k] / a[k][k];
            for (int j = k; j < n; ++j)
                a[i][j] -= m * a[k][j];
            b[i] -= m * b[k];
        }
    }
    std::vector<double> x(n);
    for (int i = n - 1; i >= 0; --i) {
        double s = b[i];
        for (int j = i + 1; j < n; ++j)
            s -= a[i][j] * x[j];
        x[i] = s / a[i][i];
    }
    return x;
}

} // namespace

TEST(LatticeLeastSquares, OperatorAndDiagonalAreTheNormalMatrix) {
    for (double kappa : {0.0, 3.0}) {
        Problem p = makeProblem(0.7, 1e-3, kappa, 3);
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        std::vector<double> v(kCount), y(kCount);
        for (double& x : v)
            x = u(rng);
        p.sys.apply(v, y);
        const std::vector<double> diag = p.sys.diagonal();
        for (int i = 0; i < kCount; ++i) {
            double want = 0.0;
            for (int j = 0; j < kCount; ++j)
                want += p.a[i][j] * v[j];
            EXPECT_NEAR(y[i], want, 1e-12) << "row " << i << " kappa " << kappa;
            EXPECT_NEAR(diag[i], p.a[i][i], 1e-12) << "row " << i;
        }
        // Skipping the rows without data changes no bit.
        std::vector<double> skipped(kCount);
        p.sys.finishAssembly();
        p.sys.apply(v, skipped);
        EXPECT_EQ(skipped, y);
    }
}

TEST(LatticeLeastSquares, ConjugateGradientsReachTheDenseSolution) {
    for (double lambda : {0.0, 0.05, 2.0})
        for (double kappa : {0.0, 10.0}) {
            Problem p = makeProblem(lambda, 1e-4, kappa, 11);
            const std::vector<double> want = denseSolve(p.a, p.rhs);
            std::vector<double> x(kCount, 0.0);
            const auto cg = lut::detail::solveJacobiCg(p.sys, p.rhs, x, 5000, 1e-13);
            EXPECT_TRUE(cg.converged) << lambda << " " << kappa;
            EXPECT_GT(cg.iterations, 0);
            double worst = 0.0, scale = 0.0;
            for (int i = 0; i < kCount; ++i) {
                worst = std::max(worst, std::fabs(x[i] - want[i]));
                scale = std::max(scale, std::fabs(want[i]));
            }
            EXPECT_LT(worst, 1e-8 * std::max(1.0, scale))
                << "lambda " << lambda << " kappa " << kappa;
        }
}

TEST(LatticeLeastSquares, StopsWhereTheIterationsRunOut) {
    Problem p = makeProblem(0.5, 1e-4, 0.0, 17);
    std::vector<double> x(kCount, 0.0);
    const auto cg = lut::detail::solveJacobiCg(p.sys, p.rhs, x, 2, 1e-13);
    EXPECT_FALSE(cg.converged);
    EXPECT_EQ(cg.iterations, 2);
}
