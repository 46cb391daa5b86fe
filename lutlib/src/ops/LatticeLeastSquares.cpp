// SPDX-License-Identifier: Apache-2.0
// The regularised lattice least-squares fit and its conjugate-gradient solve: see
// ops/LatticeLeastSquares.h.
#include "ops/LatticeLeastSquares.h"

#include <cmath>
#include <cstddef>
#include <utility>

namespace lut::detail {

LatticeLeastSquares::LatticeLeastSquares(int n, double lambda, double mu)
    : m_n(n), m_count(std::size_t(n) * n * n), m_lambda(lambda), m_mu(mu),
      m_data(m_count * kLatticeStencil, 0.0) {}

void LatticeLeastSquares::finishAssembly() {
    m_hasData.assign(m_count, 0);
    for (std::size_t i = 0; i < m_count; ++i)
        for (int o = 0; o < kLatticeStencil; ++o)
            if (m_data[i * kLatticeStencil + o] != 0.0) {
                m_hasData[i] = 1;
                break;
            }
}

void LatticeLeastSquares::setPenalty(double kappa, std::vector<LatticeEdge> edges) {
    m_kappa = kappa;
    m_edges = std::move(edges);
}

void LatticeLeastSquares::apply(const std::vector<double>& v, std::vector<double>& y) const {
    const int n = m_n;
    const std::size_t nn = std::size_t(n) * n;
    const bool skip = !m_hasData.empty();
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const std::size_t i = std::size_t(r) + std::size_t(n) * g + nn * b;
                double acc = m_mu * v[i];
                // A row of zeros adds nothing (every term below is skipped for m == 0).
                if (!skip || m_hasData[i]) {
                    const double* row = &m_data[i * kLatticeStencil];
                    for (int db = -1; db <= 1; ++db) {
                        if (b + db < 0 || b + db >= n)
                            continue;
                        for (int dg = -1; dg <= 1; ++dg) {
                            if (g + dg < 0 || g + dg >= n)
                                continue;
                            for (int dr = -1; dr <= 1; ++dr) {
                                if (r + dr < 0 || r + dr >= n)
                                    continue;
                                const double m = row[(dr + 1) + 3 * (dg + 1) + 9 * (db + 1)];
                                if (m != 0.0)
                                    acc += m * v[std::size_t(std::ptrdiff_t(i) + dr +
                                                             std::ptrdiff_t(n) * dg +
                                                             std::ptrdiff_t(nn) * db)];
                            }
                        }
                    }
                }
                y[i] = acc;
            }
    if (m_lambda > 0.0)
        addSmoothness(v, y);
    for (const LatticeEdge& e : m_edges) {
        const double d = m_kappa * (v[e.hi] - v[e.lo]);
        y[e.hi] += d;
        y[e.lo] -= d;
    }
}

// lambda * sum over the axes of D2^T D2 v.
void LatticeLeastSquares::addSmoothness(const std::vector<double>& v,
                                        std::vector<double>& y) const {
    const int n = m_n;
    const std::ptrdiff_t strides[3] = {1, n, std::ptrdiff_t(n) * n};
    for (int axis = 0; axis < 3; ++axis) {
        const std::ptrdiff_t s = strides[axis];
        for (int b = 0; b < n; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r) {
                    const int coord = axis == 0 ? r : axis == 1 ? g : b;
                    if (coord < 1 || coord > n - 2)
                        continue;
                    const std::ptrdiff_t i = r + std::ptrdiff_t(n) * (g + std::ptrdiff_t(n) * b);
                    const double d = m_lambda * (v[std::size_t(i - s)] - 2.0 * v[std::size_t(i)] +
                                                 v[std::size_t(i + s)]);
                    y[std::size_t(i - s)] += d;
                    y[std::size_t(i)] -= 2.0 * d;
                    y[std::size_t(i + s)] += d;
                }
    }
}

std::vector<double> LatticeLeastSquares::diagonal() const {
    std::vector<double> d(m_count);
    const int n = m_n;
    // The diagonal of D2^T D2 along one axis at coordinate i: 4 as a centre, 1 as each
    // neighbour's neighbour.
    auto axisDiag = [n](int i) {
        double s = 0.0;
        if (i >= 1 && i <= n - 2)
            s += 4.0;
        if (i - 1 >= 1 && i - 1 <= n - 2)
            s += 1.0;
        if (i + 1 >= 1 && i + 1 <= n - 2)
            s += 1.0;
        return s;
    };
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const std::size_t i = std::size_t(r) + std::size_t(n) * (g + std::size_t(n) * b);
                d[i] = m_data[i * kLatticeStencil + kLatticeCentre] + m_mu +
                       m_lambda * (axisDiag(r) + axisDiag(g) + axisDiag(b));
            }
    for (const LatticeEdge& e : m_edges) {
        d[e.hi] += m_kappa;
        d[e.lo] += m_kappa;
    }
    return d;
}

CgResult solveJacobiCg(const LatticeLeastSquares& sys, const std::vector<double>& diag,
                       const std::vector<double>& rhs, std::vector<double>& x, int maxIterations,
                       double tolerance) {
    const std::size_t n = sys.count();
    std::vector<double> r(n), z(n), p(n), q(n);
    sys.apply(x, q);
    double bnorm = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        r[i] = rhs[i] - q[i];
        bnorm += rhs[i] * rhs[i];
    }
    bnorm = std::sqrt(bnorm);
    if (bnorm == 0.0)
        bnorm = 1.0;
    double rz = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        z[i] = r[i] / diag[i];
        p[i] = z[i];
        rz += r[i] * z[i];
    }
    CgResult res;
    int it = 0;
    for (; it < maxIterations; ++it) {
        double rnorm = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            rnorm += r[i] * r[i];
        if (std::sqrt(rnorm) <= tolerance * bnorm) {
            res.converged = true;
            break;
        }
        sys.apply(p, q);
        double pq = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            pq += p[i] * q[i];
        if (!(pq > 0.0))
            break; // cannot happen for an SPD system; guards round-off
        const double alpha = rz / pq;
        double rzNew = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            x[i] += alpha * p[i];
            r[i] -= alpha * q[i];
            z[i] = r[i] / diag[i];
            rzNew += r[i] * z[i];
        }
        const double beta = rzNew / rz;
        rz = rzNew;
        for (std::size_t i = 0; i < n; ++i)
            p[i] = z[i] + beta * p[i];
    }
    res.iterations = it;
    return res;
}

} // namespace lut::detail
