// SPDX-License-Identifier: Apache-2.0
#include "lut/check/CheckPicture.h"

#include "check/CheckDetail.h"
#include "lut/Error.h"
#include "lut/Math.h"
#include "lut/check/StressCharts.h"
#include "ops/Canvas.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace lut {

namespace {

// clang-format off
constexpr int kWidth = 1600, kMargin = 24, kColumn = 760, kAfterX = kMargin + kColumn + 32;
constexpr int kRowHeights[6] = {36, 36, 112, 112, 48, 0}; // slices: from their width
constexpr int kMaxMarked = 15;  // findings circled and plotted (the list shows more)
constexpr int kRayPlots = 4, kRayW = 362, kRayH = 190;
// clang-format on
const glm::vec3 kBackground(0.13f), kPanel(0.07f), kInk(0.88f), kDim(0.55f), kGrid(0.24f);
const glm::vec3 kFail(1.0f, 0.3f, 0.3f), kWarn(1.0f, 0.76f, 0.15f), kPass(0.4f, 0.85f, 0.45f);
const glm::vec3 kChannel[3] = {{1.0f, 0.32f, 0.32f}, {0.35f, 0.95f, 0.35f}, {0.45f, 0.6f, 1.0f}};
const char* const kRowNames[6] = {"GREY RAMP",
                                  "SHADOWS (INPUT 0-0.25, SHOWN 4X BRIGHTER)",
                                  "HUE X SATURATION (HSV, VALUE 1)",
                                  "HUE X LIGHTNESS (HSL, SATURATION 1)",
                                  "SKIN LINE, DARK TO LIGHT (CHROMA 1.4X TOP, 0.4X BOTTOM)",
                                  "SLICES AT BLUE 0, 0.25, 0.5, 0.75, 1 (RED RIGHT, GREEN UP)"};

glm::vec3 statusColour(CheckStatus s) {
    return s == CheckStatus::Fail ? kFail : s == CheckStatus::Warn ? kWarn : kPass;
}

std::string upper(std::string s) {
    for (char& c : s)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

// Text cut to fit `pixels` at scale 2.
std::string fit(std::string s, int pixels) {
    const std::size_t chars = static_cast<std::size_t>(std::max(4, (pixels + 2) / 12));
    if (s.size() > chars)
        s = s.substr(0, chars - 3) + "...";
    return s;
}

void ring(detail::Canvas& cv, double cx, double cy, double radius, glm::vec3 colour) {
    std::vector<glm::dvec2> pts;
    for (int i = 0; i <= 40; ++i) {
        const double a = 2.0 * std::numbers::pi * i / 40.0;
        pts.emplace_back(cx + radius * lut::math::cos(a), cy + radius * lut::math::sin(a));
    }
    cv.polyline(pts, glm::vec3(0.0f), 4.5, false);
    cv.polyline(pts, colour, 2.5, false);
}

// The chart behind row `row` of the picture, the input colour of its pixel (x, y).
glm::vec3 rowColour(int row, int w, int h, int x, int y) {
    switch (row) {
    case 0:
        return stressChartColour(StressChart::Grey, w, h, x, y);
    case 1:
        return 0.25f * stressChartColour(StressChart::Grey, w, h, x, y);
    case 2:
        return stressChartColour(StressChart::HueSaturation, w, h, x, y);
    case 3:
        return stressChartColour(StressChart::HueLightness, w, h, x, y);
    case 4:
        return stressChartColour(StressChart::Skin, w, h, x, y);
    default:
        return stressChartColour(StressChart::Slices, w, h, x, y);
    }
}

// Where a colour (in [0, 1]) shows in row `row`, in the row's own pixels.
std::optional<glm::ivec2> locateInRow(int row, int w, int h, glm::vec3 c) {
    const float spread = std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b});
    const float mean = (c.r + c.g + c.b) / 3.0f;
    switch (row) {
    case 0:
        if (spread > 0.03f)
            return std::nullopt;
        return glm::ivec2(static_cast<int>(std::lround(mean * (w - 1))), h / 2);
    case 1:
        if (spread > 0.03f || mean > 0.25f)
            return std::nullopt;
        return glm::ivec2(static_cast<int>(std::lround(mean / 0.25f * (w - 1))), h / 2);
    case 2:
        return locateInChart(StressChart::HueSaturation, w, h, c, 0.035f);
    case 3:
        return locateInChart(StressChart::HueLightness, w, h, c, 0.035f);
    case 4:
        return locateInChart(StressChart::Skin, w, h, c, 0.035f);
    default:
        return locateInChart(StressChart::Slices, w, h, c, 0.13f);
    }
}

