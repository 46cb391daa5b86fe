// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/HeatMap.h"

#include "lut/Error.h"
#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/ColorDifference.h"
#include "ops/Canvas.h"
#include "ops/OpsDetail.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <string>

namespace lut {

namespace {

double deltaE(glm::vec3 a, glm::vec3 b) {
    return a == b ? 0.0 : deltaE2000(srgbToLab(a), srgbToLab(b));
}

// Fills `de` with ΔE per pixel of a width x height grid whose input is input(x, y).
template <class InputFn>
std::vector<float> deltaEGrid(const Lut3D& a, const Lut3D& b, int width, int height,
                              const HeatMapOptions& o, InputFn input) {
    std::size_t ra = 0, rb = 0;
    const auto sa = makeSampler(detail::sanitizedCopy(a, ra), o.method);
    const auto sb = makeSampler(detail::sanitizedCopy(b, rb), o.method);
    std::vector<float> de(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    std::atomic<int> rowsDone{0};
    parallelFor(height, o.nthreads, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            checkCancelled(o.progress, "heat map");
            for (int x = 0; x < width; ++x) {
                const glm::vec3 in = input(x, y);
                de[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                   static_cast<std::size_t>(x)] =
                    static_cast<float>(deltaE(sa->sample(in), sb->sample(in)));
            }
            if (o.progress)
                o.progress->report(static_cast<double>(++rowsDone) / height);
        }
    });
    return de;
}

double scaleFor(const HeatMapOptions& o, double largest) {
    if (o.maxDeltaE > 0.0 && std::isfinite(o.maxDeltaE))
        return o.maxDeltaE;
    return largest > 0.0 ? largest : 1.0;
}

} // namespace

glm::vec3 heatMapColor(double t) {
    static constexpr float kStops[5][3] = {{0.0f, 0.0f, 0.0f},
                                           {0.30f, 0.06f, 0.50f},
                                           {0.80f, 0.18f, 0.32f},
                                           {0.99f, 0.58f, 0.10f},
                                           {1.0f, 1.0f, 0.70f}};
    if (std::isnan(t))
        t = 0.0;
    t = std::clamp(t, 0.0, 1.0) * 4.0;
    const int i = std::min(3, static_cast<int>(t));
    const float f = static_cast<float>(t - i);
    glm::vec3 c;
    for (int k = 0; k < 3; ++k)
        c[k] = kStops[i][k] + f * (kStops[i + 1][k] - kStops[i][k]);
    return c;
}

HeatMap diffHeatMap(const Lut3D& a, const Lut3D& b, const ImageView& image,
                    const HeatMapOptions& options) {
    HeatMap out;
    if (image.empty())
        return out;
    const auto de = deltaEGrid(a, b, image.width, image.height, options, [&](int x, int y) {
        const float* p = image.pixel(x, y);
        return glm::vec3(p[0], p[1], p[2]);
    });
    out.largestDeltaE = de.empty() ? 0.0 : *std::max_element(de.begin(), de.end());
    out.maxDeltaE = scaleFor(options, out.largestDeltaE);
    out.image = Image(image.width, image.height, 1.0f);
    for (std::size_t i = 0; i < de.size(); ++i) {
        const glm::vec3 c = heatMapColor(de[i] / out.maxDeltaE);
        float* p = out.image.data() + 4 * i;
        p[0] = c.r;
        p[1] = c.g;
        p[2] = c.b;
    }
    return out;
}

HeatMap diffHeatMapSlices(const Lut3D& a, const Lut3D& b, const HeatMapOptions& options, int slices,
                          int cellPixels, std::vector<HeatMapSliceLayout>* layout) {
    if (slices < 1 || slices > 16)
        throw Error("heat map: slice count " + std::to_string(slices) + " is out of range 1..16");
    if (cellPixels < 16 || cellPixels > 1024)
        throw Error("heat map: slice size " + std::to_string(cellPixels) +
                    " pixels is out of range 16..1024");
    constexpr int kMargin = 12, kGap = 12, kLabel = 24, kLegend = 44;
    const int s = cellPixels;
    const int width = 2 * kMargin + slices * s + (slices - 1) * kGap;
    const int height = kMargin + kLabel + s + kLegend;
    const glm::vec3 lo = a.domainMin(), hi = a.domainMax();
    // All slices side by side as one grid of inputs; the gaps are computed but not drawn.
    const int gridW = slices * s;
    auto sliceBlue = [&](int k) {
        return slices == 1 ? 0.0f : static_cast<float>(k) / static_cast<float>(slices - 1);
    };
    const auto de = deltaEGrid(a, b, gridW, s, options, [&](int x, int y) {
        const int k = x / s, px = x % s;
        const glm::vec3 t(static_cast<float>(px) / static_cast<float>(s - 1),
                          1.0f - static_cast<float>(y) / static_cast<float>(s - 1), sliceBlue(k));
        return lo + (hi - lo) * t;
    });
    HeatMap out;
    out.largestDeltaE = *std::max_element(de.begin(), de.end());
    out.maxDeltaE = scaleFor(options, out.largestDeltaE);
    out.image = Image(width, height);
    detail::Canvas canvas(out.image);
    const glm::vec3 bg(0.12f), ink(0.85f);
    canvas.fill(bg);
    if (layout)
        layout->clear();
    for (int k = 0; k < slices; ++k) {
        const int x0 = kMargin + k * (s + kGap), y0 = kMargin + kLabel;
        for (int y = 0; y < s; ++y)
            for (int x = 0; x < s; ++x) {
                const float v = de[static_cast<std::size_t>(y) * static_cast<std::size_t>(gridW) +
                                   static_cast<std::size_t>(k * s + x)];
                canvas.rect(x0 + x, y0 + y, 1, 1, heatMapColor(v / out.maxDeltaE));
            }
        char label[32];
        std::snprintf(label, sizeof label, "B=%.3g", static_cast<double>(sliceBlue(k)));
        canvas.text(x0, kMargin, label, ink);
        if (layout)
            layout->push_back({x0, y0, s, sliceBlue(k)});
    }
    // Legend: the ramp from 0 to the scale, with its ends labelled.
    const int ly = kMargin + kLabel + s + 10, lw = std::min(width - 2 * kMargin, 256);
    for (int x = 0; x < lw; ++x)
        canvas.rect(kMargin + x, ly, 1, 10, heatMapColor(static_cast<double>(x) / (lw - 1)));
    char scale[48];
    std::snprintf(scale, sizeof scale, "^E2000 0 TO %.3g", out.maxDeltaE);
    canvas.text(kMargin, ly + 14, scale, ink);
    return out;
}

} // namespace lut
