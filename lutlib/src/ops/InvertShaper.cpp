// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/InvertShaper.h"

#include "lut/Error.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/ErrorBound.h"
#include "ops/OpsDetail.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

namespace lut {

namespace {

// d_c(t) = A(t, t, t)_c: linear between the diagonal's lattice points (the tetrahedra along
// the main diagonal share that edge).
struct Diagonal {
    std::array<std::vector<double>, 3> x, y;
    double operator()(int c, double t) const {
        const auto& xs = x[static_cast<std::size_t>(c)];
        const auto& ys = y[static_cast<std::size_t>(c)];
        if (t <= xs.front())
            return ys.front();
        if (t >= xs.back())
            return ys.back();
        const auto k =
            static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), t) - xs.begin() - 1);
        const double f = (t - xs[k]) / (xs[k + 1] - xs[k]);
        return ys[k] + (ys[k + 1] - ys[k]) * f;
    }
};

// The shaper's own sampling error, which a grid over the whole box steps over (it lives within
// one of its 4096 entries, at the kinks of the exact curve between them): per channel, the exact
// largest |S_c(y) - dinv_c(y)| (both piecewise linear: at the union of their breakpoints), per
// cell of the table it lands in, times the steepest change per unit u of `g` along that axis
// over the cell and its neighbours (g: the table, or A after it), summed over the channels.
double shaperTerm(const Lut1D& shaper, const Diagonal& d,
                  const std::vector<std::unique_ptr<detail::PiecewiseLinearInverse>>& inv,
                  glm::dvec3 alo, glm::dvec3 ahi, const Lut3D& table,
                  const std::function<glm::dvec3(glm::vec3)>& g) {
    const int m = table.size(), s = shaper.size();
    const double L = shaper.domainMin().x, H = shaper.domainMax().x;
    double total = 0.0;
    for (int c = 0; c < 3; ++c) {
        std::vector<double> ys;
        for (int i = 0; i < s; ++i)
            ys.push_back(L + (H - L) * (static_cast<double>(i) / (s - 1)));
        for (const double y : d.y[static_cast<std::size_t>(c)])
            if (y > L && y < H)
                ys.push_back(y);
        std::sort(ys.begin(), ys.end());
        std::vector<double> e(static_cast<std::size_t>(m - 1), 0.0);
        auto cellOf = [&](double u) { return std::clamp(static_cast<int>(u * (m - 1)), 0, m - 2); };
        double prevE = 0.0;
        int prevCell = 0;
        for (std::size_t j = 0; j < ys.size(); ++j) {
            const double f = (ys[j] - L) / (H - L) * (s - 1);
            const int i0 = std::clamp(static_cast<int>(f), 0, s - 2);
            const double sv = shaper[i0][c] + (shaper[i0 + 1][c] - shaper[i0][c]) * (f - i0);
            const double u = std::clamp(((*inv[static_cast<std::size_t>(c)])(ys[j]).x - alo[c]) /
                                            (ahi[c] - alo[c]),
                                        0.0, 1.0);
            const double err = std::fabs(sv - u);
            const int cell = cellOf(u);
            const double segment = j ? std::max(err, prevE) : err;
            for (int k = std::min(cell, j ? prevCell : cell); k <= std::max(cell, prevCell); ++k)
                e[static_cast<std::size_t>(k)] = std::max(e[static_cast<std::size_t>(k)], segment);
            prevE = err;
            prevCell = cell;
        }
        // the steepest change of g along c per cell
        std::vector<double> slope(static_cast<std::size_t>(m - 1), 0.0);
        for (int a = 0; a < m; ++a)
            for (int b = 0; b < m; ++b)
                for (int k = 0; k + 1 < m; ++k) {
                    int p[3] = {0, 0, 0}, q[3];
                    p[c] = k;
                    p[(c + 1) % 3] = a;
                    p[(c + 2) % 3] = b;
                    std::copy(p, p + 3, q);
                    ++q[c];
                    const glm::dvec3 dv = g(table.latticeInput(q[0], q[1], q[2])) -
                                          g(table.latticeInput(p[0], p[1], p[2]));
                    const double v = std::max({std::fabs(dv.x), std::fabs(dv.y), std::fabs(dv.z)});
                    slope[static_cast<std::size_t>(k)] =
                        std::max(slope[static_cast<std::size_t>(k)], v * (m - 1));
                }
        double worst = 0.0;
        for (int k = 0; k + 1 < m; ++k) {
            double sl = 0.0;
            for (int j = std::max(k - 1, 0); j <= std::min(k + 1, m - 2); ++j)
                sl = std::max(sl, slope[static_cast<std::size_t>(j)]);
            worst = std::max(worst, e[static_cast<std::size_t>(k)] * sl);
        }
        total += worst;
    }
    return total;
}

} // namespace

