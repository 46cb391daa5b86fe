// SPDX-License-Identifier: Apache-2.0
// The lattice and ray scans of the LUT check: every lattice line along each axis and every ray
// through scanLine (LineScan.h), their events turned into flags on the cells they touch.
#include "check/CheckDetail.h"
#include "check/LineScan.h"

#include "lut/Parallel.h"

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <mutex>

namespace lut::check {

namespace {

// clang-format off
const std::vector<Ray> kRays = {
    {"grey axis",        {0, 0, 0}, {1, 1, 1}, {1, 1, 1}, false},
    {"black to red",     {0, 0, 0}, {1, 0, 0}, {1, 0, 0}, true},
    {"black to green",   {0, 0, 0}, {0, 1, 0}, {0, 1, 0}, true},
    {"black to blue",    {0, 0, 0}, {0, 0, 1}, {0, 0, 1}, true},
    {"black to cyan",    {0, 0, 0}, {0, 1, 1}, {0, 1, 1}, false},
    {"black to magenta", {0, 0, 0}, {1, 0, 1}, {1, 0, 1}, false},
    {"black to yellow",  {0, 0, 0}, {1, 1, 0}, {1, 1, 0}, false},
    {"red to white",     {1, 0, 0}, {1, 1, 1}, {0, 1, 1}, false},
    {"green to white",   {0, 1, 0}, {1, 1, 1}, {1, 0, 1}, false},
    {"blue to white",    {0, 0, 1}, {1, 1, 1}, {1, 1, 0}, false},
    // The line through the ColorChecker's dark skin (115, 82, 68) and light skin (194, 150, 130)
    // sRGB patches, from near black to where red reaches 1.
    {"skin line",        {0.2030f, 0.1094f, 0.0730f}, {0.9935f, 0.7875f, 0.6923f}, {1, 1, 1}, false},
};
// clang-format on

ClipBounds clipBounds(const Lut3D& table) {
    glm::vec3 lo(0.0f), hi(1.0f);
    if (!table.entries().empty()) {
        lo = hi = table.entries().front();
        for (const glm::vec3& e : table.entries()) {
            lo = glm::min(lo, e);
            hi = glm::max(hi, e);
        }
    }
    ClipBounds b;
    for (std::size_t c = 0; c < 3; ++c) {
        b.top[c] = {1.0f, hi[static_cast<int>(c)]};
        b.bottom[c] = {0.0f, lo[static_cast<int>(c)]};
    }
    return b;
}

// The cells around lattice edge (p, p + e_axis), with the edge's share of the cube.
void edgeCells(const Context& ctx, glm::ivec3 p, int axis, Flag& f) {
    const int cells = ctx.cellsPerAxis();
    const int o1 = (axis + 1) % 3, o2 = (axis + 2) % 3;
    f.cellCount = 0;
    float weight = 0.0f;
    for (int d1 = -1; d1 <= 0; ++d1)
        for (int d2 = -1; d2 <= 0; ++d2) {
            glm::ivec3 c = p;
            c[o1] += d1;
            c[o2] += d2;
            if (c[o1] < 0 || c[o1] >= cells || c[o2] < 0 || c[o2] >= cells)
                continue;
            const std::uint32_t idx = ctx.cellIndex(c.x, c.y, c.z);
            f.cells[f.cellCount++] = idx;
            weight += ctx.cellWeight(idx) / 4.0f;
        }
    f.share = weight;
}

// The cells a ray's segment between lattice points a and b passes through.
void segmentCells(const Context& ctx, glm::ivec3 a, glm::ivec3 b, Flag& f) {
    const int cells = ctx.cellsPerAxis();
    f.cellCount = 0;
    glm::ivec3 lo = glm::min(a, b);
    int spread[3][2];
    int counts[3];
    for (int c = 0; c < 3; ++c) {
        if (a[c] != b[c]) {
            spread[c][0] = std::min(lo[c], cells - 1);
            counts[c] = 1;
        } else {
            counts[c] = 0;
            for (int d = -1; d <= 0; ++d)
                if (a[c] + d >= 0 && a[c] + d < cells)
                    spread[c][counts[c]++] = a[c] + d;
        }
    }
    for (int i = 0; i < counts[0]; ++i)
        for (int j = 0; j < counts[1]; ++j)
            for (int k = 0; k < counts[2]; ++k)
                if (f.cellCount < f.cells.size())
                    f.cells[f.cellCount++] =
                        ctx.cellIndex(spread[0][i], spread[1][j], spread[2][k]);
    f.share = 0.0f;
}

// The cell holding table coordinates u.
std::uint32_t cellAt(const Context& ctx, glm::vec3 u) {
    const int cells = ctx.cellsPerAxis();
    int idx[3];
    for (int c = 0; c < 3; ++c)
        idx[c] = std::clamp(static_cast<int>(u[c] * cells), 0, cells - 1);
    return ctx.cellIndex(idx[0], idx[1], idx[2]);
}

// The cells around lattice point p, with its share of the cube.
void pointCells(const Context& ctx, glm::ivec3 p, Flag& f) {
    const int cells = ctx.cellsPerAxis();
    f.cellCount = 0;
    float weight = 0.0f;
    for (int dz = -1; dz <= 0; ++dz)
        for (int dy = -1; dy <= 0; ++dy)
            for (int dx = -1; dx <= 0; ++dx) {
                const glm::ivec3 c = p + glm::ivec3(dx, dy, dz);
                if (glm::any(glm::lessThan(c, glm::ivec3(0))) ||
                    glm::any(glm::greaterThanEqual(c, glm::ivec3(cells))))
                    continue;
                const std::uint32_t idx = ctx.cellIndex(c.x, c.y, c.z);
                f.cells[f.cellCount++] = idx;
                weight += ctx.cellWeight(idx) / 8.0f;
            }
    f.share = weight;
}

Flag flagFrom(const LineEvent& e) {
    Flag f;
    f.kind = e.kind;
    f.channel = static_cast<std::int8_t>(e.channel);
    f.variant = static_cast<std::int8_t>(e.variant);
    f.size = e.size;
    f.from = e.from;
    f.to = e.to;
    return f;
}

// One lattice line's events as flags: one per edge it covers (one per point for second
// differences).
void latticeFlags(const Context& ctx, int axis, glm::ivec3 start, const std::vector<LineEvent>& ev,
                  std::vector<Flag>& out) {
    const float scale = 1.0f / static_cast<float>(ctx.cellsPerAxis());
    for (const LineEvent& e : ev) {
        Flag f = flagFrom(e);
        f.axis = static_cast<std::int8_t>(axis);
        glm::vec3 at = glm::vec3(start) * scale;
        at[axis] = e.at * scale;
        f.at = at;
        if (e.kind == FindingKind::Rough) {
            glm::ivec3 p = start;
            p[axis] = e.begin;
            pointCells(ctx, p, f);
            f.point = true;
            out.push_back(f);
            continue;
        }
        for (int s = e.begin; s < e.end; ++s) {
            glm::ivec3 p = start;
            p[axis] = s;
            Flag g = f;
            edgeCells(ctx, p, axis, g);
            if (e.kind == FindingKind::Clip)
                g.share *= s == e.begin ? e.firstFraction : s == e.end - 1 ? e.lastFraction : 1.0f;
            out.push_back(g);
        }
    }
}

void scanRays(const Context& ctx, const ClipBounds& bounds, std::vector<Flag>& flags,
              CheckFigures& figures) {
    const int n = ctx.size();
    const bool plain = !ctx.shaper();
    for (std::size_t r = 0; r < kRays.size(); ++r) {
        const Ray& ray = kRays[r];
        if (ray.latticeLine && plain)
            continue; // scanned with the lattice lines
        const bool onLattice = plain && static_cast<int>(r) != kSkinRay;
        const int m = onLattice ? n : std::max(n, 33);
        std::vector<glm::vec3> values(static_cast<std::size_t>(m));
        std::vector<glm::vec3> u(static_cast<std::size_t>(m));
        for (int i = 0; i < m; ++i) {
            const float t = static_cast<float>(i) / static_cast<float>(m - 1);
            u[static_cast<std::size_t>(i)] = ray.from + (ray.to - ray.from) * t;
            values[static_cast<std::size_t>(i)] =
                ctx.inputMin() + (ctx.inputMax() - ctx.inputMin()) * u[static_cast<std::size_t>(i)];
        }
        ctx.evaluate(values);
        const glm::vec3 span = glm::abs(ray.to - ray.from);
        LineSpec line;
        line.values = values.data();
        line.count = m;
        line.step = std::max({span.x, span.y, span.z}) / (m - 1);
        line.direction = ray.direction;
        std::vector<LineEvent> events;
        LineFigures lf;
        scanLine(line, bounds, ctx.thresholds(), events, lf);
        if (r == 0)
            figures.greyWorstFold = lf.worstFold;
        for (const LineEvent& e : events) {
            Flag f = flagFrom(e);
            f.ray = static_cast<std::int8_t>(r);
            f.at = ctx.tableCoordinates(ctx.inputMin() +
                                        (ctx.inputMax() - ctx.inputMin()) *
                                            (ray.from + (ray.to - ray.from) * (e.at / (m - 1))));
            for (int s = e.begin; s < std::max(e.end, e.begin + 1) && s + 1 < m; ++s) {
                Flag g = f;
                if (onLattice) {
                    const glm::vec3 a = u[static_cast<std::size_t>(s)] * float(n - 1);
                    const glm::vec3 b = u[static_cast<std::size_t>(s + 1)] * float(n - 1);
                    segmentCells(ctx, glm::ivec3(glm::round(a)), glm::ivec3(glm::round(b)), g);
                } else {
                    const glm::vec3 mid = 0.5f * (u[static_cast<std::size_t>(s)] +
                                                  u[static_cast<std::size_t>(s + 1)]);
                    g.cells[0] =
                        cellAt(ctx, ctx.tableCoordinates(ctx.inputMin() +
                                                         (ctx.inputMax() - ctx.inputMin()) * mid));
                    g.cellCount = 1;
                    g.share = 0.0f;
                }
                flags.push_back(g);
            }
        }
    }
}

} // namespace

const std::vector<Ray>& rays() {
    return kRays;
}

void scanLattice(const Context& ctx, std::vector<Flag>& flags, CheckFigures& figures) {
    const Lut3D& table = ctx.table();
    const int n = table.size();
    const ClipBounds bounds = clipBounds(table);
    const int lines = 3 * n * n;
    const double step = 1.0 / (n - 1);
    std::vector<double> variation(static_cast<std::size_t>(lines)), net(variation.size());
    std::vector<char> falling(variation.size(), 0);
    std::map<int, std::vector<Flag>> chunks;
    std::mutex mutex;
    double worstFold = 0.0, steepest = 0.0;
    // Behind a 1D shaper a lattice step is not a fixed input step: each one's input distance in
    // the file (per axis, through the shaper's inverse), so slopes are what the file does, the
    // shaper then the table, as OpenColorIO applies it.
    std::array<std::vector<double>, 3> inputSteps;
    if (ctx.shaper()) {
        const glm::vec3 span = ctx.inputMax() - ctx.inputMin();
        for (int i = 0; i + 1 < n; ++i) {
            const glm::vec3 a = ctx.fileInput(glm::vec3(static_cast<float>(i) / (n - 1)));
            const glm::vec3 b = ctx.fileInput(glm::vec3(static_cast<float>(i + 1) / (n - 1)));
            for (int c = 0; c < 3; ++c)
                inputSteps[static_cast<std::size_t>(c)].push_back(
                    span[c] > 0.0f ? std::fabs(double(b[c]) - a[c]) / span[c] : step);
        }
    }
    parallelFor(lines, ctx.nthreads(), [&](int begin, int end) {
        std::vector<Flag> local;
        std::vector<glm::vec3> values(static_cast<std::size_t>(n));
        std::vector<LineEvent> events;
        double localFold = 0.0, localSteep = 0.0;
        for (int l = begin; l < end; ++l) {
            const int axis = l / (n * n);
            const int j = (l / n) % n, k = l % n;
            glm::ivec3 start(0);
            start[(axis + 1) % 3] = j;
            start[(axis + 2) % 3] = k;
            for (int i = 0; i < n; ++i) {
                glm::ivec3 p = start;
                p[axis] = i;
                values[static_cast<std::size_t>(i)] = table.at(p.x, p.y, p.z);
            }
            LineSpec line;
            line.values = values.data();
            line.count = n;
            line.step = step;
            if (ctx.shaper())
                line.segmentSteps = inputSteps[static_cast<std::size_t>(axis)].data();
            line.direction = glm::ivec3(0);
            line.direction[axis] = 1;
            line.ownChannel = axis;
            events.clear();
            LineFigures lf;
            scanLine(line, bounds, ctx.thresholds(), events, lf);
            variation[static_cast<std::size_t>(l)] = lf.ownVariation;
            net[static_cast<std::size_t>(l)] = lf.ownNet;
            falling[static_cast<std::size_t>(l)] =
                values[static_cast<std::size_t>(n - 1)][axis] < values[0][axis] ? 1 : 0;
            localFold = std::max(localFold, lf.worstFold);
            localSteep = std::max(localSteep, lf.steepest);
            latticeFlags(ctx, axis, start, events, local);
        }
        std::lock_guard<std::mutex> lock(mutex);
        chunks[begin] = std::move(local);
        worstFold = std::max(worstFold, localFold);
        steepest = std::max(steepest, localSteep);
    });
    for (auto& [begin, chunk] : chunks)
        flags.insert(flags.end(), chunk.begin(), chunk.end());
    double totalVariation = 0.0, totalNet = 0.0;
    for (std::size_t i = 0; i < variation.size(); ++i) {
        totalVariation += variation[i];
        totalNet += net[i];
    }
    figures.totalVariationRatio = totalNet > 0.0 ? totalVariation / totalNet : 1.0;
    figures.fallingShare =
        static_cast<double>(std::count(falling.begin(), falling.end(), 1)) / lines;
    figures.worstFold = std::max(figures.worstFold, worstFold);
    figures.steepest = std::max(figures.steepest, steepest);
    scanRays(ctx, bounds, flags, figures);
}

void scanEntries(const Context& ctx, std::vector<Flag>& flags, CheckFigures& figures) {
    const Lut3D& raw = *ctx.rawTable();
    const int n = raw.size();
    const float scale = 1.0f / static_cast<float>(n - 1);
    constexpr float kHalfStep = 0.5f / 255.0f;
    bool first = true;
    double outsideShare = 0.0;
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 e = raw.at(r, g, b);
                const glm::ivec3 p(r, g, b);
                const bool finite = std::isfinite(e.x) && std::isfinite(e.y) && std::isfinite(e.z);
                if (!finite) {
                    Flag f;
                    f.kind = FindingKind::NonFinite;
                    f.point = true;
                    f.size = 1.0f;
                    f.at = glm::vec3(p) * scale;
                    pointCells(ctx, p, f);
                    flags.push_back(f);
                    ++figures.nonFinite;
                    continue;
                }
                if (first) {
                    figures.outputMin = figures.outputMax = e;
                    first = false;
                }
                figures.outputMin = glm::min(figures.outputMin, e);
                figures.outputMax = glm::max(figures.outputMax, e);
                bool outside = false;
                for (int c = 0; c < 3; ++c) {
                    const float over = e[c] > 1.0f + kHalfStep ? e[c] - 1.0f
                                       : e[c] < -kHalfStep     ? -e[c]
                                                               : 0.0f;
                    if (over <= 0.0f)
                        continue;
                    Flag f;
                    f.kind = FindingKind::OutOfRange;
                    f.channel = static_cast<std::int8_t>(c);
                    f.variant = e[c] > 1.0f ? 0 : 1;
                    f.point = true;
                    f.size = double(over) * 255.0;
                    f.from = f.to = e[c];
                    f.at = glm::vec3(p) * scale;
                    pointCells(ctx, p, f);
                    if (!outside)
                        outsideShare += f.share;
                    outside = true;
                    flags.push_back(f);
                }
            }
    figures.outOfRangeShare = outsideShare;
}

} // namespace lut::check
