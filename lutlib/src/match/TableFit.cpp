// SPDX-License-Identifier: Apache-2.0
// A table's values fitted to a transfer over the source's colours: see match/TableFit.h.
#include "match/TableFit.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lut::detail {

namespace {

struct Corners {
    std::array<std::uint32_t, 4> index;
    std::array<double, 4> weight;
};

// The standard tetrahedral split (interp/Tetrahedral.h): c000, the max-axis vertex, c111 minus
// the min-axis vertex, c111; weights the differences of the sorted fractions.
Corners corners(const glm::vec3& x, const glm::dvec3& lo, const glm::dvec3& hi, int n) {
    double f[3];
    std::uint32_t base = 0;
    const std::uint32_t stride[3] = {1u, static_cast<std::uint32_t>(n),
                                     static_cast<std::uint32_t>(n * n)};
    for (int c = 0; c < 3; ++c) {
        double q = (x[c] - lo[c]) / (hi[c] - lo[c]) * (n - 1);
        q = std::clamp(std::isfinite(q) ? q : 0.0, 0.0, static_cast<double>(n - 1));
        const int i = std::min(static_cast<int>(q), n - 2);
        f[c] = q - i;
        base += static_cast<std::uint32_t>(i) * stride[c];
    }
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int a, int b) { return f[a] > f[b]; });
    Corners k;
    k.index[0] = base;
    k.weight[0] = 1.0 - f[order[0]];
    std::uint32_t offset = 0;
    for (int j = 0; j < 3; ++j) {
        offset += stride[order[j]];
        k.index[static_cast<std::size_t>(j + 1)] = base + offset;
        k.weight[static_cast<std::size_t>(j + 1)] = f[order[j]] - (j < 2 ? f[order[j + 1]] : 0.0);
    }
    return k;
}

} // namespace

void fitTableToColours(Lut3D& table, const std::vector<glm::vec3>& colours,
                       const std::vector<std::uint32_t>& counts,
                       const std::vector<glm::dvec3>& wanted) {
    const int n = table.size();
    const std::size_t nodes = table.entries().size();
    if (colours.empty() || n < 2)
        return;
    const glm::dvec3 lo(table.domainMin()), hi(table.domainMax());
    std::vector<Corners> k(colours.size());
    double meanCount = 0.0;
    for (std::size_t i = 0; i < colours.size(); ++i) {
        k[i] = corners(colours[i], lo, hi, n);
        meanCount += counts[i];
    }
    meanCount /= static_cast<double>(colours.size());
    const double lambda = 1e-3 * meanCount;
    std::vector<double> x(nodes), b(nodes), r(nodes), p(nodes), ap(nodes), x0(nodes);
    auto normal = [&](const std::vector<double>& v, std::vector<double>& out) {
        for (std::size_t j = 0; j < nodes; ++j)
            out[j] = lambda * v[j];
        for (std::size_t i = 0; i < k.size(); ++i) {
            double a = 0.0;
            for (int c = 0; c < 4; ++c)
                a += k[i].weight[static_cast<std::size_t>(c)] *
                     v[k[i].index[static_cast<std::size_t>(c)]];
            a *= counts[i];
            for (int c = 0; c < 4; ++c)
                out[k[i].index[static_cast<std::size_t>(c)]] +=
                    k[i].weight[static_cast<std::size_t>(c)] * a;
        }
    };
    auto& entries = table.entries();
    for (int c = 0; c < 3; ++c) {
        for (std::size_t j = 0; j < nodes; ++j)
            x0[j] = x[j] = entries[j][c];
        for (std::size_t j = 0; j < nodes; ++j)
            b[j] = lambda * x0[j];
        for (std::size_t i = 0; i < k.size(); ++i)
            for (int v = 0; v < 4; ++v)
                b[k[i].index[static_cast<std::size_t>(v)]] +=
                    k[i].weight[static_cast<std::size_t>(v)] * counts[i] * wanted[i][c];
        normal(x, ap);
        double bb = 0.0, rs = 0.0;
        for (std::size_t j = 0; j < nodes; ++j) {
            r[j] = b[j] - ap[j];
            p[j] = r[j];
            rs += r[j] * r[j];
            bb += b[j] * b[j];
        }
        for (int it = 0; it < 40 && rs > 1e-14 * bb; ++it) {
            normal(p, ap);
            double pap = 0.0;
            for (std::size_t j = 0; j < nodes; ++j)
                pap += p[j] * ap[j];
            if (!(pap > 0.0))
                break;
            const double alpha = rs / pap;
            double next = 0.0;
            for (std::size_t j = 0; j < nodes; ++j) {
                x[j] += alpha * p[j];
                r[j] -= alpha * ap[j];
                next += r[j] * r[j];
            }
            for (std::size_t j = 0; j < nodes; ++j)
                p[j] = r[j] + next / rs * p[j];
            rs = next;
        }
        // No overshoot beyond the colours the table is asked for (an 8-bit output would clip it).
        double yLo = INFINITY, yHi = -INFINITY;
        for (const auto& y : wanted) {
            yLo = std::min(yLo, y[c]);
            yHi = std::max(yHi, y[c]);
        }
        for (std::size_t j = 0; j < nodes; ++j)
            entries[j][c] =
                static_cast<float>(std::clamp(x[j], std::min(yLo, x0[j]), std::max(yHi, x0[j])));
    }
}

} // namespace lut::detail