ShaperInvertResult invertWithShaper(const Lut3D& a, const InvertOptions& options, int shaperSize) {
    if (a.empty())
        throw Error("invert: the LUT has no entries");
    ShaperInvertResult out;
    const int n = a.size();
    Diagonal d;
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < n; ++k) {
            const double y = detail::sanitizeValue(a.at(k, k, k)[c]);
            auto& ys = d.y[static_cast<std::size_t>(c)];
            if (!ys.empty() && !(y > ys.back()))
                return out; // flat or falling: no shaper
            ys.push_back(y);
            d.x[static_cast<std::size_t>(c)].push_back(a.latticeInput(k, k, k)[c]);
        }
    const glm::dvec3 alo(a.domainMin()), ahi(a.domainMax());

    // The inverse's domain, as lut::invert places it; one range for the shaper (a Resolve
    // .cube has one LUT_1D_INPUT_RANGE).
    glm::dvec3 lo = alo, hi = ahi;
    if (options.outputRangeDomain) {
        glm::dvec3 emin(INFINITY), emax(-INFINITY);
        for (const auto& e : a.entries()) {
            emin = glm::min(emin, glm::dvec3(e));
            emax = glm::max(emax, glm::dvec3(e));
        }
        for (int c = 0; c < 3; ++c)
            if (emin[c] < emax[c]) {
                lo[c] = emin[c];
                hi[c] = emax[c];
            }
    }
    const double L = std::min({lo.x, lo.y, lo.z}), H = std::max({hi.x, hi.y, hi.z});
    const int s = std::max(shaperSize, 2);
    Lut1D shaper(s);
    shaper.setDomain(glm::vec3(static_cast<float>(L)), glm::vec3(static_cast<float>(H)));
    std::vector<std::unique_ptr<detail::PiecewiseLinearInverse>> inv;
    for (int c = 0; c < 3; ++c)
        inv.push_back(std::make_unique<detail::PiecewiseLinearInverse>(
            d.x[static_cast<std::size_t>(c)], d.y[static_cast<std::size_t>(c)]));
    for (int i = 0; i < s; ++i) {
        const double y = L + (H - L) * (static_cast<double>(i) / (s - 1));
        for (int c = 0; c < 3; ++c) {
            const double t = (*inv[static_cast<std::size_t>(c)])(y).x;
            shaper[i][c] =
                static_cast<float>(std::clamp((t - alo[c]) / (ahi[c] - alo[c]), 0.0, 1.0));
        }
    }

    // The table: at lattice input p (over the inverse's domain, renamed [0, 1] after), u the
    // fraction, the x with A(x) = d(u).
    InvertOptions o = options;
    o.outputRangeDomain = false;
    o.targetOf = [&](glm::dvec3 p) {
        glm::dvec3 y;
        for (int c = 0; c < 3; ++c)
            y[c] = d(c, p[c]); // p = alo + u (ahi - alo): the diagonal at the same fraction
        return y;
    };
    InvertResult table = invert(a, o);
    table.lut.setDomain(glm::vec3(0.0f), glm::vec3(1.0f));
    table.lut.setTitle({});
    out.report = std::move(table.report);
    out.lut.shaper = std::move(shaper);
    out.lut.cube = std::move(table.lut);
    out.made = true;

    const auto fa = makeSampler(a, Interpolation::Tetrahedral);
    const auto fi = makeSampler(out.lut, Interpolation::Tetrahedral);
    // Both measured between the points solved, the table's planes (in y: where the shaper
    // reaches them) among the grid's breaks.
    const int m = out.lut.cube->size();
    BoundOptions bo;
    bo.lo = lo;
    bo.hi = hi;
    bo.cells = m - 1;
    bo.nthreads = options.nthreads;
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k <= m - 1; ++k)
            bo.breaks[static_cast<std::size_t>(c)].push_back(
                d(c, alo[c] + (ahi[c] - alo[c]) * k / (m - 1)));
    out.report.residual = boundError(
        [&](const glm::dvec3* in, glm::dvec3* diff, std::size_t count) {
            for (std::size_t i = 0; i < count; ++i)
                diff[i] = glm::dvec3(fa->sample(fi->sample(glm::vec3(in[i])))) - in[i];
        },
        bo);
    bo.lo = alo;
    bo.hi = ahi;
    bo.cells = n - 1;
    bo.breaks = {};
    out.report.roundTrip = boundError(
        [&](const glm::dvec3* in, glm::dvec3* diff, std::size_t count) {
            for (std::size_t i = 0; i < count; ++i)
                diff[i] = glm::dvec3(fi->sample(fa->sample(glm::vec3(in[i])))) - in[i];
        },
        bo);
    // Plus what the shaper's sampling adds where the grid did not look (the table's entries
    // through A for the residual, the table itself for the round trip).
    const Lut3D& t = *out.lut.cube;
    const auto entryAt = [&](glm::vec3 u) {
        const glm::ivec3 k = glm::ivec3(glm::round(u * static_cast<float>(m - 1)));
        return glm::dvec3(t.at(k.x, k.y, k.z));
    };
    out.report.residual.maxAbs +=
        shaperTerm(*out.lut.shaper, d, inv, alo, ahi, t,
                   [&](glm::vec3 u) { return glm::dvec3(fa->sample(glm::vec3(entryAt(u)))); });
    out.report.roundTrip.maxAbs += shaperTerm(*out.lut.shaper, d, inv, alo, ahi, t, entryAt);
    return out;
}

} // namespace lut
