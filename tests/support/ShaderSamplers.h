// SPDX-License-Identifier: Apache-2.0
#pragma once
// Engine shaders that sample LUT strips and atlases, written out from their sources as the
// oracle of the strip and atlas tests (docs/specs/strip-layouts.md): ReShade's LUT.fx and
// MultiLUT.fx (crosire/reshade-shaders, Shaders/LUT.fx, Shaders/MultiLUT.fx) and Unity's
// ApplyLut2D (Unity-Technologies/PostProcessing, PostProcessing/Shaders/Colors.hlsl), over
// bilinear texture fetches with clamped addressing; the file is read with OpenImageIO directly.
#include "lut/Lut3D.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace lut::test {

// An 8-bit RGBA texture as the GPU sees it: values 0..1, row 0 the file's first (top) row.
struct Texture {
    int w = 0, h = 0, ch = 0;
    std::vector<float> px;
    double at(int x, int y, int c) const {
        x = std::clamp(x, 0, w - 1); // clamp addressing
        y = std::clamp(y, 0, h - 1);
        return px[(static_cast<std::size_t>(y) * w + x) * ch + c];
    }
    // Bilinear filtering at texture coordinates (u, v), v = 0 at the top row (D3D, ReShade).
    std::array<double, 3> sample(double u, double v) const {
        const double x = u * w - 0.5, y = v * h - 0.5;
        const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
        const double fx = x - x0, fy = y - y0;
        std::array<double, 3> o{};
        for (int c = 0; c < 3; ++c)
            o[c] = (1 - fy) * ((1 - fx) * at(x0, y0, c) + fx * at(x0 + 1, y0, c)) +
                   fy * ((1 - fx) * at(x0, y0 + 1, c) + fx * at(x0 + 1, y0 + 1, c));
        return o;
    }
};

inline Texture load(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << path;
    Texture t;
    t.w = in->spec().width;
    t.h = in->spec().height;
    t.ch = in->spec().nchannels;
    EXPECT_EQ(in->spec().format, OIIO::TypeDesc::UINT8);
    t.px.resize(static_cast<std::size_t>(t.w) * t.h * t.ch);
    in->read_image(0, 0, 0, t.ch, OIIO::TypeDesc::FLOAT, t.px.data());
    return t;
}

// ReShade's LUT.fx, tile size T, T tiles:
//   texelsize = 1 / T; texelsize.x /= T
//   lutcoord = ((c.xy * T - c.xy + 0.5) * texelsize.xy, c.z * T - c.z)
//   lerpfact = frac(lutcoord.z); lutcoord.x += (lutcoord.z - lerpfact) * texelsize.y
//   lerp(tex(lutcoord.xy), tex(lutcoord.x + texelsize.y, lutcoord.y), lerpfact)
// MultiLUT.fx (row `row` of `rows`): lutcoord.y /= rows; lutcoord.y += row / rows.
inline std::array<double, 3> reshadeSample(const Texture& tex, glm::dvec3 c, int row = 0,
                                           int rows = 1) {
    const double T = 32;
    const double tx = 1.0 / T / T, ty = 1.0 / T;
    double x = (c.x * T - c.x + 0.5) * tx, y = (c.y * T - c.y + 0.5) * ty;
    const double z = c.z * T - c.z;
    const double f = z - std::floor(z);
    y = y / rows + static_cast<double>(row) / rows;
    x += (z - f) * ty;
    const auto a = tex.sample(x, y), b = tex.sample(x + ty, y);
    return {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])};
}

// Unity's ApplyLut2D with scaleOffset = (1 / width, 1 / height, height - 1):
//   uvw.z *= scaleOffset.z; shift = floor(uvw.z)
//   uvw.xy = uvw.xy * scaleOffset.z * scaleOffset.xy + scaleOffset.xy * 0.5
//   uvw.x += shift * scaleOffset.y
//   lerp(tex(uvw.xy), tex(uvw.xy + (scaleOffset.y, 0)), uvw.z - shift)
// Unity's texture coordinates have v = 0 at the bottom row: the file's row is flipped.
inline std::array<double, 3> unitySample(const Texture& tex, glm::dvec3 c) {
    const double sx = 1.0 / tex.w, sy = 1.0 / tex.h, sz = tex.h - 1;
    const double z = c.z * sz, shift = std::floor(z);
    double u = c.x * sz * sx + sx * 0.5;
    const double v = c.y * sz * sy + sy * 0.5;
    u += shift * sy;
    const auto a = tex.sample(u, 1.0 - v), b = tex.sample(u + sy, 1.0 - v);
    const double f = z - shift;
    return {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])};
}

// Trilinear interpolation of the LUT in float64 (per axis: index = c * (N - 1)).
inline std::array<double, 3> trilinear(const lut::Lut3D& l, glm::dvec3 c) {
    const int n = l.size();
    int i0[3];
    double f[3];
    for (int a = 0; a < 3; ++a) {
        const double p = std::clamp(c[a], 0.0, 1.0) * (n - 1);
        i0[a] = std::min(static_cast<int>(p), n - 2);
        f[a] = p - i0[a];
    }
    std::array<double, 3> o{};
    for (int k = 0; k < 8; ++k) {
        const int dr = k & 1, dg = (k >> 1) & 1, db = (k >> 2) & 1;
        const double w = (dr ? f[0] : 1 - f[0]) * (dg ? f[1] : 1 - f[1]) * (db ? f[2] : 1 - f[2]);
        const glm::vec3 e = l.at(i0[0] + dr, i0[1] + dg, i0[2] + db);
        for (int ch = 0; ch < 3; ++ch)
            o[ch] += w * e[ch];
    }
    return o;
}

} // namespace lut::test
