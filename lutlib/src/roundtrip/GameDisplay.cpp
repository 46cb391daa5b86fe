// The game's display model in double; see GameDisplay.h.
#include "roundtrip/GameDisplay.h"

#include "lut/pipeline/SmashConstants.h"
#include "lut/roundtrip/PatchLattice.h"

#include <algorithm>
#include <cmath>

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
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

double srgbDecodeUnit(double v) {
    if (!(v > 0.0))
        return 0.0;
    if (v >= 1.0)
        return 1.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

double clampUnit(double v) {
    return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
}

double gameShown(double lutOut, double s) {
    const double r = ((lutOut - s) * kBrightenMix + s) * kBrightenScale;
    return srgbEncodeUnit(clampUnit(std::pow(std::max(r, 0.0), kGammaDecode)));
}

double gameDisplayLatticeValue(int index) {
    if (index >= kSmashLatticeSize - 1)
        return 1.0;
    const double s = index / static_cast<double>(kSmashLutSize - 1);
    return srgbEncodeUnit(clampUnit(std::pow(s * kBrightenScale, kGammaDecode)));
}

} // namespace lut::detail
