// SPDX-License-Identifier: Apache-2.0
// Source, result and reference side by side with histograms: see lut/match/MatchReportImage.h.
#include "lut/match/MatchReportImage.h"

#include "lut/Error.h"
#include "lut/Parallel.h"
#include "lut/match/LutQuality.h"
#include "lut/match/WorkingSpace.h"
#include "ops/Canvas.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace lut {

namespace {

constexpr int kPanelW = 480, kPanelH = 270, kHistH = 110, kMargin = 16, kTitle = 30;
const glm::vec3 kBackground(0.13f), kPanelBg(0.07f), kInk(0.85f);
const glm::vec3 kChannel[3] = {{1.0f, 0.32f, 0.32f}, {0.35f, 0.95f, 0.35f}, {0.45f, 0.6f, 1.0f}};

float shown(float v, bool linear) {
    if (std::isnan(v))
        return 0.0f;
    const double d = linear ? srgbEncodeExtended(v) : v;
    return static_cast<float>(std::clamp(d, 0.0, 1.0));
}

// One panel: the picture scaled into kPanelW x kPanelH (area average), its histograms below.
void drawPanel(Image& out, detail::Canvas& canvas, int x0, const char* title, const ImageView& img,
               bool linear, bool toLinear, bool toDisplay) {
    canvas.text(x0, kMargin, title, kInk, 2);
    const int top = kMargin + kTitle;
    canvas.rect(x0, top, kPanelW, kPanelH, kPanelBg);
    const double scale = std::min(static_cast<double>(kPanelW) / img.width,
                                  static_cast<double>(kPanelH) / img.height);
    const int w = std::max(1, static_cast<int>(img.width * scale));
    const int h = std::max(1, static_cast<int>(img.height * scale));
    const int ox = x0 + (kPanelW - w) / 2, oy = top + (kPanelH - h) / 2;
    std::array<std::array<double, 256>, 3> hist{};
    auto value = [&](float v) {
        double s = v;
        if (toLinear)
            s = srgbDecodeExtended(s);
        else if (toDisplay)
            s = srgbEncodeExtended(s);
        return static_cast<float>(s);
    };
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const float* p = img.pixel(x, y);
            for (int c = 0; c < 3; ++c) {
                const float d = shown(value(p[c]), linear);
                hist[static_cast<std::size_t>(c)][static_cast<std::size_t>(
                    std::clamp(static_cast<int>(d * 255.0f + 0.5f), 0, 255))] += 1.0;
            }
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // area average of the source pixels this one covers
            const int sx0 = static_cast<int>(x / scale),
                      sx1 = std::max(sx0 + 1, static_cast<int>((x + 1) / scale));
            const int sy0 = static_cast<int>(y / scale),
                      sy1 = std::max(sy0 + 1, static_cast<int>((y + 1) / scale));
            glm::dvec3 acc(0.0);
            int n = 0;
            for (int sy = sy0; sy < std::min(sy1, img.height); ++sy)
                for (int sx = sx0; sx < std::min(sx1, img.width); ++sx) {
                    const float* p = img.pixel(sx, sy);
                    acc += glm::dvec3(shown(value(p[0]), linear), shown(value(p[1]), linear),
                                      shown(value(p[2]), linear));
                    ++n;
                }
            float* o = out.pixel(ox + x, oy + y);
            for (int c = 0; c < 3; ++c)
                o[c] = static_cast<float>(acc[c] / std::max(n, 1));
            o[3] = 1.0f;
        }
    const int hy = top + kPanelH + 8;
    canvas.rect(x0, hy, kPanelW, kHistH, kPanelBg);
    for (int c = 0; c < 3; ++c) {
        const auto& hc = hist[static_cast<std::size_t>(c)];
        const double peak = std::max(1.0, *std::max_element(hc.begin(), hc.end()));
        std::vector<glm::dvec2> line;
        for (int k = 0; k < 256; ++k)
            line.emplace_back(x0 + (k + 0.5) * kPanelW / 256.0,
                              hy + kHistH - 1 -
                                  (kHistH - 4) * std::sqrt(hc[static_cast<std::size_t>(k)] / peak));
        canvas.polyline(line, kChannel[c], 1.5, true);
    }
}

} // namespace

Image applyLutFile(const LutFile& lut, const ImageView& image, int nthreads) {
    Image out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        std::copy(image.row(y), image.row(y) + 4 * image.width, out.pixel(0, y));
    const LutFileSampler sampler(lut);
    parallelFor(image.height, nthreads, [&](int a, int b) {
        for (int y = a; y < b; ++y)
            sampler.applyPixels(out.pixel(0, y), static_cast<std::size_t>(image.width));
    });
    return out;
}

Image matchReportImage(const MatchReportPicture& source, const LutFile& lut,
                       const MatchReportPicture& reference, int nthreads) {
    if (source.pixels.empty() || reference.pixels.empty())
        throw Error("match report picture: an empty picture");
    const Image result = applyLutFile(lut, source.pixels, nthreads);
    const int width = 4 * kMargin + 3 * kPanelW;
    const int height = kMargin + kTitle + kPanelH + 8 + kHistH + kMargin + 16;
    Image out(width, height);
    detail::Canvas canvas(out);
    canvas.fill(kBackground);
    const bool convert = reference.linear != source.linear;
    drawPanel(out, canvas, kMargin, "SOURCE", source.pixels, source.linear, false, false);
    drawPanel(out, canvas, 2 * kMargin + kPanelW, "RESULT", result.view(), source.linear, false,
              false);
    drawPanel(out, canvas, 3 * kMargin + 2 * kPanelW, "REFERENCE", reference.pixels, source.linear,
              convert && source.linear, convert && !source.linear);
    canvas.text(kMargin, height - kMargin - 8,
                "HISTOGRAMS: R G B OF THE VALUES AS SHOWN, SQUARE ROOT OF THE COUNT",
                glm::vec3(0.5f), 1);
    return out;
}

} // namespace lut
