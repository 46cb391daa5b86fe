// SPDX-License-Identifier: Apache-2.0
#pragma once
// Helpers for the pipeline tests: deterministic scenes and float64 reference maths written from
// docs/specs/smash-pipeline.md (independent of lutlib's implementation).
#include "lut/Image.h"
#include "lut/Lut3D.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace lut::test {

// Deterministic pseudo-random numbers (splitmix64).
struct Rng {
    std::uint64_t s;
    explicit Rng(std::uint64_t seed) : s(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double uniform() { return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0); }
};

// An HDR scene: mostly 0..1.2, some highlights up to `peak`, alpha a mix of 0, 1 and fractions.
inline Image makeScene(int w, int h, std::uint64_t seed, float peak = 20.0f, bool alphaMix = true) {
    Image img(w, h);
    Rng r(seed);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = static_cast<float>(1.2 * r.uniform());
            if (r.uniform() < 0.08)
                for (int c = 0; c < 3; ++c)
                    p[c] = static_cast<float>(1.0 + (peak - 1.0) * r.uniform());
            const double a = r.uniform();
            p[3] = !alphaMix  ? 1.0f
                   : a < 0.15 ? 0.0f
                   : a < 0.75 ? 1.0f
                              : static_cast<float>(r.uniform());
        }
    return img;
}

// A smooth, invertible, non-trivial grading LUT over [0,1] (gamma-space entries).
inline Lut3D makeWarmLut(int n = 16, double amount = 1.0) {
    Lut3D l(n);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const double R = r / (n - 1.0), G = g / (n - 1.0), B = b / (n - 1.0);
                const double y = 0.3 * R + 0.6 * G + 0.1 * B;
                l.at(r, g, b) = glm::vec3(
                    static_cast<float>(R + amount * (0.06 * std::sin(3.0 * R) + 0.04 * (y - R))),
                    static_cast<float>(G + amount * (0.03 * std::sin(2.0 * G) * (1 - G))),
                    static_cast<float>(B + amount * (-0.05 * B * (1 - B) + 0.02 * (y - B))));
            }
    return l;
}

// ---- float64 reference of docs/specs/smash-pipeline.md ----

struct RefImg {
    int w = 0, h = 0, ch = 3;
    std::vector<double> v;
    RefImg(int w_, int h_, int c_ = 3)
        : w(w_), h(h_), ch(c_), v(static_cast<std::size_t>(w_) * h_ * c_, 0.0) {}
    double& at(int x, int y, int c) { return v[(static_cast<std::size_t>(y) * w + x) * ch + c]; }
    double at(int x, int y, int c) const {
        return v[(static_cast<std::size_t>(y) * w + x) * ch + c];
    }
    // GPU bilinear at normalized (u, v): texel centres at (i + 0.5) / w, clamp to edge.
    double sample(double u, double vv, int c) const {
        const double fx = u * w - 0.5, fy = vv * h - 0.5;
        const double x0 = std::floor(fx), y0 = std::floor(fy);
        const double tx = fx - x0, ty = fy - y0;
        auto cl = [](double i, int n) { return std::clamp(static_cast<int>(i), 0, n - 1); };
        const int xa = cl(x0, w), xb = cl(x0 + 1, w), ya = cl(y0, h), yb = cl(y0 + 1, h);
        const double top = at(xa, ya, c) * (1 - tx) + at(xb, ya, c) * tx;
        const double bot = at(xa, yb, c) * (1 - tx) + at(xb, yb, c) * tx;
        return top * (1 - ty) + bot * ty;
    }
};

inline RefImg toRef(const Image& img) {
    RefImg r(img.width(), img.height(), 4);
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            for (int c = 0; c < 4; ++c)
                r.at(x, y, c) = img.pixel(x, y)[c];
    return r;
}

// Section 1: the bloom to add at full resolution (RGB).
inline RefImg refSmashBloom(const RefImg& scene) {
    const int W = scene.w, H = scene.h;
    const int w4 = std::max(1, W / 4), h4 = std::max(1, H / 4);
    RefImg th(w4, h4);
    for (int j = 0; j < h4; ++j)
        for (int i = 0; i < w4; ++i) {
            const double u = (i + 0.5) / w4, v = (j + 0.5) / h4;
            double c[3];
            for (int k = 0; k < 3; ++k)
                c[k] = std::clamp(scene.sample(u, v, k), 0.0, 1.0);
            const double a = std::clamp(scene.sample(u, v, 3), 0.0, 1.0);
            const double m = std::max({c[0], c[1], c[2], 0.001});
            for (int k = 0; k < 3; ++k)
                th.at(i, j, k) = c[k] / m * std::max(m - 0.4625, 0.0) * 6.0 * a;
        }
    std::vector<RefImg> levels;
    const RefImg* in = &th;
    const double kw[3] = {1, 2, 1};
    for (int l = 0; l < 4; ++l) {
        const int wo = std::max(1, in->w / 2), ho = std::max(1, in->h / 2);
        RefImg out(wo, ho);
        for (int j = 0; j < ho; ++j)
            for (int i = 0; i < wo; ++i) {
                const double u = (i + 0.5) / wo, v = (j + 0.5) / ho;
                for (int k = 0; k < 3; ++k) {
                    double s = 0;
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx)
                            s += kw[dx + 1] * kw[dy + 1] / 16.0 *
                                 in->sample(u + dx / double(in->w), v + dy / double(in->h), k);
                    out.at(i, j, k) = s;
                }
            }
        levels.push_back(std::move(out));
        in = &levels.back();
    }
    RefImg comb(w4, h4);
    const double wt[4] = {0.32, 0.10, 0.20, 0.25};
    for (int j = 0; j < h4; ++j)
        for (int i = 0; i < w4; ++i) {
            const double u = (i + 0.5) / w4, v = (j + 0.5) / h4;
            for (int k = 0; k < 3; ++k) {
                double s = 0;
                for (int l = 0; l < 4; ++l)
                    s += wt[l] * levels[l].sample(u, v, k);
                comb.at(i, j, k) = std::pow(std::clamp(s, 0.0, 1.0), 2.2);
            }
        }
    RefImg up(W, H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            for (int k = 0; k < 3; ++k)
                up.at(x, y, k) = comb.sample((x + 0.5) / W, (y + 0.5) / H, k);
    return up;
}

