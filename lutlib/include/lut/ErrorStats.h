// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <cstddef>
#include <string>

namespace lut {

// How far one set of values is from a reference: the measure every lossy step reports.
struct ErrorStats {
    // The largest absolute difference over all channels; with `bounded`, an upper bound of it
    // over every input of the domain, not only the values compared (lut/ops/ErrorBound.h).
    double maxAbs = 0.0;
    double meanAbs = 0.0;  // mean absolute difference over all channels
    std::size_t count = 0; // number of channel values compared
    double seconds = 0.0;  // what the step cost, when the producer timed it
    bool bounded = false;
    // With `bounded`: the largest difference seen at the held-out points (maxAbs adds the slope
    // between them; equal when the maximum is exact), and how many points there were (0: the
    // maximum is exact, found where it is attained).
    double sampledMax = 0.0;
    std::size_t heldOutPoints = 0;

    double maxSteps8() const { return maxAbs * 255.0; }
    double meanSteps8() const { return meanAbs * 255.0; }
    // "max 1.2e-03 (0.31 8-bit steps), mean 3.4e-04 (0.087 steps), 12.3 ms"
    std::string str() const;
    // What maxAbs covers, for a bounded figure: "a bound over every input (0.29 steps seen at
    // 2146689 points between the lattice points, plus the slope between them)", "the exact
    // maximum over every input" ("" when not bounded).
    std::string coverage() const;
};

// v rounded up to `digits` significant digits (a printed bound must not round below the truth).
double roundUpSignificant(double v, int digits = 3);
// v rounded up to `decimals` decimal places.
double roundUpDecimals(double v, int decimals);

// Accumulates |a - b| over values; NaN differences count as infinite error.
class ErrorAccumulator {
public:
    void add(double a, double b);
    // Folds in another accumulator (e.g. one thread's share of the values).
    void merge(const ErrorAccumulator& other);
    ErrorStats result() const;

private:
    double m_max = 0.0;
    double m_sum = 0.0;
    std::size_t m_count = 0;
};

} // namespace lut
