// SPDX-License-Identifier: Apache-2.0
#pragma once
// Private helpers shared by the stage implementations.
#include "core/FastMath.h"
#include "lut/Image.h"
#include "lut/Lut1D.h"
#include "lut/Lut3D.h"
#include "lut/Math.h"
#include "lut/Parallel.h"
#include "lut/interp/Interpolation.h"
#include "lut/interp/Sampler.h"
#include "lut/pipeline/Stage.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <vector>

namespace lut::detail {

// Stages that sample a grading LUT (smash-grade, lut).
class LutStage : public Stage {
public:
    // shaper: run before lut's table, exactly (lut null: the shaper alone); null = none.
    virtual void setLut(std::shared_ptr<const Lut3D> lut, Interpolation method,
                        std::shared_ptr<const Lut1D> shaper = nullptr) = 0;
};

// The sampler of a LUT stage: lut with `method`, after the shaper when there is one.
std::unique_ptr<Sampler> makeStageSampler(const Lut3D* lut, const Lut1D* shaper,
                                          Interpolation method);

// An RGB float image, 3 interleaved channels, used for bloom intermediates.
struct RgbBuffer {
    int w = 0, h = 0;
    std::vector<float> v;
    void resize(int width, int height) {
        w = width;
        h = height;
        v.assign(static_cast<std::size_t>(w) * h * 3, 0.0f);
    }
    float* at(int x, int y) { return v.data() + 3 * (static_cast<std::size_t>(y) * w + x); }
    const float* at(int x, int y) const {
        return v.data() + 3 * (static_cast<std::size_t>(y) * w + x);
    }
};

// Bilinear taps along one axis, GPU convention: destination texel i of an axis of outSize texels
// has its centre at u = (i + 0.5) / outSize; a source of inSize texels is sampled there at texel
// coordinate u * inSize - 0.5 (+ offset texels), between texels floor and floor + 1, both clamped
// to [0, inSize - 1] (clamp to edge). Computed in double so the weights are exact to float.
struct Axis {
    std::vector<int> i0, i1;
    std::vector<float> t;
};
inline Axis makeAxis(int outSize, int inSize, double offsetTexels = 0.0) {
    Axis a;
    a.i0.resize(outSize);
    a.i1.resize(outSize);
    a.t.resize(outSize);
    for (int i = 0; i < outSize; ++i) {
        const double f = (i + 0.5) * inSize / outSize - 0.5 + offsetTexels;
        const double fl = std::floor(f);
        const int k = static_cast<int>(fl);
        a.t[i] = static_cast<float>(f - fl);
        a.i0[i] = std::clamp(k, 0, inSize - 1);
        a.i1[i] = std::clamp(k + 1, 0, inSize - 1);
    }
    return a;
}

// Bilinear sample of an RgbBuffer at (ax[i], ay[j]), added into acc with weight w.
inline void bilinearAdd(const RgbBuffer& b, const Axis& ax, int i, const Axis& ay, int j, float w,
                        float acc[3]) {
    const float tx = ax.t[i], ty = ay.t[j];
    const float* p00 = b.at(ax.i0[i], ay.i0[j]);
    const float* p10 = b.at(ax.i1[i], ay.i0[j]);
    const float* p01 = b.at(ax.i0[i], ay.i1[j]);
    const float* p11 = b.at(ax.i1[i], ay.i1[j]);
    for (int c = 0; c < 3; ++c) {
        const float top = p00[c] + (p10[c] - p00[c]) * tx;
        const float bot = p01[c] + (p11[c] - p01[c]) * tx;
        acc[c] += w * (top + (bot - top) * ty);
    }
}

// Rescales `in` to outW x outH with one bilinear tap per texel (GPU-style down/upsample).
inline void resampleBilinear(const RgbBuffer& in, RgbBuffer& out, int outW, int outH,
                             int nthreads) {
    out.resize(outW, outH);
    const Axis ax = makeAxis(outW, in.w), ay = makeAxis(outH, in.h);
    parallelFor(outH, nthreads, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < outW; ++x) {
                float acc[3] = {0, 0, 0};
                bilinearAdd(in, ax, x, ay, y, 1.0f, acc);
                float* o = out.at(x, y);
                o[0] = acc[0];
                o[1] = acc[1];
                o[2] = acc[2];
            }
    });
}

// One output row of a symmetric blur: out[j] = c[j] * w[0] + sum_k (a_k[j] + b_k[j]) * w[k],
// accumulated in that order, where a_k / b_k are the rows (or row offsets) k taps away. Done in
// blocks of 64 floats so the accumulators stay in registers across the taps.
template <class Tap>
inline void blurRow(float* out, const float* c, std::size_t n, const std::vector<float>& w,
                    Tap tap) {
    constexpr std::size_t kBlock = 64;
    const int r = static_cast<int>(w.size()) - 1;
    for (std::size_t j0 = 0; j0 < n; j0 += kBlock) {
        const std::size_t m = std::min(kBlock, n - j0);
        float acc[kBlock];
        for (std::size_t j = 0; j < m; ++j)
            acc[j] = c[j0 + j] * w[0];
        for (int k = 1; k <= r; ++k) {
            const float* a = tap(-k) + j0;
            const float* b = tap(k) + j0;
            const float wk = w[k];
            for (std::size_t j = 0; j < m; ++j)
                acc[j] += (a[j] + b[j]) * wk;
        }
        for (std::size_t j = 0; j < m; ++j)
            out[j0 + j] = acc[j];
    }
}

