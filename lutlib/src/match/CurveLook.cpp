// SPDX-License-Identifier: Apache-2.0
// Looks that are a colour per luma, and the gradient-map transfer: see match/CurveLook.h.
#include "match/CurveLook.h"

#include "core/Printf.h"
#include "lut/Math.h"
#include "lut/match/HistogramMatch.h"

#include <algorithm>
#include <cmath>

namespace lut::detail {

namespace {

constexpr int kKnots = 1024;
constexpr double kCurveRms = 3.0; // 8-bit steps

double luma(const glm::vec3& w) {
    return 0.2126 * w.x + 0.7152 * w.y + 0.0722 * w.z;
}

struct LumaRange {
    double lo = 0.0, hi = 1.0;
};

LumaRange lumaRange(const SampleSet& s) {
    LumaRange r{INFINITY, -INFINITY};
    for (const auto& v : s.values) {
        const double l = luma(v);
        if (std::isfinite(l)) {
            r.lo = std::min(r.lo, l);
            r.hi = std::max(r.hi, l);
        }
    }
    if (!(r.hi >= r.lo))
        r = {0.0, 1.0};
    if (!(r.hi > r.lo))
        r.hi = r.lo + 1e-6;
    return r;
}

// The reference's mean colour per luma knot (nearest knot), weights per knot; empty knots
// take the colour of the nearest occupied one (steps stay steps).
struct ToneBins {
    LumaRange range;
    std::vector<glm::dvec3> mean;
    std::vector<double> weight;
};

ToneBins toneBins(const SampleSet& ref) {
    ToneBins b;
    b.range = lumaRange(ref);
    b.mean.assign(kKnots, glm::dvec3(0.0));
    b.weight.assign(kKnots, 0.0);
    const double scale = (kKnots - 1) / (b.range.hi - b.range.lo);
    for (std::size_t i = 0; i < ref.values.size(); ++i) {
        const double l = luma(ref.values[i]);
        if (!std::isfinite(l))
            continue;
        const int k =
            std::clamp(static_cast<int>(std::lround((l - b.range.lo) * scale)), 0, kKnots - 1);
        const double w = ref.weights.empty() ? 1.0 : ref.weights[i];
        b.mean[static_cast<std::size_t>(k)] += w * glm::dvec3(ref.values[i]);
        b.weight[static_cast<std::size_t>(k)] += w;
    }
    for (int k = 0; k < kKnots; ++k)
        if (b.weight[static_cast<std::size_t>(k)] > 0.0)
            b.mean[static_cast<std::size_t>(k)] /= b.weight[static_cast<std::size_t>(k)];
    return b;
}

void fillGaps(ToneBins& b) {
    std::vector<int> occupied;
    for (int k = 0; k < kKnots; ++k)
        if (b.weight[static_cast<std::size_t>(k)] > 0.0)
            occupied.push_back(k);
    if (occupied.empty())
        return;
    std::size_t j = 0;
    for (int k = 0; k < kKnots; ++k) {
        while (j + 1 < occupied.size() &&
               std::abs(occupied[j + 1] - k) <= std::abs(occupied[j] - k))
            ++j;
        if (b.weight[static_cast<std::size_t>(k)] <= 0.0)
            b.mean[static_cast<std::size_t>(k)] = b.mean[static_cast<std::size_t>(occupied[j])];
    }
}

} // namespace

CurveLook detectCurveLook(const SampleSet& ref, std::size_t distinct) {
    CurveLook c;
    c.colours = distinct <= 256 ? distinct : 0;
    if (ref.values.empty())
        return c;
    const ToneBins b = toneBins(ref);
    const double scale = (kKnots - 1) / (b.range.hi - b.range.lo);
    double sum = 0.0, total = 0.0;
    for (std::size_t i = 0; i < ref.values.size(); ++i) {
        const double l = luma(ref.values[i]);
        if (!std::isfinite(l))
            continue;
        const int k =
            std::clamp(static_cast<int>(std::lround((l - b.range.lo) * scale)), 0, kKnots - 1);
        const double w = ref.weights.empty() ? 1.0 : ref.weights[i];
        const glm::dvec3 d = glm::dvec3(ref.values[i]) - b.mean[static_cast<std::size_t>(k)];
        sum += w * (d.x * d.x + d.y * d.y + d.z * d.z) / 3.0;
        total += w;
    }
    c.rmsSteps = total > 0.0 ? std::sqrt(sum / total) * 255.0 : 0.0;
    // One colour (a black or flat reference) is no look with steps: nothing to map luma onto.
    c.onCurve = c.rmsSteps < kCurveRms && distinct >= 2 && (b.range.hi - b.range.lo) * 255.0 >= 4.0;
    if (!c.onCurve)
        return c;
    if (c.colours > 0 && c.colours <= 32) {
        c.kind = fmt("posterised palette of %zu colours", c.colours);
        return c;
    }
    // Chroma and hue of each knot's colour (an opponent pair of the working values).
    double chromaSum = 0.0, weightSum = 0.0, cx = 0.0, cy = 0.0, hueWeight = 0.0;
    for (int k = 0; k < kKnots; ++k) {
        const double w = b.weight[static_cast<std::size_t>(k)];
        if (!(w > 0.0))
            continue;
        const glm::dvec3 m = b.mean[static_cast<std::size_t>(k)];
        const double x = m.x - 0.5 * (m.y + m.z), y = 0.8660254037844386 * (m.y - m.z);
        const double chroma = std::sqrt(x * x + y * y) * 255.0;
        chromaSum += w * chroma;
        weightSum += w;
        if (chroma > 3.0) {
            cx += w * x / (chroma / 255.0);
            cy += w * y / (chroma / 255.0);
            hueWeight += w;
        }
    }
    if (chromaSum / weightSum < 3.0)
        c.kind = "greys (monochrome)";
    else if (hueWeight > 0.0 && std::sqrt(cx * cx + cy * cy) / hueWeight > 0.966) // ~15 degrees
        c.kind = "one hue along lightness (sepia, a tinted monochrome)";
    else
        c.kind = "gradient map or duotone (the hue changes with lightness)";
    return c;
}

void fitGradientMap(const SampleSet& source, const SampleSet& ref, MatchTransfer& t) {
    ToneBins b = toneBins(ref);
    fillGaps(b);
    constexpr int kBins = 4096;
    const LumaRange sr = lumaRange(source);
    ChannelHistogram hs(sr.lo, sr.hi, kBins), hr(b.range.lo, b.range.hi, kBins);
    for (std::size_t i = 0; i < source.values.size(); ++i)
        hs.add(luma(source.values[i]), source.weights.empty() ? 1.0 : source.weights[i]);
    for (std::size_t i = 0; i < ref.values.size(); ++i)
        hr.add(luma(ref.values[i]), ref.weights.empty() ? 1.0 : ref.weights[i]);
    CurveLimits limits; // steps where the reference has steps
    limits.minSlope = 1e-6;
    limits.maxSlope = 1e6;
    limits.smoothing = 0.0;
    t.lumaMatch = matchHistograms(hs, hr, limits);
    t.tone = b.mean;
    t.toneMin = b.range.lo;
    t.toneMax = b.range.hi;
}

} // namespace lut::detail