struct Drawing {
    detail::Canvas& cv;
    const check::Context& ctx;
    const CheckReport& report;
    CheckPictureLayout& layout;
};

int drawSummary(Drawing& d, const std::string& title, int y) {
    detail::Canvas& cv = d.cv;
    const CheckStatus overall = d.report.status();
    cv.text(kMargin, y, "LUT CHECK: " + fit(upper(title), kWidth - 420), kInk, 3);
    const std::string verdict = upper(toString(overall));
    cv.text(kWidth - kMargin - detail::Canvas::textWidth(verdict, 4), y - 4, verdict,
            statusColour(overall), 4);
    y += 34;
    std::string sub = upper(d.report.description);
    for (std::size_t at; (at = sub.find('^')) != std::string::npos;) // "33^3" -> "33X33X33"
        sub.replace(at, 2,
                    "X" + sub.substr(sub.rfind(' ', at) + 1, at - sub.rfind(' ', at) - 1) + "X" +
                        sub.substr(sub.rfind(' ', at) + 1, at - sub.rfind(' ', at) - 1));
    if (d.report.image)
        sub += "   OVER THE PICTURE'S COLOURS";
    sub += "   " + std::to_string(d.report.findings.size() + d.report.findingsLeftOut) +
           " FINDING" + (d.report.findings.size() + d.report.findingsLeftOut == 1 ? "" : "S");
    cv.text(kMargin, y, sub, kDim);
    y += 26;
    for (const CheckSummary& s : d.report.checks) {
        const glm::vec3 c = s.kind == CheckKind::Neutral ? kDim : statusColour(s.status);
        const std::string badge = s.kind == CheckKind::Neutral ? "INFO" : upper(toString(s.status));
        cv.rect(kMargin, y - 3, 60, 20, c * 0.35f);
        cv.text(kMargin + 30 - detail::Canvas::textWidth(badge) / 2, y, badge, c);
        cv.text(kMargin + 72, y, upper(toString(s.kind)), kInk);
        cv.text(kMargin + 252, y, fit(upper(s.text), kWidth - kMargin - 252 - kMargin), kDim);
        y += 22;
    }
    return y + 8;
}