// The lattice cell holding `in` (clamped to [0,1]): its lower corner i and the fractions f.
inline void refCell(const Lut3D& lut, const double in[3], int i[3], double f[3]) {
    const int n = lut.size();
    for (int c = 0; c < 3; ++c) {
        const double t = std::clamp(in[c], 0.0, 1.0) * (n - 1);
        i[c] = std::min(static_cast<int>(std::floor(t)), n - 2);
        f[c] = t - i[c];
    }
}

// Tetrahedral interpolation of a LUT over [0,1] in double (clamp to edge): the cube cell is cut
// into six tetrahedra along its main diagonal, chosen by the order of the fractions.
inline void refTetrahedral(const Lut3D& lut, const double in[3], double out[3]) {
    int i[3];
    double f[3];
    refCell(lut, in, i, f);
    // Walk from corner 000 to 111 one axis at a time, largest fraction first.
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int a, int b) { return f[a] > f[b]; });
    int corner[3] = {i[0], i[1], i[2]};
    auto entry = [&](int k) {
        const glm::vec3 v = lut.at(corner[0], corner[1], corner[2]);
        return static_cast<double>(v[k]);
    };
    double acc[3], prev[3];
    for (int k = 0; k < 3; ++k)
        acc[k] = prev[k] = entry(k);
    for (int step = 0; step < 3; ++step) {
        const int axis = order[step];
        const double w = f[axis];
        corner[axis] += 1;
        for (int k = 0; k < 3; ++k) {
            const double v = entry(k);
            acc[k] += w * (v - prev[k]);
            prev[k] = v;
        }
    }
    for (int k = 0; k < 3; ++k)
        out[k] = acc[k];
}

// Plain trilinear of a LUT over [0,1], clamp to edge, in double.
inline void refTrilinear(const Lut3D& lut, const double in[3], double out[3]) {
    int i[3];
    double f[3];
    refCell(lut, in, i, f);
    for (int c = 0; c < 3; ++c) {
        double acc = 0;
        for (int k = 0; k < 8; ++k) {
            const int dr = k & 1, dg = (k >> 1) & 1, db = (k >> 2) & 1;
            const double w =
                (dr ? f[0] : 1 - f[0]) * (dg ? f[1] : 1 - f[1]) * (db ? f[2] : 1 - f[2]);
            acc += w * lut.at(i[0] + dr, i[1] + dg, i[2] + db)[c];
        }
        out[c] = acc;
    }
}

// Section 2 with the alpha mix: GPU lookup at s * 0.9375 + 0.03125 on a 16^3 texture, written as
// the texture coordinate the hardware uses (u * 16 - 0.5 = texel coordinate).
inline void refSmashGrade(const Lut3D& lut, const double x[3], double alpha, double out[3]) {
    double s[3], uvwTexel[3];
    for (int c = 0; c < 3; ++c) {
        s[c] = std::pow(std::max(x[c], 0.0), 0.454545);
        const double uvw = s[c] * 0.9375 + 0.03125;
        uvwTexel[c] =
            (uvw * 16.0 - 0.5) / 15.0; // texel coordinate / (N-1): same as trilinear over [0,1]
    }
    double L[3];
    refTrilinear(lut, uvwTexel, L);
    const double a = std::clamp(alpha, 0.0, 1.0);
    for (int c = 0; c < 3; ++c) {
        double r = (L[c] - s[c]) * 0.99961 + s[c];
        r *= 1.3703;
        const double g = std::pow(std::max(r, 0.0), 2.2);
        out[c] = x[c] * (1 - a) + g * a;
    }
}

inline double refSrgbEncode(double x) {
    const double a = std::fabs(x);
    const double e = a <= 0.0031308 ? 12.92 * a : 1.055 * std::pow(a, 1 / 2.4) - 0.055;
    return x < 0 ? -e : e;
}

inline double relErr(double got, double want) {
    return std::fabs(got - want) / std::max(1.0, std::fabs(want));
}

} // namespace lut::test
