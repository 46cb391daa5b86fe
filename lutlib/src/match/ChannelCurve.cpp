// SPDX-License-Identifier: Apache-2.0
#include "lut/match/ChannelCurve.h"

#include "lut/Error.h"

#include <algorithm>
#include <cmath>

namespace lut {

ChannelCurve::ChannelCurve(double x0, double x1, std::vector<double> values, double slopeBelow,
                           double slopeAbove)
    : m_x0(x0), m_x1(x1), m_values(std::move(values)), m_slopeBelow(slopeBelow),
      m_slopeAbove(slopeAbove) {
    if (m_values.size() < 2 || !(x0 < x1) || !std::isfinite(x0) || !std::isfinite(x1))
        throw Error("channel curve: needs 2 or more knots over a finite x0 < x1");
    for (double v : m_values)
        if (!std::isfinite(v))
            throw Error("channel curve: a knot value is not finite");
    if (!std::isfinite(slopeBelow) || !std::isfinite(slopeAbove))
        throw Error("channel curve: an end slope is not finite");
    m_step = (x1 - x0) / static_cast<double>(m_values.size() - 1);
}

ChannelCurve ChannelCurve::identity(double x0, double x1) {
    return ChannelCurve(x0, x1, {x0, x1}, 1.0, 1.0);
}

double ChannelCurve::operator()(double x) const {
    if (m_values.empty())
        return x;
    if (!(x > m_x0)) // NaN lands here too: the first knot
        return std::isnan(x) ? m_values.front() : m_values.front() + m_slopeBelow * (x - m_x0);
    if (x >= m_x1)
        return m_values.back() + m_slopeAbove * (x - m_x1);
    const double pos = (x - m_x0) / m_step;
    const std::size_t k = std::min(static_cast<std::size_t>(pos), m_values.size() - 2);
    const double t = pos - static_cast<double>(k);
    return m_values[k] + (m_values[k + 1] - m_values[k]) * t;
}

double ChannelCurve::inverse(double y) const {
    if (m_values.empty())
        return y;
    if (std::isnan(y))
        return m_x0;
    if (y <= m_values.front())
        return m_slopeBelow > 0.0 ? m_x0 + (y - m_values.front()) / m_slopeBelow : m_x0;
    if (y >= m_values.back())
        return m_slopeAbove > 0.0 ? m_x1 + (y - m_values.back()) / m_slopeAbove : m_x1;
    // first knot whose value is >= y
    const auto it = std::lower_bound(m_values.begin(), m_values.end(), y);
    const std::size_t k = static_cast<std::size_t>(it - m_values.begin());
    if (k == 0)
        return m_x0;
    const double a = m_values[k - 1], b = m_values[k];
    const double t = b > a ? (y - a) / (b - a) : 0.0;
    return m_x0 + (static_cast<double>(k - 1) + t) * m_step;
}

double ChannelCurve::minSlope() const {
    double s = std::min(m_slopeBelow, m_slopeAbove);
    for (std::size_t k = 0; k + 1 < m_values.size(); ++k)
        s = std::min(s, (m_values[k + 1] - m_values[k]) / m_step);
    return s;
}

double ChannelCurve::maxSlope() const {
    double s = std::max(m_slopeBelow, m_slopeAbove);
    for (std::size_t k = 0; k + 1 < m_values.size(); ++k)
        s = std::max(s, (m_values[k + 1] - m_values[k]) / m_step);
    return s;
}

} // namespace lut
