#pragma once
#include <cstddef>
#include <string>

namespace lut {

// How far one set of values is from a reference: the measure every lossy step reports.
struct ErrorStats {
    double maxAbs = 0.0;   // largest absolute difference over all channels
    double meanAbs = 0.0;  // mean absolute difference over all channels
    std::size_t count = 0; // number of channel values compared
    double seconds = 0.0;  // what the step cost, when the producer timed it

    double maxSteps8() const { return maxAbs * 255.0; }
    double meanSteps8() const { return meanAbs * 255.0; }
    // "max 1.2e-03 (0.31 8-bit steps), mean 3.4e-04 (0.087 steps), 12.3 ms"
    std::string str() const;
};

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
