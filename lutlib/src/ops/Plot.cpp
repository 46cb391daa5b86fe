// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Plot.h"

#include "lut/Error.h"
#include "lut/Math.h"
#include "lut/interp/Sampler.h"
#include "ops/Canvas.h"
#include "ops/OpsDetail.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace lut {

namespace {

// clang-format off
constexpr int kWidth = 1356, kHeight = 420;
constexpr int kPanelTop = 68, kPanel = 300;            // curve and lattice panels
constexpr int kCurvesX = 60, kSlicesX = 400, kLatticeX = 1036;
constexpr int kSlice = 180, kSliceGap = 24;
// clang-format on
const glm::vec3 kBackground(0.13f), kPanelBg(0.07f), kGrid(0.22f), kInk(0.85f), kDim(0.5f);
const glm::vec3 kChannel[3] = {{1.0f, 0.32f, 0.32f}, {0.35f, 0.95f, 0.35f}, {0.45f, 0.6f, 1.0f}};

glm::vec3 display(glm::vec3 v) {
    return glm::clamp(v, glm::vec3(0.0f), glm::vec3(1.0f));
}

std::string label(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

std::string upperTitle(const Lut3D& lut) {
    std::string t = lut.title().empty() ? "LUT" : lut.title();
    if (t.size() > 48)
        t = t.substr(0, 45) + "...";
    char buf[96];
    std::snprintf(buf, sizeof buf, "  SIZE %d", lut.size());
    t += buf;
    if (!lut.hasDefaultDomain())
        t += "  DOMAIN " + label(lut.domainMin().x) + ".." + label(lut.domainMax().x);
    return t;
}

void drawCurves(detail::Canvas& cv, const Sampler& s, const Lut3D& lut, PlotLayout& layout) {
    const PlotRect r{kCurvesX, kPanelTop, kPanel, kPanel};
    constexpr int kSamples = kPanel;
    std::vector<glm::vec3> out(kSamples);
    float lo = 0.0f, hi = 1.0f;
    for (int i = 0; i < kSamples; ++i) {
        const float t = static_cast<float>(i) / (kSamples - 1);
        out[static_cast<std::size_t>(i)] =
            s.sample(lut.domainMin() + (lut.domainMax() - lut.domainMin()) * t);
        for (int c = 0; c < 3; ++c) {
            lo = std::min(lo, out[static_cast<std::size_t>(i)][c]);
            hi = std::max(hi, out[static_cast<std::size_t>(i)][c]);
        }
    }
    // Round the range out to quarters, within [-1, 2].
    layout.curveMin = std::max(-1.0, std::floor(lo * 4.0) / 4.0);
    layout.curveMax = std::min(2.0, std::ceil(hi * 4.0) / 4.0);
    layout.curves = r;
    const double span = layout.curveMax - layout.curveMin;
    auto px = [&](double t) { return r.x + t * (r.width - 1); };
    auto py = [&](double v) { return r.y + (r.height - 1) * (1.0 - (v - layout.curveMin) / span); };
    cv.rect(r.x, r.y, r.width, r.height, kPanelBg);
    for (int q = 1; q < 4; ++q)
        cv.line(px(q / 4.0), r.y, px(q / 4.0), r.y + r.height - 1, kGrid, 1.0);
    for (double v = layout.curveMin; v <= layout.curveMax + 1e-9; v += 0.25)
        cv.line(r.x, py(v), r.x + r.width - 1, py(v), kGrid, 1.0);
    // The identity, dashed.
    for (int k = 0; k < 20; k += 2)
        cv.line(px(k / 20.0), py(k / 20.0), px((k + 1) / 20.0), py((k + 1) / 20.0), kDim, 1.0);
    // Added, so where curves coincide they mix: all three on top of each other draw white.
    for (int c = 0; c < 3; ++c) {
        std::vector<glm::dvec2> pts;
        for (int i = 0; i < kSamples; ++i)
            pts.emplace_back(px(static_cast<double>(i) / (kSamples - 1)),
                             py(std::clamp<double>(out[static_cast<std::size_t>(i)][c],
                                                   layout.curveMin, layout.curveMax)));
        cv.polyline(pts, kChannel[c], 2.0, true);
    }
    cv.frame(r.x - 1, r.y - 1, r.width + 2, r.height + 2, kDim);
    cv.text(r.x, r.y - 24, "NEUTRAL AXIS: OUT VS IN", kInk);
    // Ticks: inputs under the panel, outputs on the left.
    for (double t : {0.0, 0.5, 1.0}) {
        const std::string s = label(t);
        cv.text(static_cast<int>(px(t)) - detail::Canvas::textWidth(s) / 2, r.y + r.height + 6, s,
                kInk);
    }
    for (double v : {layout.curveMin, 0.0, 0.5, 1.0, layout.curveMax}) {
        if (v < layout.curveMin || v > layout.curveMax)
            continue;
        const std::string s = label(v);
        cv.text(r.x - 8 - detail::Canvas::textWidth(s), static_cast<int>(py(v)) - 7, s, kInk);
    }
    cv.text(r.x + r.width / 2 - 8, r.y + r.height + 24, "IN", kDim);
    // Legend.
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c)
        cv.text(r.x + 8 + c * 20, r.y + 8, names[c], kChannel[c]);
}

void drawSlices(detail::Canvas& cv, const Sampler& s, const Lut3D& lut, PlotLayout& layout) {
    const glm::vec3 lo = lut.domainMin(), hi = lut.domainMax();
    cv.text(kSlicesX, kPanelTop - 24, "SLICES: R RIGHT, G UP", kInk);
    for (int k = 0; k < 3; ++k) {
        const PlotRect r{kSlicesX + k * (kSlice + kSliceGap), kPanelTop, kSlice, kSlice};
        layout.slices[static_cast<std::size_t>(k)] = r;
        const float blue = layout.sliceBlue[static_cast<std::size_t>(k)];
        for (int y = 0; y < kSlice; ++y)
            for (int x = 0; x < kSlice; ++x) {
                const glm::vec3 t(static_cast<float>(x) / (kSlice - 1),
                                  1.0f - static_cast<float>(y) / (kSlice - 1), blue);
                cv.rect(r.x + x, r.y + y, 1, 1, display(s.sample(lo + (hi - lo) * t)));
            }
        cv.frame(r.x - 1, r.y - 1, r.width + 2, r.height + 2, kDim);
        const std::string name = "B=" + label(blue);
        cv.text(r.x + (r.width - detail::Canvas::textWidth(name)) / 2, r.y + r.height + 8, name,
                kInk);
    }
}

struct Projected {
    double x, y, depth;
};

void drawLattice(detail::Canvas& cv, const Sampler& s, const Lut3D& lut, int points,
                 PlotLayout& layout) {
    const PlotRect r{kLatticeX, kPanelTop, kPanel, kPanel};
    layout.lattice = r;
    cv.rect(r.x, r.y, r.width, r.height, kPanelBg);
    cv.frame(r.x - 1, r.y - 1, r.width + 2, r.height + 2, kDim);
    cv.text(r.x, r.y - 24, "LATTICE AT ITS OUTPUTS", kInk);
    constexpr double kAzimuth = 30.0 * std::numbers::pi / 180.0;
    constexpr double kElevation = 25.0 * std::numbers::pi / 180.0;
    const glm::dvec3 up = glm::dvec3(1, 1, 1) / std::sqrt(3.0);
    const glm::dvec3 e1 = glm::dvec3(1, -1, 0) / std::sqrt(2.0);
    const glm::dvec3 e2 = glm::dvec3(1, 1, -2) / std::sqrt(6.0);
    const glm::dvec3 right = lut::math::cos(kAzimuth) * e1 + lut::math::sin(kAzimuth) * e2;
    const glm::dvec3 front = -lut::math::sin(kAzimuth) * e1 + lut::math::cos(kAzimuth) * e2;
    const glm::dvec3 toViewer =
        lut::math::cos(kElevation) * front + lut::math::sin(kElevation) * up;
    const glm::dvec3 screenUp =
        -lut::math::sin(kElevation) * front + lut::math::cos(kElevation) * up;
    const double scale = 0.44 * r.width;
    const double cx = r.x + 0.5 * r.width, cy = r.y + 0.5 * r.height;
    auto project = [&](glm::dvec3 p) {
        const glm::dvec3 q = p - 0.5;
        return Projected{cx + scale * glm::dot(q, right), cy - scale * glm::dot(q, screenUp),
                         glm::dot(q, toViewer)};
    };
    // The identity cube's edges and corners.
    const glm::dvec3 corners[8] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                   {1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
    const char* names[8] = {"K", "R", "G", "B", "Y", "M", "C", "W"};
    for (int i = 0; i < 8; ++i)
        for (int j = i + 1; j < 8; ++j) {
            const glm::dvec3 d = corners[j] - corners[i];
            if (std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z) != 1.0)
                continue;
            const Projected a = project(corners[i]), b = project(corners[j]);
            cv.line(a.x, a.y, b.x, b.y, kGrid, 1.0);
        }
    // Grid points at their outputs, far ones first.
    const int k = std::clamp(points, 2, 17);
    struct Dot {
        Projected at;
        glm::vec3 colour;
    };
    std::vector<Dot> dots;
    const glm::vec3 lo = lut.domainMin(), hi = lut.domainMax();
    for (int b = 0; b < k; ++b)
        for (int g = 0; g < k; ++g)
            for (int rr = 0; rr < k; ++rr) {
                const glm::vec3 t = glm::vec3(rr, g, b) / static_cast<float>(k - 1);
                const glm::vec3 out = s.sample(lo + (hi - lo) * t);
                dots.push_back({project(glm::dvec3(out)), display(out)});
            }
    std::stable_sort(dots.begin(), dots.end(),
                     [](const Dot& a, const Dot& b) { return a.at.depth < b.at.depth; });
    const double radius = k <= 5 ? 5.0 : k <= 9 ? 4.0 : 2.5;
    for (const Dot& d : dots) {
        if (d.at.x < r.x || d.at.x > r.x + r.width - 1 || d.at.y < r.y ||
            d.at.y > r.y + r.height - 1)
            continue; // far outside the cube: not drawn over the other panels
        cv.disc(d.at.x, d.at.y, radius + 1.0, kPanelBg);
        cv.disc(d.at.x, d.at.y, radius, d.colour);
    }
    for (int i = 0; i < 8; ++i) {
        const Projected p = project(corners[i]);
        const Projected c = project(glm::dvec3(0.5));
        const double dx = p.x - c.x, dy = p.y - c.y, len = std::max(1.0, lut::math::hypot(dx, dy));
        cv.text(static_cast<int>(p.x + 16 * dx / len) - 5,
                static_cast<int>(p.y + 16 * dy / len) - 7, names[i], kDim);
    }
}

} // namespace

Plot plotLut(const Lut3D& lut, const PlotOptions& options) {
    if (lut.empty())
        throw Error("plot: the LUT has no entries");
    std::size_t replaced = 0;
    const Lut3D clean = detail::sanitizedCopy(lut, replaced);
    const auto sampler = makeSampler(clean, options.method);
    Plot plot;
    plot.image = Image(kWidth, kHeight);
    detail::Canvas cv(plot.image);
    cv.fill(kBackground);
    cv.text(16, 12, upperTitle(lut), kInk);
    drawCurves(cv, *sampler, clean, plot.layout);
    drawSlices(cv, *sampler, clean, plot.layout);
    drawLattice(cv, *sampler, clean, options.latticePoints, plot.layout);
    return plot;
}

} // namespace lut
