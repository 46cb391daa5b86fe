#include "lut/ops/Oklab.h"

#include "lut/ops/ColorDifference.h"

#include <cmath>
#include <numbers>

namespace lut {

namespace {

double encode(double v) {
    const double a = std::fabs(v);
    const double e = a <= 0.0031308 ? 12.92 * a : 1.055 * std::pow(a, 1.0 / 2.4) - 0.055;
    return v < 0.0 ? -e : e;
}

} // namespace

glm::dvec3 linearSrgbToOklab(glm::dvec3 c) {
    const double l = 0.4122214708 * c.x + 0.5363325363 * c.y + 0.0514459929 * c.z;
    const double m = 0.2119034982 * c.x + 0.6806995451 * c.y + 0.1073969566 * c.z;
    const double s = 0.0883024619 * c.x + 0.2817188376 * c.y + 0.6299787005 * c.z;
    const double l3 = std::cbrt(l), m3 = std::cbrt(m), s3 = std::cbrt(s);
    return {0.2104542553 * l3 + 0.7936177850 * m3 - 0.0040720468 * s3,
            1.9779984951 * l3 - 2.4285922050 * m3 + 0.4505937099 * s3,
            0.0259040371 * l3 + 0.7827717662 * m3 - 0.8086757660 * s3};
}

glm::dvec3 oklabToLinearSrgb(glm::dvec3 lab) {
    const double l3 = lab.x + 0.3963377774 * lab.y + 0.2158037573 * lab.z;
    const double m3 = lab.x - 0.1055613458 * lab.y - 0.0638541728 * lab.z;
    const double s3 = lab.x - 0.0894841775 * lab.y - 1.2914855480 * lab.z;
    const double l = l3 * l3 * l3, m = m3 * m3 * m3, s = s3 * s3 * s3;
    return {4.0767416621 * l - 3.3077115913 * m + 0.2309699292 * s,
            -1.2684380046 * l + 2.6097574011 * m - 0.3413193965 * s,
            -0.0041960863 * l - 0.7034186147 * m + 1.7076147010 * s};
}

glm::dvec3 srgbToOklab(glm::dvec3 encoded) {
    return linearSrgbToOklab(srgbToLinear(encoded));
}

glm::dvec3 oklabToSrgb(glm::dvec3 lab) {
    const glm::dvec3 l = oklabToLinearSrgb(lab);
    return {encode(l.x), encode(l.y), encode(l.z)};
}

double oklabHue(glm::dvec3 lab) {
    const double h = std::atan2(lab.z, lab.y) * 180.0 / std::numbers::pi;
    return h < 0.0 ? h + 360.0 : (h >= 360.0 ? h - 360.0 : h);
}

double oklabChroma(glm::dvec3 lab) {
    return std::hypot(lab.y, lab.z);
}

glm::dvec3 oklabFromLch(double lightness, double chroma, double hueDegrees) {
    const double h = hueDegrees * std::numbers::pi / 180.0;
    return {lightness, chroma * std::cos(h), chroma * std::sin(h)};
}

double hueDifference(double from, double to) {
    double d = std::fmod(to - from, 360.0);
    if (d <= -180.0)
        d += 360.0;
    else if (d > 180.0)
        d -= 360.0;
    return d;
}

} // namespace lut