int drawCharts(Drawing& d, int y) {
    detail::Canvas& cv = d.cv;
    cv.text(kMargin, y, "BEFORE: THE CHARTS", kInk);
    cv.text(kAfterX, y, "AFTER: THROUGH THE LUT", kInk);
    y += 24;
    const glm::vec3 lo = d.ctx.inputMin(), hi = d.ctx.inputMax();
    for (int row = 0; row < 6; ++row) {
        const int w = kColumn;
        int h = kRowHeights[row];
        if (row == 5)
            h = std::max(1, (w - 4 * std::max(2, w / 80)) / 5);
        cv.text(kMargin, y, kRowNames[row], kDim);
        y += 18;
        d.layout.before[row] = {kMargin, y, w, h};
        d.layout.after[row] = {kAfterX, y, w, h};
        std::vector<glm::vec3> colours(static_cast<std::size_t>(w) * h);
        for (int yy = 0; yy < h; ++yy)
            for (int xx = 0; xx < w; ++xx)
                colours[static_cast<std::size_t>(yy) * w + xx] = rowColour(row, w, h, xx, yy);
        std::vector<glm::vec3> after = colours;
        for (glm::vec3& c : after)
            c = lo + (hi - lo) * c;
        d.ctx.evaluate(after);
        const float gain = row == 1 ? 4.0f : 1.0f;
        for (int yy = 0; yy < h; ++yy)
            for (int xx = 0; xx < w; ++xx) {
                const std::size_t i = static_cast<std::size_t>(yy) * w + xx;
                const glm::vec3 a = glm::clamp(after[i] * gain, 0.0f, 1.0f);
                cv.rect(kMargin + xx, y + yy, 1, 1, glm::clamp(colours[i] * gain, 0.0f, 1.0f));
                cv.rect(kAfterX + xx, y + yy, 1, 1,
                        glm::all(glm::equal(a, a)) ? a : glm::vec3(0.0f));
            }
        cv.frame(kMargin - 1, y - 1, w + 2, h + 2, kGrid);
        cv.frame(kAfterX - 1, y - 1, w + 2, h + 2, kGrid);
        y += h + 14;
    }
    // Every finding circled where its colour shows, on both sides, with its number.
    const int marked = std::min<int>(kMaxMarked, static_cast<int>(d.report.findings.size()));
    for (int i = 0; i < marked; ++i) {
        const CheckFinding& f = d.report.findings[static_cast<std::size_t>(i)];
        const glm::vec3 c = glm::clamp((f.input - lo) / (hi - lo), 0.0f, 1.0f);
        const glm::vec3 colour = statusColour(f.severity);
        for (int row = 0; row < 6; ++row) {
            const auto& b = d.layout.before[row];
            const auto at = locateInRow(row, b.width, b.height, c);
            if (!at)
                continue;
            const std::string label = std::to_string(i + 1);
            for (const auto* r : {&d.layout.before[row], &d.layout.after[row]}) {
                const int cx = r->x + at->x, cy = r->y + at->y;
                ring(cv, cx, cy, 10.0, colour);
                const int ly =
                    cy - 19 < r->y ? cy + 3 : cy - 19; // inside the chart, under its title
                cv.rect(cx + 11, ly, detail::Canvas::textWidth(label) + 4, 18, glm::vec3(0.0f));
                cv.text(cx + 13, ly + 2, label, colour);
            }
            d.layout.marks.push_back(
                {i + 1, row, d.layout.after[row].x + at->x, d.layout.after[row].y + at->y});
        }
    }
    return y;
}

struct RayToPlot {
    std::string name;
    glm::vec3 from, to;                       // normalised input
    std::vector<std::pair<int, float>> marks; // finding number, position t
};

