// SPDX-License-Identifier: Apache-2.0
// Flags into findings: flags of one kind whose cells touch (26-neighbourhood) make one finding,
// located at its worst flag, sized by it, with the share of the cube (or picture) its lattice
// edges stand for.
#include "check/CheckDetail.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

namespace lut::check {

namespace {

// Flats and steps of one region are one banding finding (a posterised band has both).
FindingKind groupKind(FindingKind k) {
    return k == FindingKind::Step ? FindingKind::Flat : k;
}

bool perChannel(FindingKind k) {
    return k == FindingKind::FoldOver || k == FindingKind::Clip || k == FindingKind::OutOfRange;
}

using Key = std::tuple<int, int, int>; // kind, channel, variant

Key keyOf(const Flag& f) {
    const FindingKind k = groupKind(f.kind);
    return {static_cast<int>(k), perChannel(k) ? f.channel : -1,
            k == FindingKind::Clip || k == FindingKind::OutOfRange ? f.variant : 0};
}

SizeUnit unitOf(FindingKind k) {
    switch (k) {
    case FindingKind::Steep:
        return SizeUnit::Slope;
    case FindingKind::NonFinite:
        return SizeUnit::Entries;
    case FindingKind::HueShift:
    case FindingKind::SkinDrift:
        return SizeUnit::Degrees;
    default:
        return SizeUnit::Steps8;
    }
}

std::string whereOf(const Flag& f) {
    if (f.ray >= 0)
        return std::string("on the ") + rays()[static_cast<std::size_t>(f.ray)].name;
    if (f.axis >= 0 && f.axis < 3)
        return std::string("along ") + channelName(f.axis);
    return "";
}

std::string number(double v, int digits = 2) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

std::string detailOf(const Flag& f) {
    switch (f.kind) {
    case FindingKind::FoldOver:
        return std::string("output ") + channelLetter(f.channel) + " falls from " +
               number(f.from, 4) + " to " + number(f.to, 4) + " while input " +
               channelLetter(f.channel) + " rises";
    case FindingKind::Flat:
        return std::string("output ") + channelLetter(f.channel) + " stays at " +
               number(f.from, 4) + " over " + number(f.to, 1) + " input 8-bit steps";
    case FindingKind::Step:
    case FindingKind::Steep:
        return std::string("output ") + channelLetter(f.channel) + " jumps from " +
               number(f.from, 4) + " to " + number(f.to, 4) + " in one lattice step";
    case FindingKind::Clip:
        return std::string("output ") + channelLetter(f.channel) + " held at " + number(f.from, 4);
    case FindingKind::OutOfRange:
        return std::string("output ") + channelLetter(f.channel) + " = " + number(f.from, 4);
    case FindingKind::Rough:
        return std::string("output ") + channelLetter(f.channel) +
               " bends sharply (second difference on a 33-point lattice)";
    default:
        return "";
    }
}

// Connected components of the cells flagged in one group (26-neighbourhood).
// cellsOf[k]: the cells of component k, sorted.
std::vector<int> components(const Context& ctx, const std::vector<const Flag*>& flags, int& count,
                            std::vector<std::vector<std::uint32_t>>& cellsOf) {
    const int cells = ctx.cellsPerAxis();
    std::vector<int> label(static_cast<std::size_t>(cells) * cells * cells, -2); // -2: not flagged
    std::vector<std::uint32_t> flagged;
    for (const Flag* f : flags)
        for (std::uint8_t i = 0; i < f->cellCount; ++i)
            if (label[f->cells[i]] == -2) {
                label[f->cells[i]] = -1;
                flagged.push_back(f->cells[i]);
            }
    std::sort(flagged.begin(), flagged.end()); // components numbered in cell order
    count = 0;
    std::vector<std::uint32_t> stack;
    for (std::uint32_t seed : flagged) {
        if (label[seed] >= 0)
            continue;
        label[seed] = count;
        stack.assign(1, seed);
        while (!stack.empty()) {
            const std::uint32_t c = stack.back();
            stack.pop_back();
            const int r = static_cast<int>(c % cells), g = static_cast<int>((c / cells) % cells),
                      b = static_cast<int>(c / (static_cast<std::uint32_t>(cells) * cells));
            for (int dz = -1; dz <= 1; ++dz)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int x = r + dx, y = g + dy, z = b + dz;
                        if (x < 0 || y < 0 || z < 0 || x >= cells || y >= cells || z >= cells)
                            continue;
                        const std::uint32_t n = ctx.cellIndex(x, y, z);
                        if (label[n] == -1) {
                            label[n] = count;
                            stack.push_back(n);
                        }
                    }
        }
        ++count;
    }
    cellsOf.assign(static_cast<std::size_t>(count), {});
    for (std::uint32_t c : flagged)
        cellsOf[static_cast<std::size_t>(label[c])].push_back(c);
    std::vector<int> of(flags.size());
    for (std::size_t i = 0; i < flags.size(); ++i)
        of[i] = flags[i]->cellCount ? label[flags[i]->cells[0]] : 0;
    return of;
}

} // namespace

