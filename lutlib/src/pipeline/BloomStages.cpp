// SPDX-License-Identifier: Apache-2.0
// Bloom stages. Each builds its bloom image in prepare() (reading the sanitized frame) and adds it
// in processRows(). Exact zeros are never added, so a bloom that finds nothing leaves the frame
// bit-identical (what makes skipping safe).
#include "ArrayKernels.h"
#include "StageDetail.h"
#include "lut/smash/SmashGrading.h"

namespace lut::detail {

namespace {

// The bloom source of a full-resolution bloom: out (resized to the frame) gets fn(pixel, texel)
// for every frame pixel, rows in parallel.
template <class Fn> void makeBloomSource(const ImageView& f, RgbBuffer& out, int nthreads, Fn fn) {
    out.resize(f.width, f.height);
    parallelFor(f.height, nthreads, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const float* p = f.row(y);
            for (int x = 0; x < f.width; ++x, p += 4)
                fn(p, out.at(x, y));
        }
    });
}

// Base for blooms that keep a full-resolution RGB bloom image.
class FullResBloom : public Stage {
public:
    bool needsPrepare() const override { return true; }
    bool inspectsColor() const override { return true; }
    void finish() override { m_bloom = RgbBuffer(); }
    void processRows(const ImageView& f, int y0, int y1, const StageContext&) const override {
        if (m_bloom.w != f.width || m_bloom.h != f.height)
            return;
        for (int y = y0; y < y1; ++y) {
            float* p = f.row(y);
            for (int x = 0; x < f.width; ++x, p += 4)
                addRgb(p, m_bloom.at(x, y));
        }
    }

protected:
    RgbBuffer m_bloom;
};

// Lecture: subtract (1,1,1), clamp at 0, Gaussian blur, add.
class HdrBloomStage final : public FullResBloom {
public:
    HdrBloomStage() {
        addParam(&m_threshold, "threshold", 1.0f, 0.0f, 1.0e4f, "subtracted before the blur");
        addParam(&m_sigma, "sigma", 6.0f, 0.5f, 64.0f, "Gaussian sigma in pixels");
        addParam(&m_strength, "strength", 1.0f, 0.0f, 100.0f, "multiplier of the added bloom");
    }
    const char* name() const override { return "hdr-bloom"; }
    const char* description() const override { return "HDR bloom: max(x - 1, 0), Gaussian, add"; }
    bool canChange(const ImageView& f, int nthreads) const override {
        if (!(m_strength > 0.0f))
            return false;
        const float th = m_threshold;
        return anyPixel(f, nthreads,
                        [th](const float* p) { return p[0] > th || p[1] > th || p[2] > th; });
    }
    void prepare(const ImageView& f, const StageContext& ctx) override {
        makeBloomSource(f, m_bloom, ctx.nthreads, [this](const float* p, float* o) {
            for (int c = 0; c < 3; ++c)
                o[c] = std::max(p[c] - m_threshold, 0.0f) * m_strength;
        });
        separableBlur(m_bloom, gaussianWeights(m_sigma), ctx.nthreads);
    }

private:
    float m_threshold = 1.0f, m_sigma = 6.0f, m_strength = 1.0f;
};

