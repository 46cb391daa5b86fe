// SPDX-License-Identifier: Apache-2.0
// Display error summaries; see lut/smash/GameError.h.
#include "lut/smash/GameError.h"

#include "lut/ErrorStats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace lut {

std::string GameError::str() const {
    char buf[160];
    // max and p99 rounded up: rounded to nearest, a bound could print below the truth
    std::snprintf(buf, sizeof buf, "max %.2f, mean %.3f, p99 %.2f 8-bit steps",
                  roundUpDecimals(maxSteps, 2), meanSteps, roundUpDecimals(p99Steps, 2));
    return buf;
}

GameError GameError::worst(const GameError& a, const GameError& b) {
    GameError w;
    w.maxSteps = std::max(a.maxSteps, b.maxSteps);
    w.meanSteps = std::max(a.meanSteps, b.meanSteps);
    w.p99Steps = std::max(a.p99Steps, b.p99Steps);
    w.count = std::max(a.count, b.count);
    return w;
}

GameError summariseSteps(std::vector<double>& steps) {
    GameError e;
    e.count = steps.size();
    if (steps.empty())
        return e;
    double sum = 0.0;
    for (double& v : steps) {
        if (!(v == v))
            v = std::numeric_limits<double>::infinity();
        v = std::fabs(v);
        sum += v;
        e.maxSteps = std::max(e.maxSteps, v);
    }
    e.meanSteps = sum / static_cast<double>(steps.size());
    const std::size_t k =
        std::min(steps.size() - 1, static_cast<std::size_t>(std::ceil(0.99 * steps.size())) - 1);
    std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(k), steps.end());
    e.p99Steps = steps[k];
    return e;
}

GameError summariseWeightedSteps(std::vector<std::pair<double, double>>& steps) {
    GameError e;
    e.count = steps.size();
    if (steps.empty())
        return e;
    double sum = 0.0, weights = 0.0;
    for (auto& [v, w] : steps) {
        if (!(v == v))
            v = std::numeric_limits<double>::infinity();
        v = std::fabs(v);
        sum += v * w;
        weights += w;
        e.maxSteps = std::max(e.maxSteps, v);
    }
    e.meanSteps = weights > 0.0 ? sum / weights : 0.0;
    std::sort(steps.begin(), steps.end());
    double below = 0.0;
    e.p99Steps = steps.back().first;
    for (const auto& [v, w] : steps) {
        below += w;
        if (below >= 0.99 * weights) {
            e.p99Steps = v;
            break;
        }
    }
    return e;
}

} // namespace lut
