// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Invert.h"

#include "lut/Error.h"
#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/ErrorBound.h"
#include "ops/OpsDetail.h"

#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <optional>

namespace lut {

namespace {

constexpr std::size_t kWorstKept = 16;

double maxAbs(glm::dvec3 v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}
double norm2(glm::dvec3 v) {
    return v.x * v.x + v.y * v.y + v.z * v.z;
}

struct Sol {
    glm::dvec3 x{0.0};
    glm::dvec3 fx{0.0};
    double err2 = INFINITY; // |A(x) - y|^2
};

class Solver {
public:
    Solver(const Lut3D& a, const InvertOptions& o) : m_f(a), m_o(o) {
        m_lo = a.domainMin();
        m_hi = a.domainMax();
        const int n = a.size();
        // Starts from the neutral axis: the per-channel inverse of A(t, t, t).
        for (int c = 0; c < 3; ++c) {
            std::vector<double> xs(static_cast<std::size_t>(n)), ys(static_cast<std::size_t>(n));
            for (int k = 0; k < n; ++k) {
                xs[static_cast<std::size_t>(k)] = a.latticeInput(k, k, k)[c];
                ys[static_cast<std::size_t>(k)] = a.at(k, k, k)[c];
            }
            m_diag[static_cast<std::size_t>(c)].emplace(std::move(xs), std::move(ys));
        }
        // A coarse grid of A's outputs for the nearest-output start.
        const int k = std::min(n, 9);
        for (int b = 0; b < k; ++b)
            for (int g = 0; g < k; ++g)
                for (int r = 0; r < k; ++r) {
                    const glm::dvec3 t = glm::dvec3(r, g, b) / static_cast<double>(k - 1);
                    const glm::dvec3 x = m_lo + (m_hi - m_lo) * t;
                    m_gridIn.push_back(x);
                    m_gridOut.push_back(m_f(x));
                }
    }

    // Returns the solution; usedLeastSquares says Newton failed from every start.
    Sol solve(glm::dvec3 y, const std::optional<glm::dvec3>& previous,
              bool& usedLeastSquares) const {
        usedLeastSquares = false;
        const double tol2 = m_o.tolerance * m_o.tolerance;
        Sol best;
        auto attempt = [&](glm::dvec3 start, bool damped) {
            const Sol s = descend(start, y, damped);
            if (s.err2 < best.err2)
                best = s;
            return maxAbs(s.fx - y) <= m_o.tolerance;
        };
        if (previous && attempt(*previous, false))
            return best;
        if (attempt(diagonalStart(y), false))
            return best;
        const glm::dvec3 nearest = gridStart(y);
        if (attempt(nearest, false))
            return best;
        // No start reached the target: what is left is the least-squares answer (the closest A
        // gets). A damped pass from the best point polishes it where the undamped steps stalled.
        usedLeastSquares = true;
        if (best.err2 > tol2)
            attempt(best.x, true);
        return best;
    }

private:
    glm::dvec3 clampX(glm::dvec3 x) const { return glm::clamp(x, m_lo, m_hi); }

    Sol at(glm::dvec3 x, glm::dvec3 y) const {
        Sol s{x, m_f(x), 0.0};
        s.err2 = norm2(s.fx - y);
        return s;
    }

    glm::dvec3 diagonalStart(glm::dvec3 y) const {
        glm::dvec3 x;
        for (int c = 0; c < 3; ++c)
            x[c] = (*m_diag[static_cast<std::size_t>(c)])(y[c]).x;
        return clampX(x);
    }

    glm::dvec3 gridStart(glm::dvec3 y) const {
        std::size_t best = 0;
        double bestD = INFINITY;
        for (std::size_t i = 0; i < m_gridOut.size(); ++i) {
            const double d = norm2(m_gridOut[i] - y);
            if (d < bestD) {
                bestD = d;
                best = i;
            }
        }
        return m_gridIn[best];
    }

