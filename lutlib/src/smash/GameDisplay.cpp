// SPDX-License-Identifier: Apache-2.0
// The game's display model in double; see GameDisplay.h.
#include "lut/smash/GameDisplay.h"

#include "lut/Math.h"
#include "lut/smash/SmashConstants.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lut::detail {

namespace {
// The pipeline's float literals, exactly, in double.
constexpr double kBrightenMix = kSmashBrightenMix;
constexpr double kBrightenScale = kSmashBrightenScale;
constexpr double kGammaDecode = kSmashDecodeExponent;
} // namespace

double srgbEncodeUnit(double x) {
    if (!(x > 0.0))
        return 0.0;
    if (x >= 1.0)
        return 1.0;
    return x <= 0.0031308 ? 12.92 * x : 1.055 * lut::math::pow(x, 1.0 / 2.4) - 0.055;
}

double srgbDecodeUnit(double v) {
    if (!(v > 0.0))
        return 0.0;
    if (v >= 1.0)
        return 1.0;
    return v <= 0.04045 ? v / 12.92 : lut::math::pow((v + 0.055) / 1.055, 2.4);
}

double srgbEncodeExtended(double x) {
    if (!(x == x))
        return 0.0;
    const double a = std::fabs(x);
    const double e = a <= 0.0031308 ? 12.92 * a : 1.055 * lut::math::pow(a, 1.0 / 2.4) - 0.055;
    return x < 0 ? -e : e;
}

double srgbDecodeExtended(double e) {
    if (!(e == e))
        return 0.0;
    const double a = std::fabs(e);
    const double x = a <= 0.04045 ? a / 12.92 : lut::math::pow((a + 0.055) / 1.055, 2.4);
    return e < 0 ? -x : x;
}

double clampUnit(double v) {
    return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
}

double gameShown(double lutOut, double s) {
    const double r = ((lutOut - s) * kBrightenMix + s) * kBrightenScale;
    return srgbEncodeUnit(clampUnit(lut::math::pow(std::max(r, 0.0), kGammaDecode)));
}

namespace {
// gameShown as a function of the brightened value r = ((lutOut - s) mix + s) scale, tabulated on
// 2^16 intervals of [0, 1.4] (r >= 1 shows white) and interpolated linearly: within 1e-6 of the
// display value (most intervals far closer; the clip at r = 1 costs one interval 5e-6).
class ShownOfBrightened {
public:
    ShownOfBrightened() : m_v(kSize + 2) {
        for (int i = 0; i <= kSize + 1; ++i) {
            const double r = kMax * i / kSize;
            m_v[static_cast<std::size_t>(i)] =
                srgbEncodeUnit(clampUnit(lut::math::pow(r, kGammaDecode)));
        }
    }
    double operator()(double r) const {
        if (!(r > 0.0))
            return 0.0;
        const double x = r * (kSize / kMax);
        if (x >= kSize)
            return 1.0;
        const std::size_t i = static_cast<std::size_t>(x);
        const double f = x - static_cast<double>(i);
        return m_v[i] + f * (m_v[i + 1] - m_v[i]);
    }

private:
    static constexpr int kSize = 1 << 16;
    static constexpr double kMax = 1.4;
    std::vector<double> m_v;
};
} // namespace

double gameShownTabulated(double lutOut, double s) {
    static const ShownOfBrightened table;
    return table(((lutOut - s) * kBrightenMix + s) * kBrightenScale);
}

double gameShownUnclipped(double lutOut, double s) {
    const double r = ((lutOut - s) * kBrightenMix + s) * kBrightenScale;
    return srgbEncodeExtended(lut::math::pow(std::max(r, 0.0), kGammaDecode));
}

double gameShownSlope(double lutOut, double s) {
    const double r = ((lutOut - s) * kBrightenMix + s) * kBrightenScale;
    if (!(r > 0.0))
        return 0.0;
    const double x = lut::math::pow(r, kGammaDecode);
    if (x >= 1.0)
        return 0.0;
    const double dx =
        kGammaDecode * lut::math::pow(r, kGammaDecode - 1.0) * kBrightenScale * kBrightenMix;
    const double de = x <= 0.0031308 ? 12.92 : 1.055 / 2.4 * lut::math::pow(x, 1.0 / 2.4 - 1.0);
    return de * dx;
}

double lutForShown(double display, double s) {
    const double t = srgbDecodeExtended(display);
    const double r = t > 0.0 ? lut::math::pow(t, 1.0 / kGammaDecode) : 0.0;
    return (r / kBrightenScale - s) / kBrightenMix + s;
}

double gameDisplayLatticeValue(int index) {
    const double s = index / static_cast<double>(kSmashLutSize - 1);
    return srgbEncodeUnit(clampUnit(lut::math::pow(s * kBrightenScale, kGammaDecode)));
}

} // namespace lut::detail
