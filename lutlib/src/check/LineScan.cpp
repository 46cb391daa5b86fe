// SPDX-License-Identifier: Apache-2.0
#include "check/LineScan.h"
#include "lut/Math.h"

#include <algorithm>
#include <cmath>

namespace lut::check {

namespace {

constexpr double kSteps = 255.0; // output value -> 8-bit steps
constexpr float kFlatTolerance = 1e-6f;
constexpr double kFlatRatio = 0.1;  // a flat segment's slope is under this share of the line's
constexpr double kStepRatio = 2.5;  // a step rises at least this many times its neighbours
constexpr int kLocalSegments = 3;   // segments either side of a flat run that set its slope
constexpr double kHeldSteps = 0.01; // a colour changing less per segment is held

struct Segments {
    std::vector<float> change; // max over channels of |step|
    std::vector<int> channel;  // the channel that moves most
    std::vector<double> slope; // change / step
    std::vector<char> pinned;  // a channel that must move is held at a clip bound
    std::vector<char> flagged; // already reported (second differences skip it)
};

Segments segmentsOf(const LineSpec& line, const ClipBounds& bounds) {
    const int segs = line.count - 1;
    Segments s;
    s.change.resize(static_cast<std::size_t>(segs));
    s.channel.resize(static_cast<std::size_t>(segs));
    s.slope.resize(static_cast<std::size_t>(segs));
    s.pinned.assign(static_cast<std::size_t>(segs), 0);
    s.flagged.assign(static_cast<std::size_t>(segs), 0);
    for (int i = 0; i < segs; ++i) {
        const glm::vec3 a = line.values[i], b = line.values[i + 1];
        float best = -1.0f;
        int bestC = 0;
        for (int c = 0; c < 3; ++c) {
            const float d = std::fabs(b[c] - a[c]);
            if (d > best) {
                best = d;
                bestC = c;
            }
            // Held within an 8-bit step of a clip bound: that flat part is the clip's.
            if (line.direction[c] != 0 && bounds.heldNear(c, a[c], b[c]))
                s.pinned[static_cast<std::size_t>(i)] = 1;
        }
        const auto k = static_cast<std::size_t>(i);
        s.change[k] = best;
        s.channel[k] = bestC;
        if (line.segmentSteps) {
            // From this sample over one input 8-bit step at least: the change there per step.
            double width = 0.0;
            int j = i;
            while (j < segs && width < 1.0 / kSteps)
                width += line.segmentSteps[j++];
            float across = best;
            for (int c = 0; c < 3; ++c)
                across = std::max(across, std::fabs(line.values[j][c] - a[c]));
            s.slope[k] = across / std::max(width, 1.0 / kSteps);
        } else {
            s.slope[k] = best / line.step;
        }
    }
    return s;
}

void scanFolds(const LineSpec& line, const CheckThresholds& t, Segments& s,
               std::vector<LineEvent>& events, LineFigures& figures) {
    const int segs = line.count - 1;
    const glm::vec3* v = line.values;
    for (int c = 0; c < 3; ++c) {
        if (line.direction[c] == 0)
            continue;
        const float net = v[segs][c] - v[0][c];
        const float sigma = net > 0.0f ? 1.0f : net < 0.0f ? -1.0f : float(line.direction[c]);
        int i = 0;
        while (i < segs) {
            if (sigma * (v[i + 1][c] - v[i][c]) >= -kFlatTolerance) {
                ++i;
                continue;
            }
            // A run going back, across flat segments inside it, from its local peak to its
            // local trough.
            const int a = i;
            int b = i;
            while (i < segs && sigma * (v[i + 1][c] - v[i][c]) <= kFlatTolerance) {
                if (sigma * (v[i + 1][c] - v[i][c]) < -kFlatTolerance)
                    b = i + 1;
                ++i;
            }
            const double drop = sigma * (double(v[a][c]) - v[b][c]) * kSteps;
            figures.worstFold = std::max(figures.worstFold, drop);
            if (drop >= t.foldOver.warn) {
                LineEvent e;
                e.kind = FindingKind::FoldOver;
                e.channel = c;
                e.begin = a;
                e.end = b;
                e.size = static_cast<float>(drop);
                e.at = 0.5f * static_cast<float>(a + b);
                e.from = v[a][c];
                e.to = v[b][c];
                events.push_back(e);
                for (int k = a; k < b; ++k)
                    s.flagged[static_cast<std::size_t>(k)] = 1;
            }
        }
    }
}

// The slope of a channel just outside a clipped run: from the segment next to the run's edge
// sample, or the one beyond it (which still holds the unclipped trend).
double trendBefore(const LineSpec& line, int c, int p) {
    const int k = p >= 2 ? p - 2 : p - 1;
    return (line.values[k + 1][c] - line.values[k][c]) / line.step;
}
double trendAfter(const LineSpec& line, int c, int q) {
    const int k = q + 2 <= line.count - 1 ? q + 1 : q;
    return (line.values[k + 1][c] - line.values[k][c]) / line.step;
}

void scanClips(const LineSpec& line, const ClipBounds& bounds, Segments& s,
               std::vector<LineEvent>& events) {
    const int c = line.ownChannel;
    const int last = line.count - 1;
    const glm::vec3* v = line.values;
    for (int variant = 0; variant < 2; ++variant) {
        const bool top = variant == 0;
        auto at = [&](int i) {
            return top ? bounds.atTop(c, v[i][c]) : bounds.atBottom(c, v[i][c]);
        };
        int i = 0;
        while (i <= last) {
            if (!at(i)) {
                ++i;
                continue;
            }
            const int p = i;
            while (i <= last && at(i))
                ++i;
            const int q = i - 1;
            if (q == p)
                continue; // one sample at the bound: reaching it is not clipping
            const float bound = v[p][c];
            double fracBefore = 0.0, fracAfter = 0.0, trend = 0.0;
            if (p > 0) {
                const double slope = trendBefore(line, c, p); // towards the bound
                if (top ? slope > 0.0 : slope < 0.0) {
                    const double delta = (bound - v[p - 1][c]) / (slope * line.step);
                    fracBefore = std::clamp(1.0 - delta, 0.0, 1.0);
                    trend = std::fabs(slope);
                }
            }
            if (q < last) {
                const double slope = trendAfter(line, c, q); // away from the bound
                if (top ? slope < 0.0 : slope > 0.0) {
                    const double delta = (bound - v[q + 1][c]) / (slope * line.step);
                    fracAfter = std::clamp(1.0 - std::fabs(delta), 0.0, 1.0);
                    trend = std::max(trend, std::fabs(slope));
                }
            }
            const double length = (q - p) + fracBefore + fracAfter; // in segments
            LineEvent e;
            e.kind = FindingKind::Clip;
            e.channel = c;
            e.variant = variant;
            e.begin = fracBefore > 0.0 ? p - 1 : p;
            e.end = fracAfter > 0.0 ? q + 1 : q;
            e.firstFraction = fracBefore > 0.0 ? static_cast<float>(fracBefore) : 1.0f;
            e.lastFraction = fracAfter > 0.0 ? static_cast<float>(fracAfter) : 1.0f;
            if (e.end - e.begin == 1 && fracBefore > 0.0 && fracAfter > 0.0)
                e.lastFraction = e.firstFraction = static_cast<float>(fracBefore + fracAfter);
            // Where the clip starts: where the trend before it reaches the bound.
            e.at = static_cast<float>(p > 0 ? p - fracBefore : q + fracAfter);
            if (p == 0 && q < last)
                e.at = static_cast<float>(q + fracAfter);
            e.size = trend * length * line.step * kSteps; // range cut off
            e.from = bound;
            e.to = bound;
            events.push_back(e);
            for (int k = p; k < q; ++k)
                s.flagged[static_cast<std::size_t>(k)] = 1;
        }
    }
}

void scanBanding(const LineSpec& line, const CheckThresholds& t, Segments& s,
                 std::vector<LineEvent>& events, LineFigures& figures) {
    const int segs = line.count - 1;
    const glm::vec3* v = line.values;
    double reference = 0.0; // the mean slope of the channel that moves most
    int mainChannel = line.ownChannel;
    for (int c = 0; c < 3; ++c) {
        double total = 0.0;
        for (int i = 0; i < segs; ++i)
            total += std::fabs(v[i + 1][c] - v[i][c]);
        if (total / (segs * line.step) > reference) {
            reference = total / (segs * line.step);
            if (line.ownChannel < 0)
                mainChannel = c;
        }
    }
    mainChannel = std::max(mainChannel, 0);
    for (int i = 0; i < segs; ++i)
        if (!s.pinned[static_cast<std::size_t>(i)])
            figures.steepest = std::max(figures.steepest, s.slope[static_cast<std::size_t>(i)]);
    if (reference * segs * line.step * kSteps < 1.0)
        return; // the line hardly moves at all
    auto candidate = [&](int i) {
        const auto k = static_cast<std::size_t>(i);
        return !s.pinned[k] && s.slope[k] < kFlatRatio * reference;
    };
    // Flat runs: the change they lose against the slope of the segments around them.
    for (int i = 0; i < segs;) {
        if (!candidate(i)) {
            ++i;
            continue;
        }
        const int a = i;
        while (i < segs && candidate(i))
            ++i;
        const int b = i;
        double around = 0.0;
        int n = 0;
        for (int k = a - 1; k >= std::max(0, a - kLocalSegments); --k)
            if (!s.pinned[static_cast<std::size_t>(k)]) {
                around += s.slope[static_cast<std::size_t>(k)];
                ++n;
            }
        for (int k = b; k < std::min(segs, b + kLocalSegments); ++k)
            if (!s.pinned[static_cast<std::size_t>(k)]) {
                around += s.slope[static_cast<std::size_t>(k)];
                ++n;
            }
        const double local = n > 0 ? around / n : reference;
        double lost = 0.0;
        for (int k = a; k < b; ++k)
            lost += std::max(0.0, local - s.slope[static_cast<std::size_t>(k)]);
        lost *= line.step * kSteps;
        // A run at an end of the line over which the whole colour is held: the LUT ignores
        // inputs past a point, a clip of the input (a highlight clip followed by a colour matrix
        // holds a channel away from the output's bounds), not banding.
        bool held = a == 0 || b == segs;
        for (int k = a; k < b && held; ++k)
            held = double(s.change[static_cast<std::size_t>(k)]) * kSteps <= kHeldSteps;
        if (lost >= t.flat.warn && held) {
            LineEvent e;
            e.kind = FindingKind::Clip;
            e.channel = mainChannel;
            e.variant = b == segs ? 0 : 1;
            e.begin = a;
            e.end = b;
            e.size = lost;
            e.at = static_cast<float>(b == segs ? a : b);
            e.from = v[a][mainChannel];
            e.to = v[a][mainChannel];
            events.push_back(e);
            for (int k = a; k < b; ++k)
                s.flagged[static_cast<std::size_t>(k)] = 1;
        } else if (lost >= t.flat.warn) {
            LineEvent e;
            e.kind = FindingKind::Flat;
            e.channel = mainChannel;
            e.begin = a;
            e.end = b;
            e.size = static_cast<float>(lost);
            e.at = 0.5f * static_cast<float>(a + b);
            e.from = v[a][mainChannel];
            e.to = static_cast<float>((b - a) * line.step * kSteps); // input steps it spans
            events.push_back(e);
            for (int k = a; k < b; ++k)
                s.flagged[static_cast<std::size_t>(k)] = 1;
        }
    }
    // Steps and steep slopes.
    for (int i = 0; i < segs; ++i) {
        const auto k = static_cast<std::size_t>(i);
        if (s.pinned[k])
            continue;
        bool step = false;
        if (i >= 1 && i + 1 < segs) {
            const double neighbours = std::max(s.slope[k - 1], s.slope[k + 1]);
            const double excess =
                (s.change[k] - 0.5 * (double(s.change[k - 1]) + s.change[k + 1])) * kSteps;
            if (s.slope[k] >= kStepRatio * neighbours && excess >= t.step.warn) {
                step = true;
                const int c = s.channel[k];
                LineEvent e;
                e.kind = FindingKind::Step;
                e.channel = c;
                e.begin = i;
                e.end = i + 1;
                e.size = static_cast<float>(excess);
                e.at = static_cast<float>(i) + 0.5f;
                e.from = v[i][c];
                e.to = v[i + 1][c];
                events.push_back(e);
                s.flagged[k] = 1;
            }
        }
        if (!step && s.slope[k] >= t.steep.warn) {
            const int c = s.channel[k];
            LineEvent e;
            e.kind = FindingKind::Steep;
            e.channel = c;
            e.begin = i;
            e.end = i + 1;
            e.size = static_cast<float>(s.slope[k]);
            e.at = static_cast<float>(i) + 0.5f;
            e.from = v[i][c];
            e.to = v[i + 1][c];
            events.push_back(e);
            s.flagged[k] = 1;
        }
    }
}

// Second differences at the spacing of a 33-point lattice (a stride of samples on finer lines,
// scaled up from coarser ones), so a smooth curve gives the same figure at every lattice size and
// the quantisation of a dense table is not magnified.
void scanRough(const LineSpec& line, const ClipBounds& bounds, const CheckThresholds& t,
               const Segments& s, std::vector<LineEvent>& events) {
    constexpr double kReference = 1.0 / 32.0;
    const int k = std::max(1, static_cast<int>(std::lround(kReference / line.step)));
    const double scale = lut::math::pow(kReference / (k * line.step), 2.0);
    const glm::vec3* v = line.values;
    for (int i = k; i + k < line.count; ++i) {
        bool skip = false;
        for (int j = i - k; j < i + k && !skip; ++j)
            skip = s.flagged[static_cast<std::size_t>(j)] != 0;
        if (skip)
            continue;
        for (int c = 0; c < 3; ++c) {
            if (bounds.atBound(c, v[i - k][c]) || bounds.atBound(c, v[i][c]) ||
                bounds.atBound(c, v[i + k][c]))
                continue; // a kink where a clip starts is the clip's
            const double d2 =
                std::fabs(double(v[i + k][c]) - 2.0 * v[i][c] + v[i - k][c]) * kSteps * scale;
            if (d2 >= t.rough.warn) {
                LineEvent e;
                e.kind = FindingKind::Rough;
                e.channel = c;
                e.begin = i;
                e.end = i;
                e.size = static_cast<float>(d2);
                e.at = static_cast<float>(i);
                e.from = v[i][c];
                e.to = v[i][c];
                events.push_back(e);
            }
        }
    }
}

} // namespace

bool ClipBounds::heldNear(int c, float a, float b) const {
    constexpr float kStep = 1.0f / 255.0f;
    for (const auto* bounds :
         {&top[static_cast<std::size_t>(c)], &bottom[static_cast<std::size_t>(c)]})
        for (float v : *bounds)
            if (std::fabs(a - v) <= kStep && std::fabs(b - v) <= kStep)
                return true;
    return false;
}

void scanLine(const LineSpec& line, const ClipBounds& bounds, const CheckThresholds& thresholds,
              std::vector<LineEvent>& events, LineFigures& figures) {
    if (line.count < 2)
        return;
    Segments s = segmentsOf(line, bounds);
    if (line.ownChannel >= 0) {
        const int c = line.ownChannel;
        for (int i = 0; i + 1 < line.count; ++i)
            figures.ownVariation += std::fabs(double(line.values[i + 1][c]) - line.values[i][c]);
        figures.ownNet += std::fabs(double(line.values[line.count - 1][c]) - line.values[0][c]);
    }
    scanFolds(line, thresholds, s, events, figures);
    if (line.ownChannel >= 0)
        scanClips(line, bounds, s, events);
    scanBanding(line, thresholds, s, events, figures);
    if (line.ownChannel >= 0)
        scanRough(line, bounds, thresholds, s, events);
}

} // namespace lut::check
