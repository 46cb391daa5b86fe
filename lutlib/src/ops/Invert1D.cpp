// SPDX-License-Identifier: Apache-2.0
#include "lut/Error.h"
#include "lut/ops/ErrorBound.h"
#include "lut/ops/Invert.h"
#include "ops/OpsDetail.h"

#include <algorithm>
#include <cmath>

namespace lut {

InvertResult1D invert(const Lut1D& source, const InvertOptions& options) {
    if (source.empty())
        throw Error("invert: the 1D LUT has no entries");
    const long long t0 = detail::nowNanos();
    const double tol = options.tolerance > 0.0 ? options.tolerance : 1e-5;
    InvertResult1D result;
    InvertReport& rep = result.report;
    Lut1D a = source;
    for (auto& e : a.entries()) {
        const glm::vec3 s(detail::sanitizeValue(e.x), detail::sanitizeValue(e.y),
                          detail::sanitizeValue(e.z));
        if (!(s.x == e.x && s.y == e.y && s.z == e.z))
            ++rep.sanitizedEntries;
        e = s;
    }
    const int n = a.size();
    const int m = options.size > 0 ? options.size : n;
    result.lut = Lut1D(m);
    glm::vec3 lo = a.domainMin(), hi = a.domainMax();
    if (options.outputRangeDomain)
        for (int c = 0; c < 3; ++c) {
            float mn = INFINITY, mx = -INFINITY;
            for (const auto& e : a.entries()) {
                mn = std::min(mn, e[c]);
                mx = std::max(mx, e[c]);
            }
            if (mn < mx) {
                lo[c] = mn;
                hi[c] = mx;
            }
        }
    result.lut.setDomain(lo, hi);
    result.lut.setTitle(source.title().empty() ? "inverse" : "inverse of " + source.title());
    double sumResidual = 0.0;
    for (int c = 0; c < 3; ++c) {
        std::vector<double> xs(static_cast<std::size_t>(n)), ys(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) {
            xs[static_cast<std::size_t>(i)] =
                a.domainMin()[c] +
                (static_cast<double>(a.domainMax()[c]) - a.domainMin()[c]) * i / (n - 1);
            ys[static_cast<std::size_t>(i)] = a[i][c];
        }
        const detail::PiecewiseLinearInverse inverse(xs, ys);
        rep.foldedCells += inverse.nonMonotoneSegments();
        for (int k = 0; k < m; ++k) {
            const double y = lo[c] + (static_cast<double>(hi[c]) - lo[c]) * k / (m - 1);
            const detail::CurveInverse x = inverse(y);
            result.lut[k][c] = static_cast<float>(x.x);
            glm::vec3 probe(a.domainMin());
            probe[c] = static_cast<float>(x.x);
            const double reached = a.apply(probe)[c];
            const double residual = std::fabs(reached - y);
            ++rep.points;
            sumResidual += residual;
            rep.maxResidual = std::max(rep.maxResidual, residual);
            if (!x.reached || residual > tol) {
                ++rep.unreachable;
                UnreachedPoint p;
                p.target[c] = static_cast<float>(y);
                p.solution[c] = static_cast<float>(x.x);
                p.reached[c] = static_cast<float>(reached);
                p.residual = residual;
                rep.worst.push_back(p);
            }
        }
    }
    std::sort(
        rep.worst.begin(), rep.worst.end(),
        [](const UnreachedPoint& p, const UnreachedPoint& q) { return p.residual > q.residual; });
    if (rep.worst.size() > 16)
        rep.worst.resize(16);
    rep.meanResidual = rep.points ? sumResidual / static_cast<double>(rep.points) : 0.0;
    rep.seconds = detail::secondsSince(t0);
    // Per channel along u in [0, 1] mapped onto each channel's domain, between the entries too.
    auto along = [](glm::vec3 lo3, glm::vec3 hi3, double u) {
        glm::vec3 x;
        for (int c = 0; c < 3; ++c)
            x[c] = static_cast<float>(lo3[c] + (static_cast<double>(hi3[c]) - lo3[c]) * u);
        return x;
    };
    BoundOptions bo;
    bo.greyOnly = true;
    bo.cells = m - 1;
    const Lut1D& inv = result.lut;
    rep.residual = boundError(
        [&](const glm::dvec3* in, glm::dvec3* diff, std::size_t count) {
            for (std::size_t i = 0; i < count; ++i) {
                const glm::vec3 y = along(lo, hi, in[i].x);
                diff[i] = glm::dvec3(a.apply(inv.apply(y))) - glm::dvec3(y);
            }
        },
        bo);
    bo.cells = n - 1;
    rep.roundTrip = boundError(
        [&](const glm::dvec3* in, glm::dvec3* diff, std::size_t count) {
            for (std::size_t i = 0; i < count; ++i) {
                const glm::vec3 x = along(a.domainMin(), a.domainMax(), in[i].x);
                diff[i] = glm::dvec3(inv.apply(a.apply(x))) - glm::dvec3(x);
            }
        },
        bo);
    return result;
}

} // namespace lut