// Pilot homework: luminance soft-knee filter, separable 9-tap Gaussian (0.227027, 0.1945946,
// 0.1216216, 0.054054, 0.016216) horizontal then vertical, `passes` times, add.
// Soft knee (the usual quadratic knee): with k = threshold * knee,
//   soft = clamp(l - threshold + k, 0, 2k)^2 / (4k),  weight = max(soft, l - threshold) / l.
class FilterBloomStage final : public FullResBloom {
public:
    FilterBloomStage() {
        addParam(&m_threshold, "threshold", 0.8f, 0.0f, 1.0e4f, "luminance threshold");
        addParam(&m_knee, "knee", 0.5f, 0.0f, 1.0f, "soft knee width, fraction of the threshold");
        addParam(&m_passes, "passes", 2.0f, 1.0f, 32.0f, "blur passes");
        addParam(&m_strength, "strength", 1.0f, 0.0f, 100.0f, "multiplier of the added bloom");
    }
    const char* name() const override { return "soft-bloom"; }
    const char* description() const override {
        return "soft bloom: luminance soft-knee filter, separable 9-tap Gaussian, add";
    }
    float weight(float l) const {
        const float k = m_threshold * m_knee;
        float soft = std::clamp(l - m_threshold + k, 0.0f, 2.0f * k);
        soft = k > 0.0f ? soft * soft / (4.0f * k) : 0.0f;
        const float w = std::max(soft, l - m_threshold);
        return w > 0.0f ? w / std::max(l, 1e-5f) : 0.0f;
    }
    bool canChange(const ImageView& f, int nthreads) const override {
        if (!(m_strength > 0.0f))
            return false;
        return anyPixel(f, nthreads, [this](const float* p) {
            return weight(0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) > 0.0f;
        });
    }
    void prepare(const ImageView& f, const StageContext& ctx) override {
        makeBloomSource(f, m_bloom, ctx.nthreads, [this](const float* p, float* o) {
            const float w = weight(0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) * m_strength;
            for (int c = 0; c < 3; ++c)
                o[c] = p[c] * w;
        });
        static const std::vector<float> kWeights = {0.227027f, 0.1945946f, 0.1216216f, 0.054054f,
                                                    0.016216f};
        for (int i = 0; i < static_cast<int>(m_passes); ++i)
            separableBlur(m_bloom, kWeights, ctx.nthreads);
    }

private:
    float m_threshold = 0.8f, m_knee = 0.5f, m_passes = 2.0f, m_strength = 1.0f;
};

// Sugar (../seeds/002): i = max(r, g, b) - th (>= 0); source = C * i; dilation (max filter);
// Gaussian through a mip pyramid (the average of the 2x2-box mip levels, each upsampled
// bilinearly); out = C * f0 + blur * clamp(1 - i, 0, 1) * f1.
class SugarBloomStage final : public FullResBloom {
public:
    SugarBloomStage() {
        addParam(&m_threshold, "threshold", 0.8f, 0.0f, 1.0e4f, "intensity threshold th");
        addParam(&m_dilate, "dilate", 1.0f, 0.0f, 8.0f, "dilation radius in pixels");
        addParam(&m_levels, "levels", 5.0f, 1.0f, 10.0f, "mip levels averaged by the blur");
        addParam(&m_f0, "f0", 1.0f, 0.0f, 10.0f, "weight of the base image");
        addParam(&m_f1, "f1", 1.0f, 0.0f, 100.0f, "weight of the blurred halo");
    }
    const char* name() const override { return "glow-bloom"; }
    const char* description() const override {
        return "glow bloom: intensity threshold, dilation, mip-pyramid blur, C*f0 + B*(1-i)*f1";
    }
    bool canChange(const ImageView& f, int nthreads) const override {
        if (m_f0 != 1.0f)
            return true;
        if (!(m_f1 > 0.0f))
            return false;
        const float th = m_threshold;
        return anyPixel(f, nthreads, [th](const float* p) {
            return std::max({p[0], p[1], p[2]}) - th > 0.0f;
        });
    }
    void prepare(const ImageView& f, const StageContext& ctx) override {
        const int W = f.width, H = f.height;
        RgbBuffer src;
        makeBloomSource(f, src, ctx.nthreads, [this](const float* p, float* o) {
            const float i = std::max(std::max({p[0], p[1], p[2]}) - m_threshold, 0.0f);
            for (int c = 0; c < 3; ++c)
                o[c] = p[c] * i;
        });
        // Dilation: separable max filter (a square window).
        const int r = static_cast<int>(m_dilate);
        if (r > 0) {
            RgbBuffer tmp;
            tmp.resize(W, H);
            for (int pass = 0; pass < 2; ++pass) {
                RgbBuffer& in = pass == 0 ? src : tmp;
                RgbBuffer& out = pass == 0 ? tmp : src;
                parallelFor(H, ctx.nthreads, [&](int y0, int y1) {
                    for (int y = y0; y < y1; ++y)
                        for (int x = 0; x < W; ++x) {
                            float m[3] = {-3.0e38f, -3.0e38f, -3.0e38f};
                            for (int k = -r; k <= r; ++k) {
                                const float* q = pass == 0 ? in.at(std::clamp(x + k, 0, W - 1), y)
                                                           : in.at(x, std::clamp(y + k, 0, H - 1));
                                for (int c = 0; c < 3; ++c)
                                    m[c] = std::max(m[c], q[c]);
                            }
                            float* o = out.at(x, y);
                            for (int c = 0; c < 3; ++c)
                                o[c] = m[c];
                        }
                });
            }
        }
        // Mip pyramid; the blur is the mean of all levels upsampled bilinearly to full size.
        std::vector<RgbBuffer> mips;
        mips.push_back(std::move(src));
        for (int l = 1; l < static_cast<int>(m_levels) && (mips.back().w > 1 || mips.back().h > 1);
             ++l) {
            RgbBuffer next;
            resampleBilinear(mips.back(), next, std::max(1, mips.back().w / 2),
                             std::max(1, mips.back().h / 2), ctx.nthreads);
            mips.push_back(std::move(next));
        }
        const float wl = m_f1 / static_cast<float>(mips.size());
        m_bloom.resize(W, H);
        std::vector<Axis> ax, ay;
        for (const auto& m : mips) {
            ax.push_back(makeAxis(W, m.w));
            ay.push_back(makeAxis(H, m.h));
        }
        parallelFor(H, ctx.nthreads, [&](int y0, int y1) {
            for (int y = y0; y < y1; ++y) {
                const float* p = f.row(y);
                for (int x = 0; x < W; ++x, p += 4) {
                    float acc[3] = {0, 0, 0};
                    for (std::size_t l = 0; l < mips.size(); ++l)
                        bilinearAdd(mips[l], ax[l], x, ay[l], y, wl, acc);
                    const float i = std::max(std::max({p[0], p[1], p[2]}) - m_threshold, 0.0f);
                    const float k = clamp01(1.0f - i);
                    float* o = m_bloom.at(x, y);
                    for (int c = 0; c < 3; ++c)
                        o[c] = acc[c] * k;
                }
            }
        });
    }
    void processRows(const ImageView& f, int y0, int y1, const StageContext& ctx) const override {
        if (m_f0 != 1.0f)
            for (int y = y0; y < y1; ++y) {
                float* p = f.row(y);
                for (int x = 0; x < f.width; ++x, p += 4) {
                    p[0] *= m_f0;
                    p[1] *= m_f0;
                    p[2] *= m_f0;
                }
            }
        FullResBloom::processRows(f, y0, y1, ctx);
    }

private:
    float m_threshold = 0.8f, m_dilate = 1.0f, m_levels = 5.0f, m_f0 = 1.0f, m_f1 = 1.0f;
};

