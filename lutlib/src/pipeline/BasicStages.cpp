// SPDX-License-Identifier: Apache-2.0
// Pointwise and simple stages: sanitize, exposure, tone mapping, chromatic aberration, vignette,
// film grain, display encode.
#include "ArrayKernels.h"
#include "StageDetail.h"
#include "lut/Limits.h"
#include "lut/Math.h"

#include <cstdint>
#include <cstring>

namespace lut::detail {

namespace {

// NaN -> 0 and +-Inf / huge -> +-65504 in every channel, alpha included. Runs first so that one
// bad pixel cannot spread through the blurs into the whole bloom, and every later pow() and
// lookup sees finite input.
class SanitizeStage final : public Stage {
public:
    const char* name() const override { return "sanitize"; }
    bool pointwise() const override { return true; }
    const char* description() const override {
        return "NaN -> 0, +-Inf and |x| > 65504 -> +-65504 (half-float range), always first";
    }
    bool inspectsColor() const override { return true; }
    bool canChange(const ImageView& f, int nthreads) const override {
        // Row at a time, branch-free inner loop (vectorizes): this scan reads the whole frame.
        std::atomic<bool> found{false};
        parallelFor(f.height, nthreads, [&](int y0, int y1) {
            for (int y = y0; y < y1 && !found.load(std::memory_order_relaxed); ++y) {
                const float* p = f.row(y);
                int bad = 0;
                for (int i = 0; i < 4 * f.width; ++i)
                    bad |= !(std::fabs(p[i]) <= limits::kMaxColorValue);
                if (bad)
                    found = true;
            }
        });
        return found.load();
    }
    void processRows(const ImageView& f, int y0, int y1, const StageContext&) const override {
        for (int y = y0; y < y1; ++y) {
            float* p = f.row(y);
            // The branch-free scan vectorizes; rows without a bad value (nearly all) end there.
            int bad = 0;
            for (int i = 0; i < 4 * f.width; ++i)
                bad |= !(std::fabs(p[i]) <= limits::kMaxColorValue);
            if (!bad)
                continue;
            for (int i = 0; i < 4 * f.width; ++i)
                if (!(std::fabs(p[i]) <= limits::kMaxColorValue))
                    p[i] = sanitizeValue(p[i], limits::kMaxColorValue);
        }
    }
};

class ExposureStage final : public Stage {
public:
    ExposureStage() {
        addParam(&m_stops, "stops", 0.0f, -20.0f, 20.0f, "exposure in stops: x * 2^stops");
    }
    const char* name() const override { return "exposure"; }
    bool pointwise() const override { return true; }
    const char* description() const override {
        return "exposure control: x * 2^stops (before bloom)";
    }
    bool canChange(const ImageView&, int) const override { return m_stops != 0.0f; }
    void processRows(const ImageView& f, int y0, int y1, const StageContext&) const override {
        if (m_stops == 0.0f)
            return;
        const float k = lut::math::exp2(m_stops);
        for (int y = y0; y < y1; ++y) {
            float* p = f.row(y);
            for (int x = 0; x < f.width; ++x, p += 4) {
                p[0] *= k;
                p[1] *= k;
                p[2] *= k;
            }
        }
    }

private:
    float m_stops = 0.0f;
};

// Reinhard x/(1+x); ACES filmic fit by Narkowicz (2015); Hable's Uncharted 2 curve normalized by
// its white point. Negative input is taken as 0 (the curves are defined for x >= 0).
class TonemapStage final : public Stage {
public:
    TonemapStage() {
        addChoice(&m_curve, "curve", {"reinhard", "aces", "hable"}, 0, "tone curve");
        addParam(&m_white, "white", 11.2f, 0.01f, 1.0e4f, "hable: linear white point");
    }
    const char* name() const override { return "tonemap"; }
    bool pointwise() const override { return true; }
    const char* description() const override { return "tone mapping: reinhard | aces | hable"; }
    bool canChange(const ImageView&, int) const override { return true; }
    static float hable(float x) {
        const float A = 0.15f, B = 0.50f, C = 0.10f, D = 0.20f, E = 0.02f, F = 0.30f;
        return ((x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F)) - E / F;
    }
    void processRows(const ImageView& f, int y0, int y1, const StageContext&) const override {
        const int curve = static_cast<int>(m_curve);
        const float hw = 1.0f / hable(m_white);
        for (int y = y0; y < y1; ++y) {
            float* p = f.row(y);
            for (int x = 0; x < f.width; ++x, p += 4)
                for (int c = 0; c < 3; ++c) {
                    const float v = p[c] > 0.0f ? p[c] : 0.0f;
                    float o;
                    if (curve == 0)
                        o = v / (1.0f + v);
                    else if (curve == 1)
                        o = clamp01((v * (2.51f * v + 0.03f)) / (v * (2.43f * v + 0.59f) + 0.14f));
                    else
                        o = hable(v) * hw;
                    p[c] = o;
                }
        }
    }

private:
    float m_curve = 0.0f;
    float m_white = 11.2f;
};

// Each colour sampled at its own radial distance from the centre: red pushed out by (1 + k),
// blue pulled in by (1 - k), green in place; bilinear, clamp to edge.
class ChromaticAberrationStage final : public Stage {
public:
    ChromaticAberrationStage() {
        addParam(&m_strength, "strength", 0.004f, -0.2f, 0.2f,
                 "relative radial offset of red/blue");
    }
    const char* name() const override { return "chromatic-aberration"; }
    const char* description() const override {
        return "red and blue sampled at slightly different radii";
    }
    bool canChange(const ImageView& f, int) const override {
        return m_strength != 0.0f && f.width * f.height > 1;
    }
    bool needsPrepare() const override { return m_strength != 0.0f; }
    void prepare(const ImageView& f, const StageContext&) override {
        m_copy.resize(static_cast<std::size_t>(f.width) * f.height * 2);
        for (int y = 0; y < f.height; ++y) {
            const float* p = f.row(y);
            float* o = m_copy.data() + 2 * static_cast<std::size_t>(y) * f.width;
            for (int x = 0; x < f.width; ++x) {
                o[2 * x] = p[4 * x];
                o[2 * x + 1] = p[4 * x + 2];
            }
        }
    }
    void finish() override { std::vector<float>().swap(m_copy); }
    void processRows(const ImageView& f, int y0, int y1, const StageContext&) const override {
        if (m_strength == 0.0f || m_copy.empty())
            return;
        const float cx = 0.5f * f.width, cy = 0.5f * f.height;
        auto sample = [&](float fx, float fy, int ch) {
            fx = std::clamp(fx, 0.0f, static_cast<float>(f.width - 1));
            fy = std::clamp(fy, 0.0f, static_cast<float>(f.height - 1));
            const int x0 = static_cast<int>(fx), y0i = static_cast<int>(fy);
            const int x1 = std::min(x0 + 1, f.width - 1), y1i = std::min(y0i + 1, f.height - 1);
            const float tx = fx - x0, ty = fy - y0i;
            auto v = [&](int x, int y) {
                return m_copy[2 * (static_cast<std::size_t>(y) * f.width + x) + ch];
            };
            const float top = v(x0, y0i) + (v(x1, y0i) - v(x0, y0i)) * tx;
            const float bot = v(x0, y1i) + (v(x1, y1i) - v(x0, y1i)) * tx;
            return top + (bot - top) * ty;
        };
        for (int y = y0; y < y1; ++y) {
            float* p = f.row(y);
            for (int x = 0; x < f.width; ++x, p += 4) {
                const float dx = x + 0.5f - cx, dy = y + 0.5f - cy;
                const float kr = 1.0f + m_strength, kb = 1.0f - m_strength;
                p[0] = sample(cx + dx * kr - 0.5f, cy + dy * kr - 0.5f, 0);
                p[2] = sample(cx + dx * kb - 0.5f, cy + dy * kb - 0.5f, 1);
            }
        }
    }

private:
    float m_strength = 0.0f;
    std::vector<float> m_copy; // red and blue of the input frame
};

// Darkens by distance to the centre (1 at the corners): x * (1 - strength * smoothstep(radius,
// radius + softness, d)).
class VignetteStage final : public Stage {
public:
    VignetteStage() {
        addParam(&m_strength, "strength", 0.35f, 0.0f, 1.0f, "darkening at the corners");
        addParam(&m_radius, "radius", 0.45f, 0.0f, 2.0f,
                 "distance (corner = 1) where darkening starts");
        addParam(&m_softness, "softness", 0.6f, 0.001f, 4.0f, "width of the falloff");
    }
    const char* name() const override { return "vignette"; }
    const char* description() const override { return "darken by distance to the centre"; }
    bool canChange(const ImageView&, int) const override {
        return m_strength > 0.0f && m_radius < 1.0f;
    }
    void processRows(const ImageView& f, int y0, int y1, const StageContext&) const override {
        if (!(m_strength > 0.0f))
            return;
        const float cx = 0.5f * f.width, cy = 0.5f * f.height;
        const float inv = 1.0f / std::sqrt(cx * cx + cy * cy);
        for (int y = y0; y < y1; ++y) {
            float* p = f.row(y);
            const float dy = (y + 0.5f - cy) * inv;
            for (int x = 0; x < f.width; ++x, p += 4) {
                const float dx = (x + 0.5f - cx) * inv;
                const float d = std::sqrt(dx * dx + dy * dy);
                const float t = clamp01((d - m_radius) / m_softness);
                const float k = 1.0f - m_strength * (t * t * (3.0f - 2.0f * t));
                p[0] *= k;
                p[1] *= k;
                p[2] *= k;
            }
        }
    }

private:
    float m_strength = 0.0f, m_radius = 0.0f, m_softness = 1.0f;
};

inline std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

// Monochrome film grain: triangular noise in [-1, 1] from a hash of (seed, frame, x, y), scaled
// by strength and by sqrt of the pixel's luminance (grain shows most in the mid-tones, and black
// stays black). The same seed and frame index give the same frame; another frame index changes it.
class GrainStage final : public Stage {
public:
    GrainStage() {
        addParam(&m_strength, "strength", 0.04f, 0.0f, 1.0f, "grain amplitude");
        addParam(&m_seed, "seed", 1.0f, 0.0f, 16777216.0f, "random seed (integer)");
    }
    const char* name() const override { return "grain"; }
    const char* description() const override {
        return "seeded film grain (changes per frame index)";
    }
    bool canChange(const ImageView&, int) const override { return m_strength > 0.0f; }
    void processRows(const ImageView& f, int y0, int y1, const StageContext& ctx) const override {
        if (!(m_strength > 0.0f))
            return;
        const std::uint32_t seed =
            hash32(static_cast<std::uint32_t>(m_seed) * 0x9E3779B9u ^
                   hash32(static_cast<std::uint32_t>(ctx.frameIndex) + 0x632BE5ABu));
        for (int y = y0; y < y1; ++y) {
            float* p = f.row(y);
            for (int x = 0; x < f.width; ++x, p += 4) {
                const std::uint32_t h =
                    hash32(seed ^ hash32(static_cast<std::uint32_t>(y) * 0x10001u +
                                         hash32(static_cast<std::uint32_t>(x))));
                const float u1 = static_cast<float>(h & 0xFFFFu) * (1.0f / 65535.0f);
                const float u2 = static_cast<float>(h >> 16) * (1.0f / 65535.0f);
                const float n = u1 + u2 - 1.0f;
                const float lum = 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
                const float amp = m_strength * n * std::sqrt(std::clamp(lum, 0.0f, 1.0f));
                if (amp == 0.0f)
                    continue;
                p[0] += amp;
                p[1] += amp;
                p[2] += amp;
            }
        }
    }

private:
    float m_strength = 0.0f, m_seed = 1.0f;
};

class DisplayStage final : public Stage {
public:
    DisplayStage() {
        addChoice(&m_curve, "curve", {"srgb", "gamma"}, 0, "piecewise sRGB or pure power");
        addParam(&m_gamma, "gamma", 2.2f, 0.1f, 10.0f, "gamma of the pure power curve");
    }
    const char* name() const override { return "display"; }
    bool pointwise() const override { return true; }
    const char* description() const override {
        return "display encode: piecewise sRGB or pure gamma, last";
    }
    bool canChange(const ImageView&, int) const override { return true; }
    bool isSrgb() const { return m_curve == 0.0f; }
    void processRows(const ImageView& f, int y0, int y1, const StageContext&) const override {
        const bool srgb = isSrgb();
        const float inv = 1.0f / m_gamma;
        thread_local std::vector<float> e;
        const std::size_t n = static_cast<std::size_t>(f.width) * 4;
        e.resize(n);
        for (int y = y0; y < y1; ++y) {
            float* p = f.row(y);
            // powFast is 0 for x <= 0 (as the gamma curve is defined here), within 4e-7 of pow.
            if (srgb)
                srgbEncodeArray(p, e.data(), n);
            else
                powArray(inv, p, e.data(), n);
            for (std::size_t i = 0; i < n; i += 4) { // alpha kept
                p[i] = e[i];
                p[i + 1] = e[i + 1];
                p[i + 2] = e[i + 2];
            }
        }
    }

private:
    float m_curve = 0.0f, m_gamma = 2.2f;
};

} // namespace

std::unique_ptr<Stage> makeSanitizeStage() {
    return std::make_unique<SanitizeStage>();
}
std::unique_ptr<Stage> makeExposureStage() {
    return std::make_unique<ExposureStage>();
}
std::unique_ptr<Stage> makeTonemapStage() {
    return std::make_unique<TonemapStage>();
}
std::unique_ptr<Stage> makeChromaticAberrationStage() {
    return std::make_unique<ChromaticAberrationStage>();
}
std::unique_ptr<Stage> makeVignetteStage() {
    return std::make_unique<VignetteStage>();
}
std::unique_ptr<Stage> makeGrainStage() {
    return std::make_unique<GrainStage>();
}
std::unique_ptr<Stage> makeDisplayStage() {
    return std::make_unique<DisplayStage>();
}

bool isSrgbDisplay(const Stage& s) {
    const auto* d = dynamic_cast<const DisplayStage*>(&s);
    return d && d->isSrgb();
}

} // namespace lut::detail
