// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Strength.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/Parallel.h"
#include "lut/ops/Oklab.h"

#include <cmath>
#include <sstream>

namespace lut {

namespace {

// NaN -> 0, +-Inf and beyond -> +-kMaxColorValue, as every LUT operation does (ops/OpsDetail.h).
double sanitize(double v) {
    if (v != v)
        return 0.0;
    constexpr double m = limits::kMaxColorValue;
    return v < -m ? -m : v > m ? m : v;
}

double limited(double v) {
    constexpr double m = limits::kMaxColorValue;
    return v != v ? 0.0 : v < -m ? -m : v > m ? m : v;
}

float toStored(double v) {
    return static_cast<float>(limited(v));
}

double checkedAmount(double v, const char* what) {
    if (!(v >= 0.0 && v <= 2.0)) {
        std::ostringstream s;
        s << "strength: the " << what << " amount must be between 0 and 2, got " << v;
        throw Error(s.str());
    }
    return v;
}

} // namespace

StrengthAmounts strengthAmounts(const StrengthOptions& options) {
    checkedAmount(options.strength, "overall");
    return {checkedAmount(options.luma.value_or(options.strength), "luma"),
            checkedAmount(options.chroma.value_or(options.strength), "chroma"), options.blend};
}

bool isFullStrength(const StrengthOptions& options) {
    const StrengthAmounts a = strengthAmounts(options);
    return a.luma == 1.0 && a.chroma == 1.0;
}

glm::dvec3 blendStrength(const glm::dvec3& input, const glm::dvec3& graded,
                         const StrengthAmounts& amount) {
    const glm::dvec3 x(sanitize(input.x), sanitize(input.y), sanitize(input.z));
    const glm::dvec3 y(sanitize(graded.x), sanitize(graded.y), sanitize(graded.z));
    const double tl = amount.luma, tc = amount.chroma;
    if (amount.blend == StrengthBlend::ReShade) {
        // LUT.fx: lerp(normalize(x), normalize(y), chroma) * lerp(length(x), length(y), luma)
        const double nx = std::sqrt(x.x * x.x + x.y * x.y + x.z * x.z);
        const double ny = std::sqrt(y.x * y.x + y.y * y.y + y.z * y.z);
        const glm::dvec3 dx = nx > 0.0 ? x / nx : glm::dvec3(0.0);
        const glm::dvec3 dy = ny > 0.0 ? y / ny : glm::dvec3(0.0);
        const glm::dvec3 e = (dx + tc * (dy - dx)) * (nx + tl * (ny - nx));
        return {limited(e.x), limited(e.y), limited(e.z)};
    }
    const glm::dvec3 lx = srgbToOklab(x);
    const glm::dvec3 ly = srgbToOklab(y);
    const glm::dvec3 lab(lx.x + tl * (ly.x - lx.x), lx.y + tc * (ly.y - lx.y),
                         lx.z + tc * (ly.z - lx.z));
    const glm::dvec3 e = oklabToSrgb(lab);
    return {limited(e.x), limited(e.y), limited(e.z)};
}

Lut3D applyStrength(const Lut3D& lut, const StrengthOptions& options) {
    if (lut.empty())
        throw Error("strength: the LUT has no entries");
    const StrengthAmounts amount = strengthAmounts(options);
    if (amount.luma == 1.0 && amount.chroma == 1.0)
        return lut;
    Lut3D out = lut;
    const int n = lut.size();
    const bool neutral = amount.luma == 0.0 && amount.chroma == 0.0;
    parallelFor(n, n < 17 ? 1 : 0, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r) {
                    const glm::vec3 x = lut.latticeInput(r, g, b);
                    if (neutral) {
                        out.at(r, g, b) = x;
                        continue;
                    }
                    const glm::vec3 y = lut.at(r, g, b);
                    const glm::dvec3 e = blendStrength(glm::dvec3(x), glm::dvec3(y), amount);
                    out.at(r, g, b) = glm::vec3(toStored(e.x), toStored(e.y), toStored(e.z));
                }
    });
    return out;
}

} // namespace lut