// The lines to plot: the grey axis, then the lines through the first findings.
std::vector<RayToPlot> raysToPlot(const CheckReport& report, const check::Context& ctx) {
    std::vector<RayToPlot> out;
    out.push_back({"GREY AXIS", glm::vec3(0.0f), glm::vec3(1.0f), {}});
    const glm::vec3 lo = ctx.inputMin(), hi = ctx.inputMax();
    const int n = std::min<int>(kMaxMarked, static_cast<int>(report.findings.size()));
    for (int i = 0; i < n && out.size() < kRayPlots; ++i) {
        const CheckFinding& f = report.findings[static_cast<std::size_t>(i)];
        const glm::vec3 u = glm::clamp((f.input - lo) / (hi - lo), 0.0f, 1.0f);
        RayToPlot r;
        float t = 0.0f;
        if (f.where.rfind("along ", 0) == 0) {
            const int axis = f.where == "along red" ? 0 : f.where == "along green" ? 1 : 2;
            r.from = r.to = u;
            r.from[axis] = 0.0f;
            r.to[axis] = 1.0f;
            t = u[axis];
            char buf[96];
            const int o1 = (axis + 1) % 3, o2 = (axis + 2) % 3;
            std::snprintf(buf, sizeof buf, "%s AT %s=%.2f %s=%.2f", upper(f.where).c_str(),
                          check::channelLetter(o1), u[o1], check::channelLetter(o2), u[o2]);
            r.name = buf;
        } else if (f.where.rfind("on the ", 0) == 0) {
            const std::string rayName = f.where.substr(7);
            bool found = false;
            for (const check::Ray& ray : check::rays())
                if (rayName == ray.name) {
                    r.from = ray.from;
                    r.to = ray.to;
                    const glm::vec3 span = ray.to - ray.from;
                    const int axis = std::fabs(span.x) > 0 ? 0 : std::fabs(span.y) > 0 ? 1 : 2;
                    t = (u[axis] - ray.from[axis]) / span[axis];
                    found = true;
                }
            if (!found)
                continue;
            r.name = upper(rayName);
        } else {
            continue;
        }
        bool merged = false;
        for (RayToPlot& existing : out)
            if (glm::all(glm::lessThan(glm::abs(existing.from - r.from), glm::vec3(1e-4f))) &&
                glm::all(glm::lessThan(glm::abs(existing.to - r.to), glm::vec3(1e-4f)))) {
                existing.marks.emplace_back(i + 1, t);
                merged = true;
            }
        if (!merged) {
            r.marks.emplace_back(i + 1, t);
            out.push_back(r);
        }
    }
    return out;
}

int drawRays(Drawing& d, int y) {
    detail::Canvas& cv = d.cv;
    cv.text(kMargin, y,
            "OUTPUT ALONG THE GREY AXIS AND THE LINES THROUGH THE FINDINGS "
            "(R G B; DASHED: THE INPUT)",
            kInk);
    y += 24;
    const glm::vec3 lo = d.ctx.inputMin(), hi = d.ctx.inputMax();
    const std::vector<RayToPlot> rays = raysToPlot(d.report, d.ctx);
    constexpr int kSamples = 256;
    auto fraction = [](int i) { return static_cast<float>(i) / (kSamples - 1); };
    for (std::size_t k = 0; k < rays.size(); ++k) {
        const RayToPlot& ray = rays[k];
        const int x0 = kMargin + static_cast<int>(k) * (kRayW + 24), y0 = y + 22;
        cv.text(x0, y, fit(ray.name, kRayW), kDim);
        cv.rect(x0, y0, kRayW, kRayH, kPanel);
        std::vector<glm::vec3> in(kSamples), out(kSamples);
        for (int i = 0; i < kSamples; ++i) {
            in[static_cast<std::size_t>(i)] = ray.from + (ray.to - ray.from) * fraction(i);
            out[static_cast<std::size_t>(i)] = lo + (hi - lo) * in[static_cast<std::size_t>(i)];
        }
        d.ctx.evaluate(out);
        float vmin = 0.0f, vmax = 1.0f;
        for (const glm::vec3& v : out)
            for (int c = 0; c < 3; ++c)
                if (std::isfinite(v[c])) {
                    vmin = std::min(vmin, std::max(-1.0f, v[c]));
                    vmax = std::max(vmax, std::min(2.0f, v[c]));
                }
        auto px = [&](double t) { return x0 + t * (kRayW - 1); };
        auto py = [&](double v) { return y0 + (kRayH - 1) * (1.0 - (v - vmin) / (vmax - vmin)); };
        for (int q = 1; q < 4; ++q)
            cv.line(px(q / 4.0), y0, px(q / 4.0), y0 + kRayH - 1, kGrid, 1.0);
        for (int c = 0; c < 3; ++c) {
            if (std::fabs(ray.to[c] - ray.from[c]) > 1e-6f) // the input, dashed
                for (int s = 0; s < 24; s += 2) {
                    const double t0 = s / 24.0, t1 = (s + 1) / 24.0;
                    cv.line(px(t0), py(ray.from[c] + (ray.to[c] - ray.from[c]) * t0), px(t1),
                            py(ray.from[c] + (ray.to[c] - ray.from[c]) * t1), kChannel[c] * 0.6f,
                            1.0);
                }
            std::vector<glm::dvec2> pts;
            for (int i = 0; i < kSamples; ++i)
                pts.emplace_back(px(fraction(i)),
                                 py(std::clamp(out[static_cast<std::size_t>(i)][c], vmin, vmax)));
            cv.polyline(pts, kChannel[c], 2.0, true);
        }
        for (const auto& [number, t] : ray.marks) {
            const CheckFinding& f = d.report.findings[static_cast<std::size_t>(number - 1)];
            const double x = px(std::clamp<double>(t, 0.0, 1.0));
            cv.line(x, y0, x, y0 + kRayH - 1, statusColour(f.severity), 1.5);
            cv.text(static_cast<int>(x) + 4, y0 + 4, std::to_string(number),
                    statusColour(f.severity));
        }
        cv.frame(x0 - 1, y0 - 1, kRayW + 2, kRayH + 2, kGrid);
    }
    return y + 22 + kRayH + 20;
}