    // Gauss-Newton on |A(x) - y|^2 with x kept in the domain: channels at a bound whose descent
    // direction points out of the domain are held there (active set) and the step is solved for
    // the others, so a target outside A's gamut converges to its closest reachable point as
    // quickly as a reachable one converges to its preimage. Where the Jacobian is invertible and
    // nothing is held, the step is Newton's (damped = false starts undamped); a step that does
    // not lower the residual after backtracking raises the Levenberg-Marquardt damping.
    Sol descend(glm::dvec3 x0, glm::dvec3 y, bool damped) const {
        Sol s = at(clampX(x0), y);
        double lambda = damped ? 1e-3 : 0.0;
        for (int it = 0; it < m_o.maxIterations; ++it) {
            if (maxAbs(s.fx - y) <= 0.01 * m_o.tolerance)
                break;
            glm::dmat3 j;
            m_f(s.x, &j);
            const glm::dvec3 r = y - s.fx;
            const glm::dvec3 g = glm::transpose(j) * r; // descent direction of |r|^2 / 2
            bool held[3];
            for (int c = 0; c < 3; ++c)
                held[c] = (s.x[c] <= m_lo[c] && g[c] < 0.0) || (s.x[c] >= m_hi[c] && g[c] > 0.0);
            for (int c = 0; c < 3; ++c)
                if (held[c])
                    j[c] = glm::dvec3(0.0);
            glm::dmat3 jtj = glm::transpose(j) * j;
            const double trace = jtj[0][0] + jtj[1][1] + jtj[2][2];
            if (!(trace > 0.0))
                break; // A is flat here in every free direction: a stationary point
            const double mu = std::max(lambda, 1e-12) * trace / 3.0;
            for (int c = 0; c < 3; ++c)
                jtj[c][c] += held[c] ? 1.0 : mu;
            const glm::dvec3 gf = glm::transpose(j) * r;
            const glm::dvec3 delta = glm::inverse(jtj) * gf;
            bool accepted = false;
            double step = 1.0;
            for (int k = 0; k < 12 && !accepted; ++k, step *= 0.5) {
                const Sol n = at(clampX(s.x + step * delta), y);
                if (n.err2 < s.err2) {
                    accepted = n.err2 < s.err2 * (1.0 - 1e-12) || maxAbs(n.x - s.x) > 1e-12;
                    s = n;
                    if (!accepted)
                        return s; // no measurable progress: converged as far as it goes
                }
            }
            if (accepted)
                lambda = lambda / 4.0;
            else if (lambda < 1e6)
                lambda = std::max(lambda * 10.0, 1e-3);
            else
                break;
        }
        return s;
    }

    detail::TetraEval m_f;
    const InvertOptions& m_o;
    glm::dvec3 m_lo, m_hi;
    std::array<std::optional<detail::PiecewiseLinearInverse>, 3> m_diag;
    std::vector<glm::dvec3> m_gridIn, m_gridOut;
};

struct ReportAcc {
    std::size_t points = 0, unreachable = 0, leastSquares = 0;
    RegionCounts regions{};
    std::vector<UnreachedPoint> worst;
    double maxResidual = 0.0, sumResidual = 0.0;

