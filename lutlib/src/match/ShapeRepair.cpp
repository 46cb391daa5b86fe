// SPDX-License-Identifier: Apache-2.0
// A dip along grey repaired on the table: see match/ShapeRepair.h.
#include "match/ShapeRepair.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lut::detail {

namespace {

// The non-decreasing sequence closest to v in least squares (pool adjacent violators).
std::vector<double> isotonic(const std::vector<double>& v) {
    std::vector<double> level, weight;
    std::vector<std::size_t> size;
    for (double x : v) {
        level.push_back(x);
        weight.push_back(1.0);
        size.push_back(1);
        while (level.size() > 1 && level[level.size() - 2] > level.back()) {
            const std::size_t k = level.size() - 2;
            const double w = weight[k] + weight[k + 1];
            level[k] = (level[k] * weight[k] + level[k + 1] * weight[k + 1]) / w;
            weight[k] = w;
            size[k] += size[k + 1];
            level.pop_back();
            weight.pop_back();
            size.pop_back();
        }
    }
    std::vector<double> out;
    for (std::size_t b = 0; b < level.size(); ++b)
        out.insert(out.end(), size[b], level[b]);
    return out;
}

// One round: the diagonal in order, spread to its neighbours, own axes in order again.
GreyRepair repairRound(Lut3D& table) {
    GreyRepair r;
    const int n = table.size();
    // Each channel's move along the diagonal.
    std::vector<glm::dvec3> delta(static_cast<std::size_t>(n), glm::dvec3(0.0));
    std::vector<bool> moved(static_cast<std::size_t>(n), false);
    for (int c = 0; c < 3; ++c) {
        std::vector<double> v(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i)
            v[static_cast<std::size_t>(i)] = table.at(i, i, i)[c];
        const std::vector<double> fixed = isotonic(v);
        for (std::size_t k = 0; k < v.size(); ++k) {
            delta[k][c] = fixed[k] - v[k];
            if (delta[k][c] != 0.0) {
                moved[k] = true;
                r.largestMove = std::max(r.largestMove, std::fabs(delta[k][c]) * 255.0);
            }
        }
    }
    r.nodesMoved = static_cast<int>(std::count(moved.begin(), moved.end(), true));
    if (r.nodesMoved == 0)
        return r;
    // The move spread over the nodes around the diagonal, fading to nothing kRadius nodes away
    // (the diagonal's own nodes take it whole): the nodes next to it move with it, so the
    // repair does not turn a channel's own axis down where the diagonal node alone would.
    constexpr double kRadius = 3.0;
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int rr = 0; rr < n; ++rr) {
                const double t = (rr + g + b) / 3.0;
                const double off =
                    std::max({std::fabs(rr - t), std::fabs(g - t), std::fabs(b - t)});
                const double w = 1.0 - off / kRadius;
                if (w <= 0.0)
                    continue;
                const int i0 = std::min(static_cast<int>(t), n - 2);
                const double f = t - i0;
                const glm::dvec3 d = delta[static_cast<std::size_t>(i0)] * (1.0 - f) +
                                     delta[static_cast<std::size_t>(i0 + 1)] * f;
                table.at(rr, g, b) += glm::vec3(d * w);
            }
    // Where the move met a flat stretch of a channel's own axis, it may turn it down a little:
    // each channel made non-decreasing along its own axis again (pool adjacent violators on
    // every line; a line already in order is left as it is). The diagonal's nodes were raised to
    // at least their neighbours along grey, and pooling only averages a node with its neighbours
    // on a line, so grey stays in order up to round-off (measured after, in the report).
    std::vector<double> line(static_cast<std::size_t>(n));
    for (int c = 0; c < 3; ++c)
        for (int a = 0; a < n; ++a)
            for (int e = 0; e < n; ++e) {
                auto node = [&](int i) -> float& {
                    return c == 0   ? table.at(i, a, e)[0]
                           : c == 1 ? table.at(a, i, e)[1]
                                    : table.at(a, e, i)[2];
                };
                bool ordered = true;
                for (int i = 0; i < n; ++i) {
                    line[static_cast<std::size_t>(i)] = node(i);
                    ordered = ordered && (i == 0 || node(i) >= node(i - 1));
                }
                if (ordered)
                    continue;
                const std::vector<double> fixed = isotonic(line);
                for (int i = 0; i < n; ++i)
                    node(i) = static_cast<float>(fixed[static_cast<std::size_t>(i)]);
            }
    return r;
}

} // namespace

GreyRepair repairGreyDip(Lut3D& table) {
    // Rounds until the diagonal is left in order (alternating projections onto the two orders;
    // 20 at most): the nodes moved and the largest move of all rounds together.
    const std::vector<glm::vec3> before = table.entries();
    GreyRepair total;
    std::vector<bool> moved(static_cast<std::size_t>(table.size()), false);
    for (int round = 0; round < 20; ++round) {
        const GreyRepair r = repairRound(table);
        if (r.nodesMoved == 0)
            break;
    }
    const int n = table.size();
    for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = std::fabs(table.at(i, i, i)[c] - before[table.index(i, i, i)][c]);
            if (d > 0.0) {
                moved[static_cast<std::size_t>(i)] = true;
                total.largestMove = std::max(total.largestMove, d * 255.0);
            }
        }
    total.nodesMoved = static_cast<int>(std::count(moved.begin(), moved.end(), true));
    return total;
}

} // namespace lut::detail
