// SPDX-License-Identifier: Apache-2.0
#pragma once
// How far what the game shows is from what it should show, in 8-bit display steps: the measure
// the Smash authoring functions (lut/smash/SmashAuthoring.h) and the round trip report.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace lut {

struct GameError {
    double maxSteps = 0.0;
    double meanSteps = 0.0;
    double p99Steps = 0.0; // 99% of the channel values are this close or closer
    std::size_t count = 0; // channel values compared
    // "max 1.23, mean 0.214, p99 0.88 8-bit steps"
    std::string str() const;
    // Per-field maximum (for bounds made of several estimates).
    static GameError worst(const GameError& a, const GameError& b);
};

// Summarises absolute errors given in 8-bit steps (the vector is reordered). NaN counts as
// infinite.
GameError summariseSteps(std::vector<double>& steps);
// The same for values with weights ({steps, weight}; reordered): the weighted mean and 99th
// percentile, the largest value; count = the number of values.
GameError summariseWeightedSteps(std::vector<std::pair<double, double>>& steps);

} // namespace lut
