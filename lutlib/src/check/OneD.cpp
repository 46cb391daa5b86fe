// SPDX-License-Identifier: Apache-2.0
// The LUT check of a file with only 1D tables: each channel's curve is one line (LineScan.h);
// events of one kind that touch along it make one finding.
#include "check/CheckDetail.h"
#include "check/LineScan.h"
#include "core/Printf.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lut::check {

namespace {

struct Group {
    FindingKind kind;
    int channel;
    int variant;
    int begin, end; // segments
    const LineEvent* worst;
    double score;
    double segments; // covered (clip: partial segments count in part)
};

FindingKind merged(FindingKind k) {
    return k == FindingKind::Step ? FindingKind::Flat : k;
}

// The share of the input range [a, b] (fractions of the domain) of channel c: its length, or
// the picture's pixels there.
double shareOf(const Context& ctx, int c, double a, double b) {
    if (!ctx.image())
        return std::max(0.0, b - a);
    const auto& w = ctx.channelWeights()[static_cast<std::size_t>(c)];
    double s = 0.0;
    const int i0 = std::clamp(static_cast<int>(a * 256.0), 0, 255);
    const int i1 = std::clamp(static_cast<int>(b * 256.0), 0, 255);
    for (int i = i0; i <= i1; ++i)
        s += w[static_cast<std::size_t>(i)];
    return s;
}

} // namespace

