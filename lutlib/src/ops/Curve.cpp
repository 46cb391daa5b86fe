// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Curve.h"

#include "lut/Error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace lut {

namespace {

constexpr double kPeriod = 360.0;

double wrapHue(double h) {
    double w = std::fmod(h, kPeriod);
    if (w < 0.0)
        w += kPeriod;
    return w >= kPeriod ? 0.0 : w; // fmod of a tiny negative can round up to the period
}

// Fritsch-Carlson tangents for secants d (one per segment). Periodic curves have as many
// segments as points (the last one wraps to the first point); open curves one fewer.
std::vector<double> monotoneTangents(const std::vector<double>& d, std::size_t points,
                                     bool periodic) {
    std::vector<double> m(points, 0.0);
    const std::size_t segs = d.size();
    for (std::size_t k = 0; k < points; ++k) {
        const bool hasLeft = periodic || k > 0;
        const bool hasRight = periodic || k + 1 < points;
        const double left = hasLeft ? d[(k + segs - 1) % segs] : 0.0;
        const double right = hasRight ? d[k % segs] : 0.0;
        if (!hasLeft)
            m[k] = right;
        else if (!hasRight)
            m[k] = left;
        else if (left * right <= 0.0)
            m[k] = 0.0;
        else
            m[k] = 0.5 * (left + right);
    }
    // Keep (alpha, beta) inside the circle of radius 3 on every segment: monotone segments.
    for (std::size_t k = 0; k < segs; ++k) {
        const std::size_t k1 = (k + 1) % points;
        if (d[k] == 0.0) {
            m[k] = 0.0;
            m[k1] = 0.0;
            continue;
        }
        const double a = m[k] / d[k], b = m[k1] / d[k];
        const double r = a * a + b * b;
        if (r > 9.0) {
            const double t = 3.0 / std::sqrt(r);
            m[k] = t * a * d[k];
            m[k1] = t * b * d[k];
        }
    }
    return m;
}

double hermite(double x0, double x1, double y0, double y1, double m0, double m1, double x) {
    const double h = x1 - x0;
    const double t = (x - x0) / h;
    const double t2 = t * t, t3 = t2 * t;
    const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t, h01 = -2 * t3 + 3 * t2,
                 h11 = t3 - t2;
    const double v = h00 * y0 + h10 * h * m0 + h01 * y1 + h11 * h * m1;
    // Rounding can step a hair outside the segment's range; monotone segments never do.
    return std::clamp(v, std::min(y0, y1), std::max(y0, y1));
}

} // namespace

Curve::Curve(CurveKind kind, std::vector<glm::dvec2> points) : m_kind(kind) {
    for (const auto& p : points)
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            throw Error("curve point coordinates must be finite");
    if (kind == CurveKind::Hue)
        for (auto& p : points)
            p.x = wrapHue(p.x);
    std::sort(points.begin(), points.end(),
              [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x; });
    for (std::size_t i = 1; i < points.size(); ++i)
        if (points[i].x == points[i - 1].x)
            throw Error("two curve points share x = " + std::to_string(points[i].x));
    if (kind == CurveKind::Tone && points.size() == 1)
        throw Error("a tone curve needs at least 2 points (or none for the identity)");
    m_points = std::move(points);
    const std::size_t n = m_points.size();
    if (n < 2)
        return;
    const bool periodic = kind == CurveKind::Hue;
    std::vector<double> d(periodic ? n : n - 1);
    for (std::size_t k = 0; k < d.size(); ++k) {
        const glm::dvec2 a = m_points[k];
        glm::dvec2 b = m_points[(k + 1) % n];
        if (k + 1 == n)
            b.x += kPeriod;
        d[k] = (b.y - a.y) / (b.x - a.x);
    }
    m_tangents = monotoneTangents(d, n, periodic);
}

bool Curve::isNeutral() const {
    for (const auto& p : m_points)
        if (m_kind == CurveKind::Tone ? p.y != p.x : p.y != 0.0)
            return false;
    return true;
}

double Curve::operator()(double x) const {
    const std::size_t n = m_points.size();
    if (m_kind == CurveKind::Tone) {
        if (n == 0 || std::isnan(x))
            return x;
        const glm::dvec2 first = m_points.front(), last = m_points.back();
        if (x <= first.x)
            return first.y + m_tangents.front() * (x - first.x);
        if (x >= last.x)
            return last.y + m_tangents.back() * (x - last.x);
        const auto it = std::upper_bound(m_points.begin(), m_points.end(), x,
                                         [](double v, const glm::dvec2& p) { return v < p.x; });
        const std::size_t k = static_cast<std::size_t>(it - m_points.begin()) - 1;
        const glm::dvec2 a = m_points[k], b = m_points[k + 1];
        return hermite(a.x, b.x, a.y, b.y, m_tangents[k], m_tangents[k + 1], x);
    }
    if (n == 0 || !std::isfinite(x))
        return 0.0;
    if (n == 1)
        return m_points.front().y;
    const double h = wrapHue(x);
    // Segment k runs from point k to point k+1; the last wraps to the first point + 360, and
    // hues below the first point belong to it too (shifted up a period).
    const auto it = std::upper_bound(m_points.begin(), m_points.end(), h,
                                     [](double v, const glm::dvec2& p) { return v < p.x; });
    std::size_t k =
        it == m_points.begin() ? n - 1 : static_cast<std::size_t>(it - m_points.begin()) - 1;
    const glm::dvec2 a = m_points[k];
    glm::dvec2 b = m_points[(k + 1) % n];
    double xa = a.x, xb = b.x, xh = h;
    if (k + 1 == n) {
        xb += kPeriod;
        if (xh < xa)
            xh += kPeriod;
    }
    return hermite(xa, xb, a.y, b.y, m_tangents[k], m_tangents[(k + 1) % n], xh);
}

} // namespace lut