void groupFlags(const Context& ctx, std::vector<Flag>& flags, std::vector<CheckFinding>& findings,
                CheckFigures& figures) {
    const CheckThresholds& t = ctx.thresholds();
    std::map<Key, std::vector<const Flag*>> groups;
    for (const Flag& f : flags)
        groups[keyOf(f)].push_back(&f);
    const int cells = ctx.cellsPerAxis();
    for (const auto& [key, members] : groups) {
        int count = 0;
        std::vector<std::vector<std::uint32_t>> cellsOf;
        const std::vector<int> comp = components(ctx, members, count, cellsOf);
        struct Acc {
            const Flag* worst = nullptr;
            double score = -1.0;
            double axisShare[4] = {0, 0, 0, 0};
            double entries = 0.0;
            std::vector<std::uint32_t> cells;
        };
        std::vector<Acc> acc(static_cast<std::size_t>(count));
        for (std::size_t i = 0; i < members.size(); ++i) {
            const Flag& f = *members[i];
            Acc& a = acc[static_cast<std::size_t>(comp[i])];
            // A banding region with steps is a posterised one: sized by its largest step.
            const double score = f.size / std::max(1e-9, thresholdFor(t, f.kind).warn) +
                                 (f.kind == FindingKind::Step ? 1e6 : 0.0);
            if (score > a.score) {
                a.score = score;
                a.worst = &f;
            }
            if (f.point)
                a.axisShare[3] += f.share;
            else if (f.axis >= 0 && f.axis < 3)
                a.axisShare[f.axis] += f.share;
            a.entries += 1.0;
        }
        for (std::size_t k = 0; k < acc.size(); ++k)
            acc[k].cells = std::move(cellsOf[k]);
        for (Acc& a : acc) {
            if (!a.worst)
                continue;
            const Flag& w = *a.worst;
            const FindingKind kind = w.kind;
            double share =
                std::max({a.axisShare[0], a.axisShare[1], a.axisShare[2], a.axisShare[3]});
            double touched = 0.0; // the weight of the cells it touches (a ray has no volume)
            for (std::uint32_t c : a.cells)
                touched += ctx.cellWeight(c);
            // The figures count every flag, reported or not.
            switch (groupKind(kind)) {
            case FindingKind::FoldOver:
                figures.foldShare += share;
                break;
            case FindingKind::Flat:
            case FindingKind::Steep:
                figures.bandingShare += share;
                break;
            case FindingKind::Clip:
                figures.clippedShare[static_cast<std::size_t>(std::clamp<int>(w.channel, 0, 2))] +=
                    share;
                break;
            default:
                break;
            }
            if (kind == FindingKind::Flat || kind == FindingKind::Step)
                (kind == FindingKind::Flat ? figures.worstFlat : figures.worstStep) =
                    std::max(kind == FindingKind::Flat ? figures.worstFlat : figures.worstStep,
                             double(w.size));
            if (kind == FindingKind::Rough)
                figures.worstRough = std::max(figures.worstRough, double(w.size));
            if (ctx.image() && touched <= 0.0 && kind != FindingKind::NonFinite)
                continue; // no pixel of the picture has these colours
            CheckStatus severity;
            if (kind == FindingKind::Clip || kind == FindingKind::OutOfRange)
                severity = grade(100.0 * share, thresholdFor(t, kind));
            else if (kind == FindingKind::NonFinite)
                severity = grade(a.entries, t.nonFinite);
            else
                severity = grade(w.size, thresholdFor(t, kind));
            if (severity == CheckStatus::Pass)
                continue;
            CheckFinding f;
            f.kind = kind;
            f.severity = severity;
            f.channel = perChannel(kind) || kind == FindingKind::Flat ||
                                kind == FindingKind::Step || kind == FindingKind::Steep ||
                                kind == FindingKind::Rough
                            ? w.channel
                            : -1;
            f.where = whereOf(w);
            f.input = ctx.fileInput(w.at);
            f.output = ctx.evaluate(f.input);
            for (int c = 0; c < 3; ++c)
                f.cell[c] =
                    std::clamp(static_cast<int>(std::floor(w.at[c] * cells + 1e-4f)), 0, cells - 1);
            f.size = kind == FindingKind::NonFinite ? a.entries : w.size;
            f.unit = unitOf(kind);
            f.share = share;
            f.detail = detailOf(w);
            f.region.type = FindingRegion::Type::Cells;
            f.region.cells = std::move(a.cells);
            f.region.latticeSize = ctx.size();
            f.region.domainMin = ctx.table().domainMin();
            f.region.domainMax = ctx.table().domainMax();
            f.region.shaper = ctx.shaper();
            findings.push_back(std::move(f));
        }
    }
}

} // namespace lut::check
