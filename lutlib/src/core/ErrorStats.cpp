#include "lut/ErrorStats.h"

#include <cmath>
#include <cstdio>

namespace lut {

std::string ErrorStats::str() const {
    char buf[160];
    std::snprintf(buf, sizeof buf, "max %.3g (%.3g 8-bit steps), mean %.3g (%.3g steps)", maxAbs,
                  maxSteps8(), meanAbs, meanSteps8());
    std::string s = buf;
    if (seconds > 0) {
        std::snprintf(buf, sizeof buf, ", %.3g ms", seconds * 1e3);
        s += buf;
    }
    return s;
}

void ErrorAccumulator::add(double a, double b) {
    double d = std::fabs(a - b);
    if (std::isnan(d))
        d = (std::isnan(a) && std::isnan(b)) ? 0.0 : INFINITY;
    if (d > m_max)
        m_max = d;
    m_sum += d;
    ++m_count;
}

void ErrorAccumulator::merge(const ErrorAccumulator& other) {
    if (other.m_max > m_max)
        m_max = other.m_max;
    m_sum += other.m_sum;
    m_count += other.m_count;
}

ErrorStats ErrorAccumulator::result() const {
    ErrorStats s;
    s.maxAbs = m_max;
    s.meanAbs = m_count ? m_sum / static_cast<double>(m_count) : 0.0;
    s.count = m_count;
    return s;
}

} // namespace lut