// Separable blur with symmetric weights w[0] (centre), w[1..] (each side), taps one texel apart,
// clamp to edge; horizontal (over an edge-padded copy of each row) then vertical. Flat loops over
// a row's floats, so the compiler vectorizes them.
inline void separableBlur(RgbBuffer& buf, const std::vector<float>& w, int nthreads) {
    if (buf.w == 0 || buf.h == 0)
        return;
    RgbBuffer tmp;
    tmp.resize(buf.w, buf.h);
    const int r = static_cast<int>(w.size()) - 1;
    const std::size_t rowFloats = static_cast<std::size_t>(buf.w) * 3;
    parallelFor(buf.h, nthreads, [&](int y0, int y1) {
        std::vector<float> padded(static_cast<std::size_t>(buf.w + 2 * r) * 3);
        for (int y = y0; y < y1; ++y) {
            const float* src = buf.at(0, y);
            for (int x = -r; x < buf.w + r; ++x) {
                const float* q = src + 3 * std::clamp(x, 0, buf.w - 1);
                float* o = padded.data() + 3 * (x + r);
                o[0] = q[0];
                o[1] = q[1];
                o[2] = q[2];
            }
            const float* c = padded.data() + 3 * r;
            blurRow(tmp.at(0, y), c, rowFloats, w, [c](int k) { return c + 3 * k; });
        }
    });
    parallelFor(buf.h, nthreads, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            blurRow(buf.at(0, y), tmp.at(0, y), rowFloats, w, [&](int k) {
                return static_cast<const float*>(tmp.at(0, std::clamp(y + k, 0, buf.h - 1)));
            });
    });
}

// Normalized Gaussian half-kernel (centre first) for sigma in texels, radius ceil(3 sigma).
inline std::vector<float> gaussianWeights(float sigma) {
    const int r = std::max(1, static_cast<int>(std::ceil(3.0f * sigma)));
    std::vector<double> d(r + 1);
    double sum = 0.0;
    for (int k = 0; k <= r; ++k) {
        d[k] = lut::math::exp(-0.5 * k * k / (static_cast<double>(sigma) * sigma));
        sum += k == 0 ? d[k] : 2.0 * d[k];
    }
    std::vector<float> w(r + 1);
    for (int k = 0; k <= r; ++k)
        w[k] = static_cast<float>(d[k] / sum);
    return w;
}

// True if pred(pixel) holds for any pixel; stops early once found.
template <class Pred> bool anyPixel(const ImageView& f, int nthreads, Pred pred) {
    std::atomic<bool> found{false};
    parallelFor(f.height, nthreads, [&](int y0, int y1) {
        for (int y = y0; y < y1 && !found.load(std::memory_order_relaxed); ++y) {
            const float* p = f.row(y);
            for (int x = 0; x < f.width; ++x, p += 4)
                if (pred(p)) {
                    found = true;
                    return;
                }
        }
    });
    return found.load();
}

// Adds bloom to rows of the frame (skipping exact zeros, so "nothing to add" is bit-exact).
inline void addRgb(float* p, const float b[3]) {
    if (b[0] != 0.0f)
        p[0] += b[0];
    if (b[1] != 0.0f)
        p[1] += b[1];
    if (b[2] != 0.0f)
        p[2] += b[2];
}

std::unique_ptr<Stage> makeSanitizeStage();
std::unique_ptr<Stage> makeExposureStage();
std::unique_ptr<Stage> makeTonemapStage();
std::unique_ptr<Stage> makeHdrBloomStage();
std::unique_ptr<Stage> makeFilterBloomStage();
std::unique_ptr<Stage> makeSugarBloomStage();
std::unique_ptr<Stage> makeSmashBloomStage();
std::unique_ptr<Stage> makeChromaticAberrationStage();
std::unique_ptr<Stage> makeVignetteStage();
std::unique_ptr<Stage> makeGrainStage();
std::unique_ptr<Stage> makeSmashGradeStage();
std::unique_ptr<Stage> makeLutStage();
std::unique_ptr<Stage> makeDisplayStage();

// The fusion rule's two kinds (Pipeline::run: sRGB display directly after smash-grade in one
// pass runs inside smash-grade's loop, StageContext::fusedDisplay).
bool isSmashGrade(const Stage& s);
bool isSrgbDisplay(const Stage& s);

} // namespace lut::detail
