// SPDX-License-Identifier: Apache-2.0
#pragma once
// Per-channel histogram matching: the 1D curve that gives a source channel the distribution of a
// reference channel, made smooth enough to ship in a LUT.
//
// Each histogram spreads a bin's mass uniformly over its width, so its distribution function F
// is piecewise linear and its quantile function Q (the inverse) too; 8-bit data use one bin per
// code value, which undoes the quantisation (a reference whose histogram has gaps does not turn
// into a staircase). The matching curve is
//     T(x) = Q_ref(F_src(x))         at the bin edges over the source's occupied range,
// then (each step keeps it non-decreasing):
//   0. an atom, a source bin holding over 10% of the picture (a letterbox's black bars, a flat
//      colour), is moved so its pixels (their mean in the bin) land on the reference's mean over
//      the atom's share, where the optimal 1D transport sends it, when they would land further
//      than CurveLimits::atomOff away: between the edges' quantiles they land wherever they sit in
//      the bin (a letterbox's black halfway between the reference's darkest pixels and its bars);
//   1. smoothed by a Gaussian of width `smoothing` (x units), the curve continued linearly past
//      its ends so the ends are not pulled in;
//   2. every knot slope limited to [minSlope, maxSlope], integrated again and shifted so the
//      source's median still lands on the smoothed curve: a reference of two flat colours asks
//      for a step, which becomes a ramp of slope maxSlope;
//   3. continued beyond the source's range with the mean slope over the outer 5% of its mass
//      (limited the same way): colours the source never showed follow the curve smoothly.
#include "lut/match/ChannelCurve.h"

#include <cstddef>
#include <vector>

namespace lut {

class ChannelHistogram {
public:
    ChannelHistogram() = default;
    // `bins` uniform bins over [lo, hi] (lo < hi, bins >= 1); throws lut::Error otherwise.
    ChannelHistogram(double lo, double hi, int bins);

    // Values outside [lo, hi] count in the end bins; NaN is ignored.
    void add(double value, double weight = 1.0) {
        if (!(weight > 0.0) || value != value)
            return;
        const double pos = (value - m_lo) * m_scale;
        const std::size_t last = m_counts.size() - 1;
        const std::size_t k = pos <= 0.0                         ? 0
                              : pos >= static_cast<double>(last) ? last
                                                                 : static_cast<std::size_t>(pos);
        m_counts[k] += weight;
        m_sums[k] += weight * value;
        m_stale = true;
    }
    void merge(const ChannelHistogram& other); // same bins (throws lut::Error otherwise)

    double lo() const { return m_lo; }
    double hi() const { return m_hi; }
    int bins() const { return static_cast<int>(m_counts.size()); }
    double binWidth() const { return (m_hi - m_lo) / static_cast<double>(m_counts.size()); }
    const std::vector<double>& counts() const { return m_counts; }
    double total() const;
    // The mean of the values counted in bin k, within the bin (its centre when it is empty).
    double meanIn(std::size_t k) const;
    std::size_t occupiedBins() const; // bins holding mass

    // The distribution function at x (piecewise linear, 0 below lo, 1 above hi) and its inverse
    // at p in [0, 1]: quantile() the lowest x with cdf(x) = p (where the mass below ends, when p
    // falls in a gap), upperQuantile() the highest (where the mass above starts).
    double cdf(double x) const;
    double quantile(double p) const;
    double upperQuantile(double p) const;

private:
    const std::vector<double>& cumulative() const;

    double m_lo = 0.0, m_hi = 1.0;
    double m_scale = 1.0; // bins per unit
    std::vector<double> m_counts;
    std::vector<double> m_sums;               // weight * value per bin
    mutable std::vector<double> m_cumulative; // m_counts.size() + 1 edges; rebuilt when stale
    mutable bool m_stale = true;
};

struct CurveLimits {
    double minSlope = 1.0 / 16.0;
    double maxSlope = 4.0;
    double smoothing = 1.0 / 255.0; // Gaussian sigma, x units (0 = none)
    // An atom (a source bin holding over 10% of the picture) is moved onto the reference's mean
    // over its share when its pixels would land further than this from it (x units). Half an
    // 8-bit step for the first match: a quarter took retina's sharp second match away (bench/
    // RESULTS.md, issue 42); matchChannels asks a tenth for the match after MKL, whose output is
    // what the LUT writes (a letterbox's bars otherwise land half a step off, a step rounded).
    double atomOff = 0.5 / 255.0;
};

// What the limits changed, for the warnings.
struct CurveNotes {
    bool slopeLimited = false;  // a slope over the source's occupied bins was limited
    double limitedShare = 0.0;  // the share of the source's mass in bins limited by more than 1.5x
    double steepestAsked = 0.0; // the largest slope before limiting (there)
    double flattestAsked = 0.0; // the smallest
    bool emptySource = false;   // no source mass: the identity
    bool emptyReference = false;
};

// T as above. An empty source or reference gives the identity over the source's range.
ChannelCurve matchHistograms(const ChannelHistogram& source, const ChannelHistogram& reference,
                             const CurveLimits& limits = {}, CurveNotes* notes = nullptr);

} // namespace lut