    void keepWorst(const UnreachedPoint& p) {
        worst.push_back(p);
        std::sort(worst.begin(), worst.end(), [](const UnreachedPoint& a, const UnreachedPoint& b) {
            return a.residual > b.residual;
        });
        if (worst.size() > kWorstKept)
            worst.resize(kWorstKept);
    }
    void merge(const ReportAcc& o) {
        points += o.points;
        unreachable += o.unreachable;
        leastSquares += o.leastSquares;
        for (std::size_t i = 0; i < regions.size(); ++i)
            regions[i] += o.regions[i];
        for (const auto& p : o.worst)
            keepWorst(p);
        maxResidual = std::max(maxResidual, o.maxResidual);
        sumResidual += o.sumResidual;
    }
};

// Cells of A with a tetrahedron whose Jacobian determinant is <= 0 (flat or folded): there A is
// not one-to-one. The six tetrahedra of a cell are the six axis orders of the path c000 -> c111.
std::size_t countFoldedCells(const Lut3D& a, int nthreads) {
    const int n = a.size(), cells = n - 1;
    // Relative to the identity's cell (a step of h per axis, determinant h^3).
    const double h = 1.0 / cells, eps = 1e-9 * h * h * h;
    std::mutex mutex;
    std::size_t total = 0;
    static constexpr int kOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                          {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    parallelFor(cells, cells < 16 ? 1 : nthreads, [&](int b0, int b1) {
        std::size_t count = 0;
        for (int b = b0; b < b1; ++b)
            for (int g = 0; g < cells; ++g)
                for (int r = 0; r < cells; ++r) {
                    bool folded = false;
                    for (const auto& order : kOrders) {
                        int c[3] = {r, g, b};
                        glm::dvec3 prev(a.at(c[0], c[1], c[2]));
                        glm::dmat3 j;
                        for (int k = 0; k < 3; ++k) {
                            ++c[order[k]];
                            const glm::dvec3 next(a.at(c[0], c[1], c[2]));
                            j[order[k]] = next - prev;
                            prev = next;
                        }
                        if (!(glm::determinant(j) > eps)) {
                            folded = true;
                            break;
                        }
                    }
                    count += folded;
                }
        std::lock_guard lock(mutex);
        total += count;
    });
    return total;
}

} // namespace

InvertResult invert(const Lut3D& source, const InvertOptions& options) {
    if (source.empty())
        throw Error("invert: the LUT has no entries");
    const long long t0 = detail::nowNanos();
    InvertOptions o = options;
    if (!(o.tolerance > 0.0))
        o.tolerance = 1e-5;
    o.maxIterations = std::clamp(o.maxIterations, 1, 1000);
    InvertResult result;
    InvertReport& rep = result.report;
    const Lut3D a = detail::sanitizedCopy(source, rep.sanitizedEntries);
    const int m = o.size > 0 ? o.size : a.size();
    result.lut = Lut3D(m);
    glm::vec3 lo = a.domainMin(), hi = a.domainMax();
    if (o.outputRangeDomain) {
        glm::vec3 emin(INFINITY), emax(-INFINITY);
        for (const auto& e : a.entries()) {
            emin = glm::min(emin, e);
            emax = glm::max(emax, e);
        }
        for (int c = 0; c < 3; ++c)
            if (emin[c] < emax[c]) {
                lo[c] = emin[c];
                hi[c] = emax[c];
            }
    }
    result.lut.setDomain(lo, hi);
    result.lut.setTitle(source.title().empty() ? "inverse" : "inverse of " + source.title());

    const Solver solver(a, o);
    std::mutex mutex;
    ReportAcc total;
    // One task per row (g, b); along a row each point starts from its neighbour's solution, so
    // the result does not depend on how rows are shared between threads.
    parallelForDynamic(m * m, o.nthreads, 8, [&](int row0, int row1) {
        ReportAcc acc;
        for (int row = row0; row < row1; ++row) {
            const int g = row % m, b = row / m;
            std::optional<glm::dvec3> previous;
            for (int r = 0; r < m; ++r) {
                const glm::vec3 p = result.lut.latticeInput(r, g, b);
                const glm::vec3 target = o.targetOf ? glm::vec3(o.targetOf(glm::dvec3(p))) : p;
                bool usedLs = false;
                const Sol s = solver.solve(glm::dvec3(target), previous, usedLs);
                previous = s.x;
                const glm::vec3 x(s.x);
                result.lut.at(r, g, b) = x;
                const double residual = maxAbs(s.fx - glm::dvec3(target));
                ++acc.points;
                acc.leastSquares += usedLs;
                acc.sumResidual += residual;
                acc.maxResidual = std::max(acc.maxResidual, residual);
                if (residual > o.tolerance) {
                    ++acc.unreachable;
                    const RegionOf where = classifyRegion((target - lo) / (hi - lo));
                    ++acc.regions[static_cast<std::size_t>(where.tone)];
                    ++acc.regions[static_cast<std::size_t>(where.hue)];
                    acc.keepWorst({target, x, glm::vec3(s.fx), residual});
                }
            }
        }
        std::lock_guard lock(mutex);
        total.merge(acc);
    });
    rep.points = total.points;
    rep.unreachable = total.unreachable;
    rep.leastSquares = total.leastSquares;
    rep.unreachableByRegion = total.regions;
    rep.worst = total.worst;
    rep.maxResidual = total.maxResidual;
    rep.meanResidual = total.points ? total.sumResidual / static_cast<double>(total.points) : 0.0;
    rep.foldedCells = countFoldedCells(a, o.nthreads);
    rep.seconds = detail::secondsSince(t0);
    if (o.targetOf)
        return result;

    const auto fa = makeSampler(a, Interpolation::Tetrahedral);
    const auto fi = makeSampler(result.lut, Interpolation::Tetrahedral);
    // Both measured where nothing was solved: between the lattice points, with the slope term.
    BoundOptions bo;
    bo.lo = glm::dvec3(result.lut.domainMin());
    bo.hi = glm::dvec3(result.lut.domainMax());
    bo.cells = m - 1;
    bo.nthreads = o.nthreads;
    rep.residual = boundError(
        [&](const glm::dvec3* in, glm::dvec3* diff, std::size_t count) {
            for (std::size_t i = 0; i < count; ++i)
                diff[i] = glm::dvec3(fa->sample(fi->sample(glm::vec3(in[i])))) - in[i];
        },
        bo);
    bo.lo = glm::dvec3(a.domainMin());
    bo.hi = glm::dvec3(a.domainMax());
    bo.cells = a.size() - 1;
    bo.breaks = latticeBreaks(result.lut, Interpolation::Tetrahedral);
    rep.roundTrip = boundError(
        [&](const glm::dvec3* in, glm::dvec3* diff, std::size_t count) {
            for (std::size_t i = 0; i < count; ++i)
                diff[i] = glm::dvec3(fi->sample(fa->sample(glm::vec3(in[i])))) - in[i];
        },
        bo);
    return result;
}

} // namespace lut
