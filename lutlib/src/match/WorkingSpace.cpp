// SPDX-License-Identifier: Apache-2.0
#include "lut/match/WorkingSpace.h"
#include "lut/Math.h"

#include <algorithm>
#include <cmath>

namespace lut {

namespace {
constexpr double kLinA = 10.5402377416545;
constexpr double kLinB = 0.0729055341958355;
constexpr double kBreak = 0.0078125;          // 2^-7
constexpr double kBreakW = 0.155251141552511; // (log2(2^-7) + 9.72) / 17.52
constexpr double kMax = 65504.0;
} // namespace

double encodeWorking(double x, bool linear) {
    if (!linear)
        return x;
    return x <= kBreak ? kLinA * x + kLinB : (lut::math::log2(x) + 9.72) / 17.52;
}

double decodeWorking(double w, bool linear) {
    if (!linear)
        return w;
    const double x = w <= kBreakW ? (w - kLinB) / kLinA : lut::math::exp2(w * 17.52 - 9.72);
    return std::clamp(x, -kMax, kMax);
}

double srgbEncodeExtended(double x) {
    const double a = std::fabs(x);
    const double e = a <= 0.0031308 ? 12.92 * a : 1.055 * lut::math::pow(a, 1.0 / 2.4) - 0.055;
    return x < 0.0 ? -e : e;
}

double srgbDecodeExtended(double v) {
    const double a = std::fabs(v);
    const double d = a <= 0.04045 ? a / 12.92 : lut::math::pow((a + 0.055) / 1.055, 2.4);
    return v < 0.0 ? -d : d;
}

} // namespace lut