int drawFindings(Drawing& d, int y) {
    detail::Canvas& cv = d.cv;
    const auto& findings = d.report.findings;
    if (findings.empty()) {
        cv.text(kMargin, y, "NO FINDINGS: EVERY FIGURE IS UNDER ITS THRESHOLD", kPass);
        return y + 30;
    }
    cv.text(kMargin, y, "FINDINGS, WORST FIRST", kInk);
    y += 24;
    const int listed = std::min<int>(kMaxMarked, static_cast<int>(findings.size()));
    for (int i = 0; i < listed; ++i) {
        const CheckFinding& f = findings[static_cast<std::size_t>(i)];
        const glm::vec3 c = statusColour(f.severity);
        cv.text(kMargin, y, std::to_string(i + 1), c);
        cv.text(kMargin + 36, y, upper(toString(f.severity)), c);
        char at[160];
        std::snprintf(at, sizeof at, "%s %.3g %s %s AT (%.3f, %.3f, %.3f), %.2f%%",
                      toString(f.kind), f.size, toString(f.unit), f.where.c_str(), f.input.x,
                      f.input.y, f.input.z, 100.0 * f.share);
        cv.text(kMargin + 100, y, fit(upper(at), kWidth - kMargin - 100 - kMargin), kInk);
        y += 20;
    }
    const std::size_t more =
        findings.size() - static_cast<std::size_t>(listed) + d.report.findingsLeftOut;
    if (more > 0) {
        cv.text(kMargin + 100, y, "AND " + std::to_string(more) + " MORE (LUTKIT CHECK LISTS THEM)",
                kDim);
        y += 20;
    }
    return y + 10;
}

} // namespace

CheckPicture drawCheckReport(const LutFile& file, const CheckReport& report,
                             const std::string& title) {
    if (!file.cube && !file.shaper)
        throw Error("check: the file has neither a 3D table nor a 1D table");
    const CheckOptions options;
    const check::Context ctx(file, options);
    // Draw once to learn the height, then on a picture of that height.
    CheckPicture out;
    for (int pass = 0; pass < 2; ++pass) {
        const int height = pass == 0 ? 4000 : out.image.height();
        Image image(kWidth, height);
        detail::Canvas cv(image);
        cv.fill(kBackground);
        CheckPictureLayout layout;
        Drawing d{cv, ctx, report, layout};
        int y = drawSummary(d, title, 16);
        y = drawCharts(d, y + 6);
        y = drawRays(d, y + 6);
        y = drawFindings(d, y + 6);
        if (pass == 0) {
            out.image = Image(kWidth, y + 8);
            continue;
        }
        out.image = std::move(image);
        out.layout = std::move(layout);
    }
    return out;
}

} // namespace lut
