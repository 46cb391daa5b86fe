#include "lut/ops/Strength.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/Parallel.h"

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <sstream>

namespace lut {

namespace {

// Oklab (https://bottosson.github.io/posts/oklab/): linear sRGB -> LMS (M1), cube root, -> Lab
// (M2). glm matrices are column-major: each row of Ottosson's matrices is written as a column
// and the matrix transposed.
const glm::dmat3 kM1 = glm::transpose(glm::dmat3(0.4122214708, 0.5363325363, 0.0514459929, //
                                                 0.2119034982, 0.6806995451, 0.1073969566, //
                                                 0.0883024619, 0.2817188376, 0.6299787005));
const glm::dmat3 kM2 = glm::transpose(glm::dmat3(0.2104542553, 0.7936177850, -0.0040720468, //
                                                 1.9779984951, -2.4285922050, 0.4505937099, //
                                                 0.0259040371, 0.7827717662, -0.8086757660));
// The exact inverses (not Ottosson's rounded ones), so Lab -> RGB undoes RGB -> Lab to double
// rounding and a blend with amounts (1, 0) or (0, 1) keeps the other component to float rounding.
const glm::dmat3 kM1Inv = glm::inverse(kM1);
const glm::dmat3 kM2Inv = glm::inverse(kM2);

double decode(double v) {
    const double a = std::fabs(v);
    const double l = a <= 0.04045 ? a / 12.92 : std::pow((a + 0.055) / 1.055, 2.4);
    return std::copysign(l, v);
}

double encode(double v) {
    const double a = std::fabs(v);
    const double e = a <= 0.0031308 ? a * 12.92 : 1.055 * std::pow(a, 1.0 / 2.4) - 0.055;
    return std::copysign(e, v);
}

glm::dvec3 toOklab(glm::dvec3 c) {
    glm::dvec3 lms = kM1 * glm::dvec3(decode(c.x), decode(c.y), decode(c.z));
    lms = glm::dvec3(std::cbrt(lms.x), std::cbrt(lms.y), std::cbrt(lms.z));
    return kM2 * lms;
}

glm::dvec3 fromOklab(glm::dvec3 lab) {
    glm::dvec3 lms = kM2Inv * lab;
    lms *= lms * lms;
    const glm::dvec3 rgb = kM1Inv * lms;
    return {encode(rgb.x), encode(rgb.y), encode(rgb.z)};
}

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
            checkedAmount(options.chroma.value_or(options.strength), "chroma")};
}

bool isFullStrength(const StrengthOptions& options) {
    const StrengthAmounts a = strengthAmounts(options);
    return a.luma == 1.0 && a.chroma == 1.0;
}

glm::dvec3 blendStrength(const glm::dvec3& input, const glm::dvec3& graded,
                         const StrengthAmounts& amount) {
    const glm::dvec3 x(sanitize(input.x), sanitize(input.y), sanitize(input.z));
    const glm::dvec3 y(sanitize(graded.x), sanitize(graded.y), sanitize(graded.z));
    const glm::dvec3 lx = toOklab(x);
    const glm::dvec3 ly = toOklab(y);
    const double tl = amount.luma, tc = amount.chroma;
    const glm::dvec3 lab(lx.x + tl * (ly.x - lx.x), lx.y + tc * (ly.y - lx.y),
                         lx.z + tc * (ly.z - lx.z));
    const glm::dvec3 e = fromOklab(lab);
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