// Smash Ultimate bloom, docs/specs/smash-pipeline.md section 1. Texel-centre convention (GPU):
// texel i of a w-texel image is centred at u = (i + 0.5) / w; sampling image B (size wb) at u reads
// texel coordinate u * wb - 0.5 bilinearly with clamp to edge. Sizes: quarter = max(1, W/4)
// (integer division, as render-target sizes are), each blur level max(1, previous/2).
class SmashBloomStage final : public Stage {
public:
    SmashBloomStage() {
        addParam(&m_threshold, "threshold", kSmashBloomThreshold, 0.0f, 1.0f,
                 "brightness threshold (0.4625)");
        addParam(&m_gain, "gain", kSmashBloomGain, 0.0f, 100.0f, "threshold gain (6.0)");
        addParam(&m_strength, "strength", 1.0f, 0.0f, 100.0f,
                 "multiplier of the added bloom (1 = game)");
    }
    const char* name() const override { return "smash-bloom"; }
    const char* description() const override {
        return "Smash bloom: 1/4-res threshold, 4 blur levels, weighted combine, pow 2.2, "
               "upsample, add";
    }
    bool needsPrepare() const override { return true; }
    bool inspectsColor() const override { return true; }
    bool canChange(const ImageView& f, int nthreads) const override {
        if (!(m_strength > 0.0f) || !(m_gain > 0.0f))
            return false;
        // The threshold image is zero unless some bilinear sample has a clamped component above
        // the threshold and some alpha above 0; both need such texels to exist.
        const float th = m_threshold;
        const bool bright = anyPixel(f, nthreads, [th](const float* p) {
            return std::max(
                       {clamp01(p[0]), clamp01(p[1]), clamp01(p[2]), kSmashBloomMinComponent}) -
                       th >
                   0.0f;
        });
        return bright && anyPixel(f, nthreads, [](const float* p) { return p[3] > 0.0f; });
    }
    void prepare(const ImageView& f, const StageContext& ctx) override {
        const int W = f.width, H = f.height;
        const int w4 = std::max(1, W / 4), h4 = std::max(1, H / 4);
        // 1. threshold at quarter resolution (the scratch buffers are kept from frame to frame:
        //    the editor runs this at every slider step)
        RgbBuffer& level = m_level;
        level.resize(w4, h4);
        {
            const Axis ax = makeAxis(w4, W), ay = makeAxis(h4, H);
            parallelForDynamic(h4, ctx.nthreads, 8, [&](int j0, int j1) {
                for (int j = j0; j < j1; ++j)
                    for (int i = 0; i < w4; ++i) {
                        const float tx = ax.t[i], ty = ay.t[j];
                        const float* p00 = f.pixel(ax.i0[i], ay.i0[j]);
                        const float* p10 = f.pixel(ax.i1[i], ay.i0[j]);
                        const float* p01 = f.pixel(ax.i0[i], ay.i1[j]);
                        const float* p11 = f.pixel(ax.i1[i], ay.i1[j]);
                        float s[4];
                        for (int c = 0; c < 4; ++c) {
                            const float top = p00[c] + (p10[c] - p00[c]) * tx;
                            const float bot = p01[c] + (p11[c] - p01[c]) * tx;
                            s[c] = top + (bot - top) * ty;
                        }
                        const float cr = clamp01(s[0]), cg = clamp01(s[1]), cb = clamp01(s[2]);
                        const float m = std::max({cr, cg, cb, kSmashBloomMinComponent});
                        const float k = std::max(m - m_threshold, 0.0f) * m_gain * clamp01(s[3]);
                        float* o = level.at(i, j);
                        o[0] = cr / m * k;
                        o[1] = cg / m * k;
                        o[2] = cb / m * k;
                    }
            });
        }
        // 2. four blur levels, each half the size of its input, 3x3 [1 2 1] kernel, taps one
        //    input texel apart, bilinear. The 9 bilinear taps are separable (weights kTap[dx] *
        //    kTap[dy], bilinear weights wx * wy), so each level is a horizontal pass (3 taps per
        //    input row) and a vertical pass (3 taps of that): 12 lerps per texel instead of 36.
        RgbBuffer* levels = m_levels;
        const RgbBuffer* in = &level;
        static const float kTap[3] = {0.25f, 0.5f, 0.25f};
        for (int l = 0; l < 4; ++l) {
            const int wo = std::max(1, in->w / 2), ho = std::max(1, in->h / 2);
            RgbBuffer& out = levels[l];
            out.resize(wo, ho);
            RgbBuffer& h = m_blurH;
            h.resize(wo, in->h);
            Axis ax[3], ay[3];
            for (int d = 0; d < 3; ++d) {
                ax[d] = makeAxis(wo, in->w, d - 1.0);
                ay[d] = makeAxis(ho, in->h, d - 1.0);
            }
            // Small levels are not worth a thread.
            const int threads = wo * ho < 8192 ? 1 : ctx.nthreads;
            parallelFor(in->h, threads, [&](int y0, int y1) {
                for (int y = y0; y < y1; ++y)
                    for (int i = 0; i < wo; ++i) {
                        float acc[3] = {0, 0, 0};
                        for (int d = 0; d < 3; ++d) {
                            const float* a = in->at(ax[d].i0[i], y);
                            const float* b = in->at(ax[d].i1[i], y);
                            for (int c = 0; c < 3; ++c)
                                acc[c] += kTap[d] * (a[c] + (b[c] - a[c]) * ax[d].t[i]);
                        }
                        float* o = h.at(i, y);
                        o[0] = acc[0];
                        o[1] = acc[1];
                        o[2] = acc[2];
                    }
            });
            parallelFor(ho, threads, [&](int j0, int j1) {
                for (int j = j0; j < j1; ++j)
                    for (int i = 0; i < wo; ++i) {
                        float acc[3] = {0, 0, 0};
                        for (int d = 0; d < 3; ++d) {
                            const float* a = h.at(i, ay[d].i0[j]);
                            const float* b = h.at(i, ay[d].i1[j]);
                            for (int c = 0; c < 3; ++c)
                                acc[c] += kTap[d] * (a[c] + (b[c] - a[c]) * ay[d].t[j]);
                        }
                        float* o = out.at(i, j);
                        o[0] = acc[0];
                        o[1] = acc[1];
                        o[2] = acc[2];
                    }
            });
            in = &out;
        }
        // 3. combine at quarter resolution, clamp, pow 2.2; stored as RGB0 texels (the zero 4th
        //    float makes every later loop contiguous)
        m_cw = w4;
        m_combined.assign(static_cast<std::size_t>(w4) * h4 * 4, 0.0f);
        Axis cx[4], cy[4];
        for (int l = 0; l < 4; ++l) {
            cx[l] = makeAxis(w4, levels[l].w);
            cy[l] = makeAxis(h4, levels[l].h);
        }
        parallelForDynamic(h4, ctx.nthreads, 8, [&](int j0, int j1) {
            // Separable bilinear: each level's two source rows blended once per output row.
            std::vector<float> rows[4];
            for (int l = 0; l < 4; ++l)
                rows[l].resize(static_cast<std::size_t>(levels[l].w) * 3);
            std::vector<float> sum(static_cast<std::size_t>(w4) * 4, 0.0f);
            for (int j = j0; j < j1; ++j) {
                for (int l = 0; l < 4; ++l) {
                    const float ty = cy[l].t[j];
                    const float* r0 = levels[l].at(0, cy[l].i0[j]);
                    const float* r1 = levels[l].at(0, cy[l].i1[j]);
                    for (int k = 0; k < 3 * levels[l].w; ++k)
                        rows[l][k] = r0[k] + (r1[k] - r0[k]) * ty;
                }
                for (int i = 0; i < w4; ++i)
                    for (int c = 0; c < 3; ++c) {
                        float b[4];
                        for (int l = 0; l < 4; ++l) {
                            const float tx = cx[l].t[i];
                            const float a0 = rows[l][3 * cx[l].i0[i] + c],
                                        a1 = rows[l][3 * cx[l].i1[i] + c];
                            b[l] = a0 + (a1 - a0) * tx;
                        }
                        sum[4 * i + c] =
                            clamp01(kSmashBloomWeights[0] * b[0] + kSmashBloomWeights[1] * b[1] +
                                    kSmashBloomWeights[2] * b[2] + kSmashBloomWeights[3] * b[3]);
                    }
                float* o = m_combined.data() + static_cast<std::size_t>(j) * w4 * 4;
                powArray(kSmashBloomExponent, sum.data(), o, sum.size());
                for (std::size_t k = 0; k < sum.size(); ++k)
                    o[k] *= m_strength;
            }
        });
        // 4. upsample axes for processRows
        m_ax = makeAxis(W, w4);
        m_ay = makeAxis(H, h4);
    }
    void finish() override {
        m_ax = Axis();
        m_ay = Axis();
    }
    void processRows(const ImageView& f, int y0, int y1, const StageContext&) const override {
        if (m_cw == 0 || static_cast<int>(m_ax.t.size()) != f.width ||
            static_cast<int>(m_ay.t.size()) != f.height)
            return;
        // Separable bilinear: the two source rows blended once per output row, then one lerp
        // per output pixel, two pixels per AVX2 register.
        thread_local std::vector<float> row;
        const std::size_t n = static_cast<std::size_t>(m_cw) * 4;
        row.resize(n);
        for (int y = y0; y < y1; ++y) {
            const float ty = m_ay.t[y];
            const float* r0 = m_combined.data() + static_cast<std::size_t>(m_ay.i0[y]) * n;
            const float* r1 = m_combined.data() + static_cast<std::size_t>(m_ay.i1[y]) * n;
            int nonzero = 0;
            for (std::size_t k = 0; k < n; ++k) {
                const float v = r0[k] + (r1[k] - r0[k]) * ty;
                row[k] = v;
                nonzero |= v != 0.0f;
            }
            if (nonzero)
                addBloomRow(f.row(y), f.width, row.data(), m_ax.i0.data(), m_ax.i1.data(),
                            m_ax.t.data());
        }
    }

private:
    float m_threshold = kSmashBloomThreshold, m_gain = kSmashBloomGain, m_strength = 1.0f;
    RgbBuffer m_level, m_levels[4], m_blurH;
    std::vector<float> m_combined; // h4 rows of m_cw RGB0 texels
    int m_cw = 0;
    Axis m_ax, m_ay;
};

} // namespace

std::unique_ptr<Stage> makeHdrBloomStage() {
    return std::make_unique<HdrBloomStage>();
}
std::unique_ptr<Stage> makeFilterBloomStage() {
    return std::make_unique<FilterBloomStage>();
}
std::unique_ptr<Stage> makeSugarBloomStage() {
    return std::make_unique<SugarBloomStage>();
}
std::unique_ptr<Stage> makeSmashBloomStage() {
    return std::make_unique<SmashBloomStage>();
}

} // namespace lut::detail
