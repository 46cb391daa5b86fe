// SPDX-License-Identifier: Apache-2.0
#pragma once
// A monotone 1D curve: the per-channel part of a colour match (histogram matching), sampled on
// uniformly spaced knots and continued linearly beyond them.
//
//   y(x) = values[k] + (values[k+1] - values[k]) * t    x = x0 + (k + t) * step, t in [0, 1]
//   y(x) = values.front() + slopeBelow * (x - x0)       x < x0
//   y(x) = values.back()  + slopeAbove * (x - x1)       x > x1
//
// The curves lutkit builds are strictly increasing (every knot slope >= a positive minimum), so
// they have an inverse, and never produce NaN from a finite input.
#include <vector>

namespace lut {

class ChannelCurve {
public:
    ChannelCurve() = default;
    // Knots at x0 + k * (x1 - x0) / (values.size() - 1); at least 2 values, x0 < x1, finite.
    // Throws lut::Error otherwise.
    ChannelCurve(double x0, double x1, std::vector<double> values, double slopeBelow,
                 double slopeAbove);
    static ChannelCurve identity(double x0 = 0.0, double x1 = 1.0);

    bool empty() const { return m_values.empty(); }
    double x0() const { return m_x0; }
    double x1() const { return m_x1; }
    double step() const { return m_step; }
    const std::vector<double>& values() const { return m_values; }
    double slopeBelow() const { return m_slopeBelow; }
    double slopeAbove() const { return m_slopeAbove; }

    double operator()(double x) const;
    // The x with y(x) = y, for a strictly increasing curve (the first such x where it is flat).
    double inverse(double y) const;
    // Smallest and largest slope between knots (the extension slopes included).
    double minSlope() const;
    double maxSlope() const;

private:
    double m_x0 = 0.0, m_x1 = 1.0, m_step = 1.0;
    std::vector<double> m_values;
    double m_slopeBelow = 1.0, m_slopeAbove = 1.0;
};

} // namespace lut
