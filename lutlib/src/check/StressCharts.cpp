// SPDX-License-Identifier: Apache-2.0
#include "lut/check/StressCharts.h"

#include "check/CheckDetail.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace lut {

namespace {

glm::vec3 hsv(float h, float s, float v) {
    auto f = [&](float n) {
        const float k = std::fmod(n + h / 60.0f, 6.0f);
        return v - v * s * std::max(0.0f, std::min({k, 4.0f - k, 1.0f}));
    };
    return {f(5.0f), f(3.0f), f(1.0f)};
}

glm::vec3 hsl(float h, float s, float l) {
    const float a = s * std::min(l, 1.0f - l);
    auto f = [&](float n) {
        const float k = std::fmod(n + h / 30.0f, 12.0f);
        return l - a * std::max(-1.0f, std::min({k - 3.0f, 9.0f - k, 1.0f}));
    };
    return {f(0.0f), f(8.0f), f(4.0f)};
}

float fraction(int i, int n) {
    return n > 1 ? static_cast<float>(i) / static_cast<float>(n - 1) : 0.0f;
}

struct SliceGeometry {
    int side, gap;
};
SliceGeometry slices(int width, int height) {
    const int gap = std::max(2, width / 80);
    return {std::max(1, std::min(height, (width - 4 * gap) / 5)), gap};
}

} // namespace

const std::vector<StressChartInfo>& stressCharts() {
    static const std::vector<StressChartInfo> charts = {
        {StressChart::Grey, "grey", "a ramp from black to white", 1024, 64},
        {StressChart::HueSaturation, "hue-saturation",
         "HSV hue left to right, saturation 1 (top) to 0, value 1", 1024, 256},
        {StressChart::HueLightness, "hue-lightness",
         "HSL hue left to right, lightness 1 (top) to 0, saturation 1", 1024, 256},
        {StressChart::Skin, "skin",
         "the skin line dark to light, chroma 1.4x (top) to 0.4x the line's", 1024, 128},
        {StressChart::Slices, "slices",
         "slices of the cube at blue 0, 0.25, 0.5, 0.75, 1 (red right, green up)", 1064, 200},
    };
    return charts;
}

std::optional<StressChart> stressChartByName(const std::string& name) {
    for (const StressChartInfo& c : stressCharts())
        if (name == c.name)
            return c.chart;
    return std::nullopt;
}

glm::vec3 stressChartColour(StressChart chart, int width, int height, int x, int y) {
    const float u = fraction(x, width), v = fraction(y, height);
    switch (chart) {
    case StressChart::Grey:
        return glm::vec3(u);
    case StressChart::HueSaturation:
        return glm::clamp(hsv(360.0f * u, 1.0f - v, 1.0f), 0.0f, 1.0f);
    case StressChart::HueLightness:
        return glm::clamp(hsl(360.0f * u, 1.0f, 1.0f - v), 0.0f, 1.0f);
    case StressChart::Skin: {
        const check::Ray& skin = check::rays()[check::kSkinRay];
        const glm::vec3 c = skin.from + (skin.to - skin.from) * u;
        const float luma = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
        return glm::clamp(glm::vec3(luma) + (1.4f - v) * (c - glm::vec3(luma)), 0.0f, 1.0f);
    }
    case StressChart::Slices: {
        const SliceGeometry g = slices(width, height);
        const int k = x / (g.side + g.gap), ix = x - k * (g.side + g.gap);
        if (k > 4 || ix >= g.side || y >= g.side)
            return glm::vec3(0.0f);
        return {fraction(ix, g.side), 1.0f - fraction(y, g.side), 0.25f * static_cast<float>(k)};
    }
    }
    return glm::vec3(0.0f);
}

Image stressChart(StressChart chart, int width, int height) {
    Image img(std::max(1, width), std::max(1, height));
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const glm::vec3 c = stressChartColour(chart, img.width(), img.height(), x, y);
            float* p = img.pixel(x, y);
            p[0] = c.r;
            p[1] = c.g;
            p[2] = c.b;
            p[3] = 1.0f;
        }
    return img;
}

Image stressChartSheet(int width) {
    width = std::max(16, width);
    constexpr int kGap = 16;
    std::vector<Image> parts;
    int height = 0;
    for (const StressChartInfo& c : stressCharts()) {
        const int h =
            std::max(1, static_cast<int>(std::lround(double(c.height) * width / c.width)));
        parts.push_back(stressChart(c.chart, width, h));
        height += h + (parts.size() > 1 ? kGap : 0);
    }
    Image sheet(width, height);
    int y = 0;
    for (const Image& part : parts) {
        for (int row = 0; row < part.height(); ++row)
            std::copy(part.pixel(0, row), part.pixel(0, row) + 4 * width, sheet.pixel(0, y + row));
        y += part.height();
        for (int row = 0; row < kGap && y + row < height; ++row)
            for (int x = 0; x < width; ++x)
                sheet.pixel(x, y + row)[3] = 1.0f; // black, opaque
        y += kGap;
    }
    return sheet;
}

std::optional<glm::ivec2> locateInChart(StressChart chart, int width, int height, glm::vec3 colour,
                                        float tolerance) {
    if (width <= 0 || height <= 0)
        return std::nullopt;
    const int stride = std::max(1, static_cast<int>(std::sqrt(double(width) * height / 60000.0)));
    float best = tolerance;
    std::optional<glm::ivec2> at;
    for (int y = 0; y < height; y += stride)
        for (int x = 0; x < width; x += stride) {
            if (chart == StressChart::Slices) {
                const SliceGeometry g = slices(width, height);
                if (x % (g.side + g.gap) >= g.side || y >= g.side)
                    continue; // the gaps between slices
            }
            const glm::vec3 d = glm::abs(stressChartColour(chart, width, height, x, y) - colour);
            const float dist = std::max({d.x, d.y, d.z});
            if (dist <= best) {
                best = dist;
                at = glm::ivec2(x, y);
            }
        }
    return at;
}

} // namespace lut
