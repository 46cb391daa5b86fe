// SPDX-License-Identifier: Apache-2.0
// LUT stages: the Smash grading pass (with an optional fused sRGB display encode) and a generic
// LUT stage.
#include "ArrayKernels.h"
#include "StageDetail.h"
#include "lut/LutFile.h"
#include "lut/smash/SmashGrading.h"

#include <algorithm>

namespace lut::detail {

namespace {

std::shared_ptr<const Lut3D> neutralSmashLut() {
    static const auto l = std::make_shared<const Lut3D>(Lut3D::identity(kSmashLutSize));
    return l;
}

} // namespace

std::unique_ptr<Sampler> makeStageSampler(const Lut3D* lut, const Lut1D* shaper,
                                          Interpolation method) {
    if (!shaper)
        return makeSampler(*lut, method);
    LutFile file;
    file.shaper = *shaper;
    if (lut)
        file.cube = *lut;
    return makeSampler(file, method);
}

namespace {

// docs/specs/smash-pipeline.md section 2: per pixel, s = x^0.454545; L = trilinear(lut, s);
// r = ((L - s) * 0.99961 + s) * 1.3703; g = r^2.2; out = mix(x, g, clamp(alpha, 0, 1)).
// The pow()s are FastMath.h's polynomial pows (< 4e-7 relative), run 8 pixels at a time by
// ArrayKernels; the LUT goes through the sampler's own kernel. When the pipeline fuses the display
// encode into this pass, graded pixels take srgb(r^2.2) in one power (smashDisplayFast) and
// pixels this stage leaves alone take srgbEncodeFast -- the function the display stage uses, so
// fused == unfused for them.
class SmashGradeStage final : public LutStage {
public:
    SmashGradeStage() { setLut(nullptr, Interpolation::Trilinear, nullptr); }
    const char* name() const override { return "smash-grade"; }
    bool pointwise() const override { return true; }
    const char* description() const override {
        return "Smash grading: gamma 2.2 encode, LUT, brighten (0.99961, 1.3703), decode, alpha "
               "mix";
    }
    void setLut(std::shared_ptr<const Lut3D> lut, Interpolation method,
                std::shared_ptr<const Lut1D> shaper) override {
        m_given = lut;
        m_lut = lut ? std::move(lut) : neutralSmashLut();
        m_method = method;
        m_shaper = std::move(shaper);
        m_sampler =
            makeStageSampler(m_shaper && !m_given ? nullptr : m_lut.get(), m_shaper.get(), method);
    }
    void copySettingsFrom(const Stage& other) override {
        Stage::copySettingsFrom(other);
        if (const auto* o = dynamic_cast<const SmashGradeStage*>(&other))
            setLut(o->m_given, o->m_method, o->m_shaper);
    }
    // Grading changes every pixel with alpha > 0 (the brighten step alone does, even for a
    // neutral LUT); alpha 0 is left as is.
    bool canChange(const ImageView& f, int nthreads) const override {
        return anyPixel(f, nthreads, [](const float* p) { return p[3] > 0.0f; });
    }
    void processRows(const ImageView& f, int y0, int y1, const StageContext& ctx) const override {
        const bool fused = ctx.fusedDisplay;
        // Chunks of 64 pixels: encode (SIMD), the sampler's own kernel on the encoded copy, then
        // brighten + decode + mix (+ display) (SIMD); the scratch stays in L1.
        constexpr int kChunk = 64;
        alignas(32) float s[4 * kChunk], l[4 * kChunk];
        for (int y = y0; y < y1; ++y) {
            float* row = f.row(y);
            for (int x0 = 0; x0 < f.width; x0 += kChunk) {
                const int n = std::min(kChunk, f.width - x0);
                float* p = row + 4 * x0;
                bool graded = false;
                for (int i = 0; i < n; ++i)
                    graded |= p[4 * i + 3] > 0.0f;
                if (!graded) { // alpha <= 0 everywhere: at most the display encode
                    if (fused)
                        smashFinishPixels(p, p, p, static_cast<std::size_t>(n), true);
                    continue;
                }
                smashEncodePixels(p, s, l, static_cast<std::size_t>(n));
                m_sampler->applyPixels(l, static_cast<std::size_t>(n));
                smashFinishPixels(p, s, l, static_cast<std::size_t>(n), fused);
            }
        }
    }

private:
    std::shared_ptr<const Lut3D> m_given; // as set (null: neutral)
    std::shared_ptr<const Lut3D> m_lut;
    std::shared_ptr<const Lut1D> m_shaper;
    Interpolation m_method = Interpolation::Trilinear;
    std::unique_ptr<Sampler> m_sampler;
};

// Any 3D LUT with any interpolation, on linear or encoded values as the preset places it. An
// identity LUT changes only values outside its domain (it clamps them, as every sampler does);
// for it the stage clamps exactly instead of sampling, so skipping it is exact.
class GenericLutStage final : public LutStage {
public:
    GenericLutStage() { setLut(nullptr, Interpolation::Trilinear, nullptr); }
    const char* name() const override { return "lut"; }
    bool pointwise() const override { return true; }
    const char* description() const override { return "a 3D LUT (any size, any interpolation)"; }
    void setLut(std::shared_ptr<const Lut3D> lut, Interpolation method,
                std::shared_ptr<const Lut1D> shaper) override {
        m_given = lut;
        m_lut = lut ? std::move(lut) : neutralSmashLut();
        m_method = method;
        m_shaper = std::move(shaper);
        m_sampler =
            makeStageSampler(m_shaper && !m_given ? nullptr : m_lut.get(), m_shaper.get(), method);
        // within 1e-6: treated as exact; a shaper always runs
        m_identity = !m_shaper && m_lut->isIdentity(1e-6f);
        m_min = m_shaper ? m_shaper->domainMin() : m_lut->domainMin();
        m_max = m_shaper ? m_shaper->domainMax() : m_lut->domainMax();
    }
    void copySettingsFrom(const Stage& other) override {
        Stage::copySettingsFrom(other);
        if (const auto* o = dynamic_cast<const GenericLutStage*>(&other))
            setLut(o->m_given, o->m_method, o->m_shaper);
    }
    bool inspectsColor() const override { return m_identity; }
    bool canChange(const ImageView& f, int nthreads) const override {
        if (!m_identity)
            return true;
        const glm::vec3 lo = m_min, hi = m_max;
        return anyPixel(f, nthreads, [lo, hi](const float* p) {
            for (int c = 0; c < 3; ++c)
                if (!(p[c] >= lo[c] && p[c] <= hi[c]))
                    return true;
            return false;
        });
    }
    void processRows(const ImageView& f, int y0, int y1, const StageContext&) const override {
        for (int y = y0; y < y1; ++y) {
            float* p = f.row(y);
            if (!m_identity) {
                m_sampler->applyPixels(p, static_cast<std::size_t>(f.width));
                continue;
            }
            for (int x = 0; x < f.width; ++x, p += 4)
                for (int c = 0; c < 3; ++c)
                    p[c] = std::clamp(p[c], m_min[c], m_max[c]);
        }
    }

private:
    std::shared_ptr<const Lut3D> m_given; // as set (null: neutral)
    std::shared_ptr<const Lut3D> m_lut;
    std::shared_ptr<const Lut1D> m_shaper;
    Interpolation m_method = Interpolation::Trilinear;
    std::unique_ptr<Sampler> m_sampler;
    bool m_identity = true;
    glm::vec3 m_min{0.0f}, m_max{1.0f};
};

} // namespace

std::unique_ptr<Stage> makeSmashGradeStage() {
    return std::make_unique<SmashGradeStage>();
}
std::unique_ptr<Stage> makeLutStage() {
    return std::make_unique<GenericLutStage>();
}

bool isSmashGrade(const Stage& s) {
    return dynamic_cast<const SmashGradeStage*>(&s) != nullptr;
}

} // namespace lut::detail