void scan1D(const Context& ctx, std::vector<CheckFinding>& findings, CheckFigures& figures) {
    const Lut1D& shaper = *ctx.shaper();
    const Lut1D& raw = *ctx.rawShaper();
    const int n = shaper.size();
    const double step = 1.0 / (n - 1);
    const CheckThresholds& t = ctx.thresholds();
    ClipBounds bounds;
    for (std::size_t c = 0; c < 3; ++c) {
        float lo = 0.0f, hi = 1.0f;
        for (const glm::vec3& e : shaper.entries()) {
            lo = std::min(lo, e[static_cast<int>(c)]);
            hi = std::max(hi, e[static_cast<int>(c)]);
        }
        bounds.top[c] = {1.0f, hi};
        bounds.bottom[c] = {0.0f, lo};
    }
    bool first = true;
    double variation = 0.0, net = 0.0, folded = 0.0, flat = 0.0, outside = 0.0;
    for (int c = 0; c < 3; ++c) {
        std::vector<glm::vec3> values(static_cast<std::size_t>(n), glm::vec3(0.0f));
        std::vector<LineEvent> events;
        for (int i = 0; i < n; ++i) {
            const float v = raw[i][c];
            values[static_cast<std::size_t>(i)][c] = shaper[i][c];
            LineEvent e;
            e.channel = c;
            e.begin = i;
            e.end = i;
            e.at = static_cast<float>(i);
            e.from = e.to = v;
            if (!std::isfinite(v)) {
                e.kind = FindingKind::NonFinite;
                e.size = 1.0f;
                events.push_back(e);
                ++figures.nonFinite;
                continue;
            }
            if (first) {
                figures.outputMin = figures.outputMax = glm::vec3(v);
                first = false;
            }
            figures.outputMin[c] = std::min(figures.outputMin[c], v);
            figures.outputMax[c] = std::max(figures.outputMax[c], v);
            if (v > 1.0f + 0.5f / 255.0f || v < -0.5f / 255.0f) {
                e.kind = FindingKind::OutOfRange;
                e.variant = v > 1.0f ? 0 : 1;
                e.size = (v > 1.0f ? double(v) - 1.0 : -double(v)) * 255.0;
                events.push_back(e);
                outside += (i == 0 || i == n - 1 ? 0.5 : 1.0) * step / 3.0;
            }
        }
        LineSpec line;
        line.values = values.data();
        line.count = n;
        line.step = step;
        line.direction = glm::ivec3(0);
        line.direction[c] = 1;
        line.ownChannel = c;
        LineFigures lf;
        scanLine(line, bounds, t, events, lf);
        variation += lf.ownVariation;
        net += lf.ownNet;
        figures.worstFold = std::max(figures.worstFold, lf.worstFold);
        figures.greyWorstFold = std::max(figures.greyWorstFold, lf.worstFold);
        figures.steepest = std::max(figures.steepest, lf.steepest);
        // Invertibility: segments against the curve's direction, or flat.
        const float dir = values.back()[c] >= values.front()[c] ? 1.0f : -1.0f;
        for (int i = 0; i + 1 < n; ++i) {
            const float d = dir * (values[static_cast<std::size_t>(i + 1)][c] -
                                   values[static_cast<std::size_t>(i)][c]);
            if (d < -1e-7f)
                folded += step / 3.0;
            else if (d <= 1e-7f)
                flat += step / 3.0;
        }
        // Events into groups: one kind (flats and steps together) touching along the curve.
        std::sort(events.begin(), events.end(), [](const LineEvent& a, const LineEvent& b) {
            return std::tuple(int(merged(a.kind)), a.variant, a.begin) <
                   std::tuple(int(merged(b.kind)), b.variant, b.begin);
        });
        std::vector<Group> groups;
        for (const LineEvent& e : events) {
            const double score = e.size / std::max(1e-9, thresholdFor(t, e.kind).warn);
            double segs = std::max(1, e.end - e.begin);
            if (e.kind == FindingKind::Clip)
                segs = (e.end - e.begin - 2) + e.firstFraction + e.lastFraction;
            if (!groups.empty() && merged(groups.back().kind) == merged(e.kind) &&
                groups.back().variant == e.variant && e.begin <= groups.back().end + 1) {
                Group& g = groups.back();
                g.end = std::max(g.end, e.end);
                g.segments += segs;
                if (score > g.score) {
                    g.score = score;
                    g.worst = &e;
                    g.kind = e.kind;
                }
                continue;
            }
            groups.push_back({e.kind, c, e.variant, e.begin, e.end, &e, score, segs});
        }
        for (const Group& g : groups) {
            const LineEvent& w = *g.worst;
            const double a = g.begin * step, b = std::max(g.end, g.begin + 1) * step;
            const double share = ctx.image() ? shareOf(ctx, c, a, b) : g.segments * step / 3.0;
            if (g.kind == FindingKind::Clip)
                figures.clippedShare[static_cast<std::size_t>(c)] += share;
            if (g.kind == FindingKind::Flat || g.kind == FindingKind::Step)
                figures.bandingShare += share;
            if (g.kind == FindingKind::FoldOver)
                figures.foldShare += share;
            if (g.kind == FindingKind::Rough)
                figures.worstRough = std::max(figures.worstRough, double(w.size));
            if (g.kind == FindingKind::Flat)
                figures.worstFlat = std::max(figures.worstFlat, double(w.size));
            if (g.kind == FindingKind::Step)
                figures.worstStep = std::max(figures.worstStep, double(w.size));
            CheckStatus severity;
            if (g.kind == FindingKind::Clip || g.kind == FindingKind::OutOfRange)
                severity = grade(100.0 * share, thresholdFor(t, g.kind));
            else if (g.kind == FindingKind::NonFinite)
                severity = grade(g.end - g.begin + 1, t.nonFinite);
            else
                severity = grade(w.size, thresholdFor(t, g.kind));
            if (severity == CheckStatus::Pass ||
                (ctx.image() && share <= 0.0 && g.kind != FindingKind::NonFinite))
                continue;
            CheckFinding f;
            f.kind = g.kind;
            f.severity = severity;
            f.channel = c;
            f.where = std::string("on the ") + channelName(c) + " curve";
            const double x = w.at * step;
            glm::vec3 u(static_cast<float>(x));
            f.input = ctx.fileInput(u);
            f.output = ctx.evaluate(f.input);
            f.size = g.kind == FindingKind::NonFinite ? g.end - g.begin + 1 : w.size;
            f.unit = g.kind == FindingKind::Steep       ? SizeUnit::Slope
                     : g.kind == FindingKind::NonFinite ? SizeUnit::Entries
                                                        : SizeUnit::Steps8;
            f.share = share;
            f.detail = lut::detail::fmt("input %.4f .. %.4f of the curve",
                                        ctx.fileInput(glm::vec3(float(a)))[c],
                                        ctx.fileInput(glm::vec3(float(b)))[c]);
            f.region.type = FindingRegion::Type::ChannelRange;
            f.region.channel = c;
            f.region.lo = ctx.fileInput(glm::vec3(float(a)))[c];
            f.region.hi = ctx.fileInput(glm::vec3(float(b)))[c];
            findings.push_back(std::move(f));
        }
    }
    figures.totalVariationRatio = net > 0.0 ? variation / net : 1.0;
    figures.foldedShare = folded;
    figures.flatShare = flat;
    figures.outOfRangeShare = outside;
}

} // namespace lut::check
