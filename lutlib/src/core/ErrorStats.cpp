// SPDX-License-Identifier: Apache-2.0
#include "lut/ErrorStats.h"
#include "lut/Math.h"

#include <cmath>
#include <cstdio>

namespace lut {

double roundUpSignificant(double v, int digits) {
    if (!(v > 0.0) || !std::isfinite(v))
        return v;
    const double scale = lut::math::pow(10.0, std::floor(lut::math::log10(v)) - (digits - 1));
    const double up = std::ceil(v / scale) * scale;
    return up < v ? std::nextafter(up, INFINITY) : up;
}

double roundUpDecimals(double v, int decimals) {
    if (!(v > 0.0) || !std::isfinite(v))
        return v;
    const double scale = lut::math::pow(10.0, decimals);
    const double up = std::ceil(v * scale) / scale;
    return up < v ? std::nextafter(up, INFINITY) : up;
}

std::string ErrorStats::str() const {
    char buf[160];
    // The maximum is printed rounded up: rounded to nearest, a bound could print below the truth.
    std::snprintf(buf, sizeof buf, "max %.3g (%.3g 8-bit steps), mean %.3g (%.3g steps)",
                  roundUpSignificant(maxAbs), roundUpSignificant(maxSteps8()), meanAbs,
                  meanSteps8());
    std::string s = buf;
    if (seconds > 0) {
        std::snprintf(buf, sizeof buf, ", %.3g ms", seconds * 1e3);
        s += buf;
    }
    return s;
}

std::string ErrorStats::coverage() const {
    if (!bounded)
        return {};
    if (heldOutPoints == 0)
        return "the exact maximum over every input";
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "a bound over every input (%.3g steps seen at %zu points between the lattice "
                  "points%s)",
                  sampledMax * 255.0, heldOutPoints,
                  maxAbs > sampledMax ? ", plus the slope between them" : "");
    return buf;
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
