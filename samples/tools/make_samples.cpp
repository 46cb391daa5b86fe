// SPDX-License-Identifier: Apache-2.0
// Makes the bundled samples: a small synthetic stage scene (sky gradient, saturated objects,
// skin-like tones, bright highlights above 1.0) as a linear float EXR and an 8-bit sRGB PNG, and a
// 33^3 sample grade .cube (a warm/teal "sunset" look). Deterministic: the same bytes every run.
//   make_samples OUTDIR
#include "lut/Image.h"
#include "lut/formats/ImageIO.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace {

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
float linearToSrgb(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}
struct Rgb {
    float r, g, b;
};
Rgb lin(float r, float g, float b) {
    return {srgbToLinear(r), srgbToLinear(g), srgbToLinear(b)};
}
Rgb mix(Rgb a, Rgb b, float t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}
Rgb scale(Rgb a, float s) {
    return {a.r * s, a.g * s, a.b * s};
}

lut::Image makeScene(int w, int h) {
    lut::Image img(w, h);
    const float horizon = 0.62f * h;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float u = (x + 0.5f) / w, v = (y + 0.5f) / h;
            Rgb c;
            if (y < horizon) {
                // Sky: deep blue at the top to a warm haze at the horizon.
                const float t = std::pow(v / 0.62f, 1.5f);
                c = mix(lin(0.16f, 0.32f, 0.72f), lin(0.98f, 0.78f, 0.58f), t);
            } else {
                // Stage floor: grey-brown with a subtle checker and darkening to the front.
                const bool check = (static_cast<int>(u * 16) + static_cast<int>(v * 24)) % 2;
                c = check ? lin(0.45f, 0.40f, 0.36f) : lin(0.38f, 0.34f, 0.31f);
                c = scale(c, 1.0f - 0.5f * (v - 0.62f) / 0.38f);
            }
            auto inCircle = [&](float cx, float cy, float r) {
                const float dx = (u - cx) * w / h, dy = v - cy;
                return dx * dx + dy * dy < r * r;
            };
            // Sun: far above 1 (HDR), with a soft halo.
            {
                const float dx = (u - 0.82f) * w / h, dy = v - 0.16f;
                const float d = std::sqrt(dx * dx + dy * dy);
                if (d < 0.06f)
                    c = {12.0f, 10.5f, 8.0f};
                else if (d < 0.16f) {
                    const float k = 1.0f - (d - 0.06f) / 0.10f;
                    c = mix(c, {2.2f, 1.8f, 1.3f}, k * k);
                }
            }
            // Saturated objects: red ball, green block, blue crystal, yellow star-ish disc.
            if (inCircle(0.18f, 0.70f, 0.10f)) {
                const float shade = 0.6f + 0.4f * (0.70f - v + 0.1f) / 0.2f;
                c = scale(lin(0.90f, 0.06f, 0.08f), shade);
                if (inCircle(0.16f, 0.65f, 0.02f))
                    c = {3.0f, 2.9f, 2.8f}; // specular highlight
            }
            if (u > 0.34f && u < 0.46f && v > 0.55f && v < 0.85f)
                c = lin(0.10f, 0.80f, 0.20f);
            if (std::fabs(u - 0.88f) * w / h + std::fabs(v - 0.72f) * 0.6f < 0.07f) {
                c = lin(0.15f, 0.25f, 0.95f);
                if (std::fabs(u - 0.875f) < 0.004f)
                    c = {1.6f, 1.8f, 4.0f};
            }
            if (inCircle(0.58f, 0.40f, 0.05f))
                c = lin(0.98f, 0.86f, 0.10f);
            // Skin-like tones: a face with a lit and a shadowed side, and a darker hand.
            if (inCircle(0.70f, 0.60f, 0.085f)) {
                const float side = u < 0.70f ? 1.0f : 0.7f;
                c = scale(lin(0.87f, 0.64f, 0.52f), side);
            }
            if (inCircle(0.62f, 0.78f, 0.04f))
                c = lin(0.55f, 0.36f, 0.25f);
            float* p = img.pixel(x, y);
            p[0] = c.r;
            p[1] = c.g;
            p[2] = c.b;
            p[3] = 1.0f;
        }
    return img;
}

// The sample grade: warm highlights, teal shadows, a little extra contrast, on gamma-space values.
void grade(double r, double g, double b, double out[3]) {
    const double luma = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    auto contrast = [](double x) { return x + 0.35 * x * (1 - x) * (2 * x - 1); };
    double c[3] = {r, g, b};
    const double warm[3] = {1.06, 1.0, 0.90}, teal[3] = {0.92, 1.02, 1.08};
    for (int i = 0; i < 3; ++i) {
        double v = c[i] * (luma * warm[i] + (1 - luma) * teal[i]);
        v = luma + 1.15 * (v - luma); // saturation
        v = contrast(std::clamp(v, 0.0, 1.0));
        out[i] = std::clamp(v, 0.0, 1.0);
    }
}

bool writeCube(const std::string& path, int n) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f)
        return false;
    std::fprintf(f, "# lutkit sample grade: warm highlights, teal shadows, +15%% saturation.\n");
    std::fprintf(f, "# Made by samples/tools/make_samples.cpp.\n");
    std::fprintf(f, "TITLE \"lutkit sample sunset grade\"\nLUT_3D_SIZE %d\n", n);
    std::fprintf(f, "DOMAIN_MIN 0 0 0\nDOMAIN_MAX 1 1 1\n");
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                double o[3];
                grade(r / double(n - 1), g / double(n - 1), b / double(n - 1), o);
                std::fprintf(f, "%.6f %.6f %.6f\n", o[0], o[1], o[2]);
            }
    return std::fclose(f) == 0;
}

} // namespace

int main(int argc, char** argv) {
    const std::string dir = argc > 1 ? argv[1] : ".";
    try {
        const lut::Image scene = makeScene(320, 180);
        lut::formats::writeImage(dir + "/sample_scene.exr", scene, {32, false, true});
        lut::Image shot(scene.width(), scene.height());
        for (std::size_t i = 0; i < scene.pixels().size(); ++i)
            shot.pixels()[i] = (i % 4 == 3) ? 1.0f : linearToSrgb(scene.pixels()[i]);
        lut::formats::writeImage(dir + "/sample_scene.png", shot, {8, false, false});
        if (!writeCube(dir + "/sample_grade.cube", 33))
            throw std::runtime_error("cannot write cube");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_samples: %s\n", e.what());
        return 1;
    }
    return 0;
}
