// SPDX-License-Identifier: Apache-2.0
#pragma once
// The regularised least-squares fit of one channel of a 3D lattice (n^3 nodes, r fastest), the
// solver shared by `lutkit fit` (roundtrip/Fit.cpp: the LUT from a before/after pair) and `lutkit
// match` (match/TransportFit.cpp: the transport's displacements, with a monotonicity penalty).
// It minimises over the node values v
//
//     sum_samples w (sum_corners t_a v_a - y)^2             the data: each sample reads its cell
//                                                           trilinearly (weights t_a)
//   + lambda sum_axes sum_nodes (v[i-s] - 2 v[i] + v[i+s])^2  second differences along r, g, b
//                                                           at every interior node
//   + mu |v - prior|^2                                       a small ridge (pins what nothing
//                                                           else determines)
//   + kappa sum_edges (v[hi] - v[lo] - gap)^2                optional penalty edges
//
// through its normal equations A v = b, A symmetric positive definite: the caller assembles the
// data term into 27 numbers per node (data(); stencil offset (dr+1) + 3(dg+1) + 9(db+1)) and the
// right-hand side (w t_a y summed, mu * prior, kappa * gap on the edges' ends); the operator adds
// the smoothness, the ridge and the edges. solveJacobiCg solves it by conjugate gradients with a
// Jacobi (diagonal) preconditioner. The arithmetic, term by term and in order, is what both
// callers did before it was shared: their outputs are bit-identical.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lut::detail {

inline constexpr int kLatticeStencil = 27; // the 3x3x3 neighbours of a node
inline constexpr int kLatticeCentre = 13;  // the node itself

// A penalty edge: kappa (v[hi] - v[lo] - gap)^2; hi = lo + the stride of an axis.
struct LatticeEdge {
    std::uint32_t lo, hi;
    double gap; // wanted v[hi] - v[lo] at least (the caller adds kappa * gap to the rhs)
};

class LatticeLeastSquares {
public:
    LatticeLeastSquares(int n, double lambda, double mu);

    int size() const { return m_n; }
    std::size_t count() const { return m_count; }
    // The data term, kLatticeStencil numbers per node, for the caller to sum into.
    std::vector<double>& data() { return m_data; }
    const std::vector<double>& data() const { return m_data; }
    // After the data is assembled, optionally: notes the nodes whose stencil row is all zero (most
    // of a sparsely covered cube) so apply() skips them. The same result, faster.
    void finishAssembly();
    // The penalty edges and their weight (none by default).
    void setPenalty(double kappa, std::vector<LatticeEdge> edges);
    const std::vector<LatticeEdge>& edges() const { return m_edges; }
    double kappa() const { return m_kappa; }

    // y = A v: the data, mu v, lambda's second differences (when lambda > 0), the edges.
    void apply(const std::vector<double>& v, std::vector<double>& y) const;
    // A's diagonal (the preconditioner).
    std::vector<double> diagonal() const;

private:
    void addSmoothness(const std::vector<double>& v, std::vector<double>& y) const;

    int m_n;
    std::size_t m_count;
    double m_lambda, m_mu;
    std::vector<double> m_data;
    std::vector<std::uint8_t> m_hasData; // empty: every row (finishAssembly not called)
    double m_kappa = 0.0;
    std::vector<LatticeEdge> m_edges;
};

struct CgResult {
    int iterations = 0;
    bool converged = false; // |b - A x| <= tolerance |b| reached within maxIterations
};

// Jacobi-preconditioned conjugate gradients on sys x = rhs; x holds the start and receives the
// solution. `diag` is sys.diagonal() (computed once when several right-hand sides share sys).
CgResult solveJacobiCg(const LatticeLeastSquares& sys, const std::vector<double>& diag,
                       const std::vector<double>& rhs, std::vector<double>& x, int maxIterations,
                       double tolerance);
inline CgResult solveJacobiCg(const LatticeLeastSquares& sys, const std::vector<double>& rhs,
                              std::vector<double>& x, int maxIterations, double tolerance) {
    return solveJacobiCg(sys, sys.diagonal(), rhs, x, maxIterations, tolerance);
}

} // namespace lut::detail
