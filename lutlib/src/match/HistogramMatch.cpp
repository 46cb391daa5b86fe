// SPDX-License-Identifier: Apache-2.0
// Histograms and the smooth histogram-matching curve: see lut/match/HistogramMatch.h.
#include "lut/match/HistogramMatch.h"

#include "lut/Error.h"
#include "lut/Math.h"

#include <algorithm>
#include <cmath>

namespace lut {

ChannelHistogram::ChannelHistogram(double lo, double hi, int bins) : m_lo(lo), m_hi(hi) {
    if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi) || bins < 1)
        throw Error("histogram: needs finite lo < hi and at least one bin");
    m_counts.assign(static_cast<std::size_t>(bins), 0.0);
    m_sums.assign(static_cast<std::size_t>(bins), 0.0);
    m_scale = static_cast<double>(bins) / (hi - lo);
}

void ChannelHistogram::merge(const ChannelHistogram& other) {
    if (other.m_counts.size() != m_counts.size() || other.m_lo != m_lo || other.m_hi != m_hi)
        throw Error("histogram: merging histograms of different bins");
    for (std::size_t k = 0; k < m_counts.size(); ++k) {
        m_counts[k] += other.m_counts[k];
        m_sums[k] += other.m_sums[k];
    }
    m_stale = true;
}

double ChannelHistogram::meanIn(std::size_t k) const {
    const double lo = m_lo + static_cast<double>(k) * binWidth();
    if (!(m_counts[k] > 0.0))
        return lo + 0.5 * binWidth();
    return std::clamp(m_sums[k] / m_counts[k], lo, lo + binWidth());
}

double ChannelHistogram::total() const {
    return cumulative().back();
}

std::size_t ChannelHistogram::occupiedBins() const {
    return static_cast<std::size_t>(
        std::count_if(m_counts.begin(), m_counts.end(), [](double c) { return c > 0.0; }));
}

const std::vector<double>& ChannelHistogram::cumulative() const {
    if (m_stale || m_cumulative.size() != m_counts.size() + 1) {
        m_cumulative.assign(m_counts.size() + 1, 0.0);
        for (std::size_t k = 0; k < m_counts.size(); ++k)
            m_cumulative[k + 1] = m_cumulative[k] + m_counts[k];
        m_stale = false;
    }
    return m_cumulative;
}

double ChannelHistogram::cdf(double x) const {
    const auto& cum = cumulative();
    const double total = cum.back();
    if (!(total > 0.0) || std::isnan(x))
        return 0.0;
    const double pos = (x - m_lo) / binWidth();
    if (pos <= 0.0)
        return 0.0;
    if (pos >= static_cast<double>(m_counts.size()))
        return 1.0;
    const std::size_t k = static_cast<std::size_t>(pos);
    const double t = pos - static_cast<double>(k);
    return (cum[k] + t * m_counts[k]) / total;
}

double ChannelHistogram::quantile(double p) const {
    const auto& cum = cumulative();
    const double total = cum.back();
    if (!(total > 0.0))
        return m_lo;
    const double target = std::clamp(std::isnan(p) ? 0.0 : p, 0.0, 1.0) * total;
    // the first bin whose upper edge reaches the target, skipping empty bins
    auto it = std::lower_bound(cum.begin() + 1, cum.end(), target);
    if (it == cum.end())
        it = cum.end() - 1;
    std::size_t k = static_cast<std::size_t>(it - cum.begin()) - 1;
    while (k + 1 < m_counts.size() && m_counts[k] <= 0.0)
        ++k;
    const double t =
        m_counts[k] > 0.0 ? std::clamp((target - cum[k]) / m_counts[k], 0.0, 1.0) : 0.0;
    return m_lo + (static_cast<double>(k) + t) * binWidth();
}

double ChannelHistogram::upperQuantile(double p) const {
    const auto& cum = cumulative();
    const double total = cum.back();
    if (!(total > 0.0))
        return m_hi;
    const double target = std::clamp(std::isnan(p) ? 0.0 : p, 0.0, 1.0) * total;
    // the first bin with mass above the target
    auto it = std::upper_bound(cum.begin() + 1, cum.end(), target);
    if (it == cum.end())
        return quantile(p);
    const std::size_t k = static_cast<std::size_t>(it - cum.begin()) - 1;
    const double t =
        m_counts[k] > 0.0 ? std::clamp((target - cum[k]) / m_counts[k], 0.0, 1.0) : 0.0;
    return m_lo + (static_cast<double>(k) + t) * binWidth();
}

