// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/ColorDifference.h"

#include "lut/Limits.h"
#include "lut/Math.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lut {

namespace {

constexpr double kMax = limits::kMaxColorValue; // as a double
constexpr double kPi = std::numbers::pi;

double finiteOrZero(double v) {
    return std::isnan(v) ? 0.0 : std::clamp(v, -kMax, kMax);
}

double decode(double v) {
    const double a = std::fabs(v);
    const double lin = a <= 0.04045 ? a / 12.92 : lut::math::pow((a + 0.055) / 1.055, 2.4);
    return v < 0.0 ? -lin : lin;
}

// sRGB primaries (0.64, 0.33), (0.30, 0.60), (0.15, 0.06) and D65 (0.3127, 0.3290) give this
// matrix (rows X, Y, Z), rounded to 7 places as IEC 61966-2-1:2003 amendment 1 lists it.
constexpr double kM[3][3] = {{0.4123908, 0.3575843, 0.1804808},
                             {0.2126390, 0.7151687, 0.0721923},
                             {0.0193308, 0.1191948, 0.9505322}};
constexpr double kWhite[3] = {kM[0][0] + kM[0][1] + kM[0][2], kM[1][0] + kM[1][1] + kM[1][2],
                              kM[2][0] + kM[2][1] + kM[2][2]};

double labF(double t) {
    constexpr double d = 6.0 / 29.0;
    return t > d * d * d ? lut::math::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
}

double deg(double rad) {
    return rad * 180.0 / kPi;
}
double rad(double deg) {
    return deg * kPi / 180.0;
}

} // namespace

glm::dvec3 srgbToLinear(glm::dvec3 e) {
    return {decode(finiteOrZero(e.x)), decode(finiteOrZero(e.y)), decode(finiteOrZero(e.z))};
}

glm::dvec3 linearSrgbToXyz(glm::dvec3 l) {
    glm::dvec3 out;
    for (int r = 0; r < 3; ++r)
        out[r] = kM[r][0] * l.x + kM[r][1] * l.y + kM[r][2] * l.z;
    return out;
}

glm::dvec3 xyzToLab(glm::dvec3 xyz) {
    const double fx = labF(finiteOrZero(xyz.x) / kWhite[0]);
    const double fy = labF(finiteOrZero(xyz.y) / kWhite[1]);
    const double fz = labF(finiteOrZero(xyz.z) / kWhite[2]);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

glm::dvec3 srgbToLab(glm::dvec3 encoded) {
    return xyzToLab(linearSrgbToXyz(srgbToLinear(encoded)));
}

double deltaE2000(glm::dvec3 lab1, glm::dvec3 lab2) {
    const double L1 = lab1.x, a1 = lab1.y, b1 = lab1.z;
    const double L2 = lab2.x, a2 = lab2.y, b2 = lab2.z;
    const double C1 = lut::math::hypot(a1, b1), C2 = lut::math::hypot(a2, b2);
    const double Cbar = 0.5 * (C1 + C2);
    const double Cbar7 = lut::math::pow(Cbar, 7.0);
    const double G = 0.5 * (1.0 - std::sqrt(Cbar7 / (Cbar7 + lut::math::pow(25.0, 7.0))));
    const double a1p = (1.0 + G) * a1, a2p = (1.0 + G) * a2;
    const double C1p = lut::math::hypot(a1p, b1), C2p = lut::math::hypot(a2p, b2);
    auto hueAngle = [](double b, double ap) {
        if (b == 0.0 && ap == 0.0)
            return 0.0;
        const double h = deg(lut::math::atan2(b, ap));
        return h < 0.0 ? h + 360.0 : h;
    };
    const double h1p = hueAngle(b1, a1p), h2p = hueAngle(b2, a2p);
    const double dLp = L2 - L1, dCp = C2p - C1p;
    double dhp = 0.0;
    if (C1p * C2p != 0.0) {
        dhp = h2p - h1p;
        if (dhp > 180.0)
            dhp -= 360.0;
        else if (dhp < -180.0)
            dhp += 360.0;
    }
    const double dHp = 2.0 * std::sqrt(C1p * C2p) * lut::math::sin(rad(dhp) / 2.0);
    const double Lbarp = 0.5 * (L1 + L2), Cbarp = 0.5 * (C1p + C2p);
    double hbarp = h1p + h2p;
    if (C1p * C2p != 0.0) {
        if (std::fabs(h1p - h2p) <= 180.0)
            hbarp *= 0.5;
        else
            hbarp = hbarp < 360.0 ? 0.5 * (hbarp + 360.0) : 0.5 * (hbarp - 360.0);
    }
    const double T = 1.0 - 0.17 * lut::math::cos(rad(hbarp - 30.0)) +
                     0.24 * lut::math::cos(rad(2.0 * hbarp)) +
                     0.32 * lut::math::cos(rad(3.0 * hbarp + 6.0)) -
                     0.20 * lut::math::cos(rad(4.0 * hbarp - 63.0));
    const double dTheta = 30.0 * lut::math::exp(-lut::math::pow((hbarp - 275.0) / 25.0, 2.0));
    const double Cbarp7 = lut::math::pow(Cbarp, 7.0);
    const double RC = 2.0 * std::sqrt(Cbarp7 / (Cbarp7 + lut::math::pow(25.0, 7.0)));
    const double l50 = (Lbarp - 50.0) * (Lbarp - 50.0);
    const double SL = 1.0 + 0.015 * l50 / std::sqrt(20.0 + l50);
    const double SC = 1.0 + 0.045 * Cbarp;
    const double SH = 1.0 + 0.015 * Cbarp * T;
    const double RT = -lut::math::sin(rad(2.0 * dTheta)) * RC;
    const double tL = dLp / SL, tC = dCp / SC, tH = dHp / SH;
    const double sq = tL * tL + tC * tC + tH * tH + RT * tC * tH;
    return std::sqrt(std::max(0.0, sq));
}

} // namespace lut
