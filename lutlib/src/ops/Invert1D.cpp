#include "lut/Error.h"
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
    ErrorAccumulator acc;
    const int probes = 4 * (n - 1) + 1;
    for (int k = 0; k < probes; ++k) {
        glm::vec3 x;
        for (int c = 0; c < 3; ++c)
            x[c] = static_cast<float>(a.domainMin()[c] +
                                      (static_cast<double>(a.domainMax()[c]) - a.domainMin()[c]) *
                                          k / (probes - 1));
        const glm::vec3 back = result.lut.apply(a.apply(x));
        for (int c = 0; c < 3; ++c)
            acc.add(x[c], back[c]);
    }
    rep.roundTrip = acc.result();
    return result;
}

} // namespace lut