namespace {

// A source bin holding more than this share of the picture is an atom (step 0b below) when its
// pixels land further than CurveLimits::atomOff from the reference's mean over their share.
// Measured (bench/RESULTS.md, issue 42, fourth pass): at 1% the sample scene's flat colours (up to
// 5.1% of the picture each) moved and the issue-23 acceptance went to p99 9 (limit 8).
constexpr double kAtomShare = 0.1;

// Knot index range [first, last] of the bin edges around the occupied bins.
bool occupiedEdges(const ChannelHistogram& h, std::size_t& first, std::size_t& last) {
    const auto& c = h.counts();
    std::size_t a = 0;
    while (a < c.size() && c[a] <= 0.0)
        ++a;
    if (a == c.size())
        return false;
    std::size_t b = c.size() - 1;
    while (c[b] <= 0.0)
        --b;
    first = a;
    last = b + 1;
    return true;
}

// Weighted isotonic regression (pool adjacent violators): the non-decreasing sequence closest
// to v in the weighted least-squares sense.
void isotonic(std::vector<double>& v, const std::vector<double>& w) {
    const std::size_t n = v.size();
    std::vector<double> level(n), weight(n);
    std::vector<std::size_t> size(n);
    std::size_t blocks = 0;
    for (std::size_t k = 0; k < n; ++k) {
        level[blocks] = v[k];
        weight[blocks] = w[k];
        size[blocks] = 1;
        ++blocks;
        while (blocks > 1 && level[blocks - 2] > level[blocks - 1]) {
            const double ww = weight[blocks - 2] + weight[blocks - 1];
            level[blocks - 2] =
                (level[blocks - 2] * weight[blocks - 2] + level[blocks - 1] * weight[blocks - 1]) /
                ww;
            weight[blocks - 2] = ww;
            size[blocks - 2] += size[blocks - 1];
            --blocks;
        }
    }
    std::size_t k = 0;
    for (std::size_t b = 0; b < blocks; ++b)
        for (std::size_t j = 0; j < size[b]; ++j)
            v[k++] = level[b];
}

// The sequence closest to t (weighted least squares) whose steps all lie in [lo, hi]: Dykstra's
// alternating projections onto "steps >= lo" and "steps <= hi", each an isotonic regression.
std::vector<double> boundedSlopes(const std::vector<double>& t, const std::vector<double>& w,
                                  double lo, double hi) {
    const std::size_t n = t.size();
    std::vector<double> x = t, p(n, 0.0), q(n, 0.0), y(n), v(n);
    auto projectLow = [&](std::vector<double>& z) { // steps >= lo
        for (std::size_t j = 0; j < n; ++j)
            z[j] -= lo * static_cast<double>(j);
        isotonic(z, w);
        for (std::size_t j = 0; j < n; ++j)
            z[j] += lo * static_cast<double>(j);
    };
    auto projectHigh = [&](std::vector<double>& z) { // steps <= hi
        for (std::size_t j = 0; j < n; ++j)
            z[j] = hi * static_cast<double>(j) - z[j];
        isotonic(z, w);
        for (std::size_t j = 0; j < n; ++j)
            z[j] = hi * static_cast<double>(j) - z[j];
    };
    for (int iteration = 0; iteration < 200; ++iteration) {
        for (std::size_t j = 0; j < n; ++j)
            v[j] = x[j] + p[j];
        y = v;
        projectLow(y);
        for (std::size_t j = 0; j < n; ++j) {
            p[j] = v[j] - y[j];
            v[j] = y[j] + q[j];
        }
        std::vector<double> next = v;
        projectHigh(next);
        double change = 0.0;
        for (std::size_t j = 0; j < n; ++j) {
            q[j] = v[j] - next[j];
            change = std::max(change, std::fabs(next[j] - x[j]));
        }
        x.swap(next);
        if (change < 1e-9)
            break;
    }
    // Round-off can leave a step a hair outside; the low bound is what keeps the curve
    // invertible, so it has the last word.
    for (std::size_t j = 0; j + 1 < n; ++j)
        x[j + 1] = std::max(x[j + 1], x[j] + lo);
    return x;
}

// The mean of the reference's quantile function over the share [pa, pb] of its mass (each bin's
// mass spread over its width): where an atom of the source holding that share lands under the
// optimal 1D transport.
double meanQuantile(const ChannelHistogram& h, double pa, double pb) {
    const auto& c = h.counts();
    const double total = h.total();
    const double a = pa * total, b = pb * total, w = h.binWidth();
    double below = 0.0, acc = 0.0, mass = 0.0;
    for (std::size_t k = 0; k < c.size() && below < b; ++k) {
        const double lo = below, hi = below + c[k];
        below = hi;
        if (!(c[k] > 0.0) || hi <= a)
            continue;
        const double s = std::max(lo, a), e = std::min(hi, b);
        const double xs = h.lo() + (static_cast<double>(k) + (s - lo) / c[k]) * w;
        const double xe = h.lo() + (static_cast<double>(k) + (e - lo) / c[k]) * w;
        acc += (e - s) * 0.5 * (xs + xe);
        mass += e - s;
    }
    return mass > 0.0 ? acc / mass : NAN;
}

} // namespace

