// SPDX-License-Identifier: Apache-2.0
#pragma once
// A curve through control points for the grading tools (lut/ops/Adjust.h): tone curves (master,
// red, green, blue) and the periodic hue curves (hue vs hue, saturation, luminance).
//
// Interpolation is the monotone piecewise cubic Hermite of Fritsch and Carlson (SIAM J. Numer.
// Anal. 17(2), 1980): secants d_k = (y_k+1 - y_k) / (x_k+1 - x_k); the tangent at an interior point
// is the mean of its two secants, 0 where they differ in sign or one is 0 (an extremum or a flat
// run), and scaled down so (m_k / d_k)^2 + (m_k+1 / d_k)^2 <= 9 on every segment. So each
// segment is monotone between its two points and never leaves their range: no overshoot, a flat
// run stays flat, and points on a line give that line.
//
// Tone curves (x and y in encoded values) need at least 2 points; their end tangents are the end
// secants, and outside [x_first, x_last] the curve continues as a straight line with the end
// tangent (so HDR entries stay defined). No points, or every point on the diagonal (y == x),
// is the identity, which the adjustments skip so the entries stay bit for bit.
//
// Hue curves are periodic with period 360: x is a hue in degrees (wrapped into [0, 360)), y an
// offset whose neutral value is 0 (see Adjust.h for what each curve's y means). One point gives
// a constant; no points, or every y == 0, is neutral.
//
// Points are sorted by x; two points with the same x (after wrapping) or a non-finite coordinate
// throw lut::Error.
#include <glm/vec2.hpp>

#include <vector>

namespace lut {

enum class CurveKind { Tone, Hue };

class Curve {
public:
    explicit Curve(CurveKind kind = CurveKind::Tone) : m_kind(kind) {}
    Curve(CurveKind kind, std::vector<glm::dvec2> points);

    CurveKind kind() const { return m_kind; }
    const std::vector<glm::dvec2>& points() const { return m_points; }
    bool empty() const { return m_points.empty(); }
    // True when the curve changes nothing: identity for a tone curve, 0 for a hue curve.
    bool isNeutral() const;

    // The curve at x (a hue curve takes any x and wraps it). NaN gives the neutral answer
    // (NaN for a tone curve, as the input; 0 for a hue curve).
    double operator()(double x) const;

    bool operator==(const Curve& o) const { return m_kind == o.m_kind && m_points == o.m_points; }

private:
    CurveKind m_kind;
    std::vector<glm::dvec2> m_points;
    std::vector<double> m_tangents;
};

} // namespace lut
