#include "Tables.h"

#include "lut/pipeline/SmashGrading.h"

#include <cmath>

namespace lut::detail {

const PowTable& powSmashEncode() {
    static const PowTable t(static_cast<double>(kSmashEncodeExponent));
    return t;
}
const PowTable& powSmashDecode() {
    static const PowTable t(static_cast<double>(kSmashDecodeExponent));
    return t;
}
const PowTable& powSrgbEncode() {
    static const PowTable t(1.0 / 2.4);
    return t;
}

const UniformTable& smashDisplayFromBrightened() {
    static const UniformTable t(2.0f, 8192, [](double r) {
        const double x = r > 0.0 ? std::pow(r, static_cast<double>(kSmashDecodeExponent)) : 0.0;
        return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
    });
    return t;
}

} // namespace lut::detail