ChannelCurve matchHistograms(const ChannelHistogram& source, const ChannelHistogram& reference,
                             const CurveLimits& limits, CurveNotes* notes) {
    CurveNotes local;
    CurveNotes& n = notes ? *notes : local;
    n = CurveNotes{};
    std::size_t first = 0, last = 0;
    if (!occupiedEdges(source, first, last)) {
        n.emptySource = true;
        return ChannelCurve::identity(source.lo(), source.hi());
    }
    const double h = source.binWidth();
    const double x0 = source.lo() + static_cast<double>(first) * h;
    const double x1 = source.lo() + static_cast<double>(last) * h;
    if (!(reference.total() > 0.0)) {
        n.emptyReference = true;
        return ChannelCurve::identity(x0, x1);
    }
    const double minSlope = std::max(limits.minSlope, 1e-9);
    const double maxSlope = std::max(limits.maxSlope, minSlope);
    const std::size_t count = last - first + 1;

    // 0. T at the edges: Q_ref(F_src(edge)); across the source's gaps, linear.
    const auto& counts = source.counts();
    std::vector<double> t(count);
    for (std::size_t j = 0; j < count; ++j) {
        const double p = source.cdf(x0 + static_cast<double>(j) * h);
        const bool below = j > 0 && counts[first + j - 1] > 0.0;
        const bool above = j + 1 < count && counts[first + j] > 0.0;
        if (below && above)
            t[j] = 0.5 * (reference.quantile(p) + reference.upperQuantile(p));
        else if (below)
            t[j] = reference.quantile(p);
        else if (above)
            t[j] = reference.upperQuantile(p);
        else
            t[j] = NAN; // inside a gap: filled below
    }
    for (std::size_t j = 0; j < count; ++j) {
        if (!std::isnan(t[j]))
            continue;
        std::size_t k = j;
        while (std::isnan(t[k]))
            ++k; // the last edge is always set (its bin below holds mass)
        const double a = t[j - 1], b = t[k];
        for (std::size_t i = j; i < k; ++i)
            t[i] = a + (b - a) * static_cast<double>(i - j + 1) / static_cast<double>(k - j + 1);
        j = k;
    }

    // 0b. Atoms: a source bin holding a large share of the picture (a black surround, a flat
    // colour), its pixels at one value or nearly. The curve between the bin's edges, Q_ref at
    // either end of the atom's share, puts those pixels wherever they sit between the two, which
    // can be far from every reference value of that share (a letterbox's black halfway between the
    // reference's few darkest pixels and its surround's colour: 8 steps off in blue, the limits
    // making the step a ramp). The curve at the pixels' mean goes to the mean of the reference over
    // the atom's share (where the optimal 1D transport sends an atom), with a ramp around it no
    // steeper than allowed and within the edges' values; the smoothing leaves it.
    std::vector<std::pair<std::size_t, double>> atoms; // edge index, its value
    for (std::size_t j = 0; j + 1 < count; ++j) {
        const double mass = counts[first + j];
        if (!(mass > kAtomShare * source.total()))
            continue;
        const double pa = source.cdf(x0 + static_cast<double>(j) * h);
        const double pb = source.cdf(x0 + static_cast<double>(j + 1) * h);
        const double m = meanQuantile(reference, pa, pb);
        // where the pixels sit in the bin (code values: its centre), 0..1
        const double at =
            std::clamp((source.meanIn(first + j) - x0) / h - static_cast<double>(j), 0.0, 1.0);
        if (!std::isfinite(m) ||
            std::fabs(m - (t[j] + at * (t[j + 1] - t[j]))) < std::max(0.25 * h, limits.atomOff))
            continue;
        // The ramp (rise over the bin) stays within the edges' values, so the neighbouring bins
        // keep theirs.
        double rise = maxSlope * h;
        if (at > 0.0)
            rise = std::min(rise, (m - t[j]) / at);
        if (at < 1.0)
            rise = std::min(rise, (t[j + 1] - m) / (1.0 - at));
        rise = std::max(rise, 0.0);
        t[j] = m - at * rise;
        t[j + 1] = m + (1.0 - at) * rise;
        atoms.emplace_back(j, t[j]);
        atoms.emplace_back(j + 1, t[j + 1]);
    }

    // Mean slope over the outer 5% of the source's mass at each end.
    auto slopeBetween = [&](double pa, double pb) {
        const double xa = source.quantile(pa), xb = source.quantile(pb);
        if (!(xb - xa > 1e-12))
            return 1.0;
        const double ya = reference.quantile(pa), yb = reference.quantile(pb);
        return std::clamp((yb - ya) / (xb - xa), minSlope, maxSlope);
    };
    const double slopeLo = slopeBetween(0.0, 0.05);
    const double slopeHi = slopeBetween(0.95, 1.0);

    // 1. Gaussian smoothing, the curve continued linearly past its ends.
    const double sigma = limits.smoothing / h; // in knots
    if (sigma > 0.25 && count >= 2) {
        const int radius = static_cast<int>(std::ceil(3.0 * sigma));
        std::vector<double> kernel(static_cast<std::size_t>(2 * radius + 1));
        double ksum = 0.0;
        for (int i = -radius; i <= radius; ++i)
            ksum += kernel[static_cast<std::size_t>(i + radius)] =
                lut::math::exp(-0.5 * (i * i) / (sigma * sigma));
        for (double& k : kernel)
            k /= ksum;
        const std::ptrdiff_t end = static_cast<std::ptrdiff_t>(count) - 1;
        auto extended = [&](std::ptrdiff_t j) {
            if (j < 0)
                return t.front() + slopeLo * h * static_cast<double>(j);
            if (j > end)
                return t.back() + slopeHi * h * static_cast<double>(j - end);
            return t[static_cast<std::size_t>(j)];
        };
        std::vector<double> smooth(count);
        for (std::ptrdiff_t j = 0; j <= end; ++j) {
            double acc = 0.0;
            for (int i = -radius; i <= radius; ++i)
                acc += kernel[static_cast<std::size_t>(i + radius)] * extended(j + i);
            smooth[static_cast<std::size_t>(j)] = acc;
        }
        t = std::move(smooth);
        for (const auto& [j, v] : atoms)
            t[j] = v;
    }

    // 2. Slopes limited: the closest curve (least squares weighted by the source's mass, so the
    // change lands where few pixels are) whose every step lies in [minSlope, maxSlope] * h.
    std::vector<double> weight(count);
    const double floorWeight = 1e-4 * source.total() / static_cast<double>(count);
    for (std::size_t j = 0; j < count; ++j) {
        const double below = j > 0 ? counts[first + j - 1] : 0.0;
        const double above = j + 1 < count ? counts[first + j] : 0.0;
        weight[j] = 0.5 * (below + above) + floorWeight;
    }
    n.steepestAsked = 0.0;
    n.flattestAsked = maxSlope;
    bool anyOccupied = false;
    for (std::size_t j = 0; j + 1 < count; ++j) {
        const double asked = (t[j + 1] - t[j]) / h;
        if (counts[first + j] > 0.0) {
            anyOccupied = true;
            n.steepestAsked = std::max(n.steepestAsked, asked);
            n.flattestAsked = std::min(n.flattestAsked, asked);
            if (asked > maxSlope * 1.0001 || asked < minSlope * 0.9999)
                n.slopeLimited = true;
            if (asked > maxSlope * 1.5 || asked < minSlope / 1.5)
                n.limitedShare += counts[first + j];
        }
    }
    if (!anyOccupied)
        n.flattestAsked = n.steepestAsked;
    n.limitedShare /= source.total();
    std::vector<double> out = boundedSlopes(t, weight, minSlope * h, maxSlope * h);
    return ChannelCurve(x0, x1, std::move(out), slopeLo, slopeHi);
}

} // namespace lut
