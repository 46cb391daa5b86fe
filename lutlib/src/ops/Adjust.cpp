// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Adjust.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/Math.h"
#include "lut/Parallel.h"

#include <algorithm>
#include <cmath>

namespace lut {

namespace {

constexpr double kGamma = 2.2;
constexpr double kMaxValue = limits::kMaxColorValue; // the one limit, as a double
constexpr glm::dvec3 kLuma{0.2126, 0.7152, 0.0722};

// NaN -> 0, +-Inf and huge values -> +-kMaxValue: every step below stays finite.
double sanitize(double v) {
    if (std::isnan(v))
        return 0.0;
    return std::clamp(v, -kMaxValue, kMaxValue);
}
glm::dvec3 sanitize(glm::dvec3 v) {
    return {sanitize(v.x), sanitize(v.y), sanitize(v.z)};
}
double sanitizeParam(double v, double lo, double hi, double fallback) {
    if (!std::isfinite(v))
        return fallback;
    return std::clamp(v, lo, hi);
}

// Odd extension of pow so negative entries (wide-gamut grades) stay defined.
double spow(double x, double p) {
    return x < 0.0 ? -lut::math::pow(-x, p) : lut::math::pow(x, p);
}
glm::dvec3 spow(glm::dvec3 v, glm::dvec3 p) {
    return {spow(v.x, p.x), spow(v.y, p.y), spow(v.z, p.z)};
}
glm::dvec3 spow(glm::dvec3 v, double p) {
    return spow(v, glm::dvec3(p));
}

double dot3(glm::dvec3 a, glm::dvec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// Linear-light gains (white balance times exposure); identity gains skip the decode/encode so a
// neutral setting returns entries bit for bit.
glm::dvec3 applyLinearGains(glm::dvec3 e, glm::dvec3 gains) {
    if (gains == glm::dvec3(1.0))
        return e;
    const glm::dvec3 lin = spow(e, kGamma) * gains;
    return sanitize(spow(sanitize(lin), 1.0 / kGamma));
}

double clampedGamma(double g) {
    return sanitizeParam(g, 0.01, 100.0, 1.0);
}

// HSV's hexcone hue (degrees), the largest channel and the chroma (max - min channel).
struct HueChroma {
    double hue = 0.0;
    double max = 0.0;
    double chroma = 0.0;
};

HueChroma hueChroma(glm::dvec3 e) {
    const double mx = std::max({e.x, e.y, e.z});
    const double c = mx - std::min({e.x, e.y, e.z});
    HueChroma hc{0.0, mx, c};
    if (!(c > 0.0))
        return hc;
    double h;
    if (mx == e.x)
        h = (e.y - e.z) / c;
    else if (mx == e.y)
        h = (e.z - e.x) / c + 2.0;
    else
        h = (e.x - e.y) / c + 4.0;
    h *= 60.0;
    hc.hue = h < 0.0 ? h + 360.0 : h;
    return hc;
}

// The colour of hue `hue` (any value, wrapped) with largest channel mx and chroma c.
glm::dvec3 fromHueChroma(double hue, double mx, double c) {
    double h = std::fmod(hue, 360.0);
    if (h < 0.0)
        h += 360.0;
    const double s = h / 60.0;
    const int sector = std::min(5, static_cast<int>(s));
    const double f = s - sector;
    const double mn = mx - c, rise = mn + c * f, fall = mx - c * f;
    switch (sector) {
    case 0:
        return {mx, rise, mn};
    case 1:
        return {fall, mx, mn};
    case 2:
        return {mn, mx, rise};
    case 3:
        return {mn, fall, mx};
    case 4:
        return {rise, mn, mx};
    default:
        return {mx, mn, fall};
    }
}

} // namespace

bool Adjustments::isNeutral() const {
    Adjustments scalars = *this;
    scalars.curveMaster = scalars.curveRed = scalars.curveGreen = scalars.curveBlue =
        Curve(CurveKind::Tone);
    scalars.hueVsHue = scalars.hueVsSat = scalars.hueVsLum = Curve(CurveKind::Hue);
    return scalars == Adjustments{} && curveMaster.isNeutral() && curveRed.isNeutral() &&
           curveGreen.isNeutral() && curveBlue.isNeutral() && hueVsHue.isNeutral() &&
           hueVsSat.isNeutral() && hueVsLum.isNeutral();
}

glm::dvec3 whiteBalanceGains(double temperature, double tint) {
    const double t = sanitizeParam(temperature, -4.0, 4.0, 0.0);
    const double n = sanitizeParam(tint, -4.0, 4.0, 0.0);
    if (t == 0.0 && n == 0.0)
        return glm::dvec3(1.0);
    const glm::dvec3 g{lut::math::exp2(0.25 * t), lut::math::exp2(-0.25 * n),
                       lut::math::exp2(-0.25 * t)};
    return g / dot3(g, kLuma);
}

glm::dvec3 adjustWhiteBalance(glm::dvec3 e, double temperature, double tint) {
    return applyLinearGains(sanitize(e), whiteBalanceGains(temperature, tint));
}

glm::dvec3 adjustExposure(glm::dvec3 e, double stops) {
    const double s = sanitizeParam(stops, -32.0, 32.0, 0.0);
    return applyLinearGains(sanitize(e), glm::dvec3(lut::math::exp2(s)));
}

glm::dvec3 adjustContrast(glm::dvec3 e, double contrast) {
    e = sanitize(e);
    const double c = sanitizeParam(contrast, -1.0, 10.0, 0.0);
    if (c == 0.0)
        return e;
    return sanitize((e - 0.5) * (1.0 + c) + 0.5);
}

glm::dvec3 adjustLiftGammaGain(glm::dvec3 e, glm::dvec3 lift, glm::dvec3 gamma, glm::dvec3 gain) {
    e = sanitize(e);
    glm::dvec3 out;
    for (int c = 0; c < 3; ++c) {
        const double l = sanitizeParam(lift[c], -kMaxValue, kMaxValue, 0.0);
        const double g = clampedGamma(gamma[c]);
        const double k = sanitizeParam(gain[c], -kMaxValue, kMaxValue, 1.0);
        double v = e[c];
        if (l != 0.0 || k != 1.0)
            v = sanitize(k * (v + l * (1.0 - v)));
        if (g != 1.0)
            v = sanitize(spow(v, 1.0 / g));
        out[c] = v;
    }
    return out;
}

glm::dvec3 adjustSaturation(glm::dvec3 e, double saturation) {
    e = sanitize(e);
    const double s = sanitizeParam(saturation, -kMaxValue, kMaxValue, 1.0);
    if (s == 1.0)
        return e;
    const double y = dot3(e, kLuma);
    return sanitize(glm::dvec3(y) + s * (e - y));
}

glm::dvec3 adjustCurves(glm::dvec3 e, const Curve& master, const Curve& red, const Curve& green,
                        const Curve& blue) {
    e = sanitize(e);
    const Curve* own[3] = {&red, &green, &blue};
    const bool skipMaster = master.isNeutral();
    for (int c = 0; c < 3; ++c) {
        if (!skipMaster)
            e[c] = sanitize(master(e[c]));
        if (!own[c]->isNeutral())
            e[c] = sanitize((*own[c])(e[c]));
    }
    return e;
}

glm::dvec3 adjustHueCurves(glm::dvec3 e, const Curve& hueVsHue, const Curve& hueVsSat,
                           const Curve& hueVsLum) {
    e = sanitize(e);
    const HueChroma hc = hueChroma(e);
    if (!(hc.chroma > 0.0))
        return e; // a grey has no hue: hue curves leave it alone
    const double shift = hueVsHue.isNeutral() ? 0.0 : hueVsHue(hc.hue);
    if (shift != 0.0)
        e = sanitize(fromHueChroma(hc.hue + shift, hc.max, hc.chroma));
    const double sat = hueVsSat.isNeutral() ? 0.0 : hueVsSat(hc.hue);
    if (sat != 0.0) {
        const double y = dot3(e, kLuma);
        e = sanitize(glm::dvec3(y) + std::max(0.0, 1.0 + sat) * (e - y));
    }
    const double lum = hueVsLum.isNeutral() ? 0.0 : hueVsLum(hc.hue);
    if (lum != 0.0) {
        const double w = hc.chroma / std::max(hc.max, hc.chroma);
        e = sanitize(e * std::max(0.0, 1.0 + lum * w));
    }
    return e;
}

glm::dvec3 adjustStrength(glm::dvec3 input, glm::dvec3 e, double strength) {
    const double s = sanitizeParam(strength, 0.0, 2.0, 1.0);
    e = sanitize(e);
    if (s == 1.0)
        return e;
    return sanitize((1.0 - s) * sanitize(input) + s * e);
}

glm::dvec3 colorWheelOffset(double hueDegrees, double amount) {
    const double a = sanitizeParam(amount, -kMaxValue, kMaxValue, 0.0);
    const double h = std::isfinite(hueDegrees) ? hueDegrees : 0.0;
    if (a == 0.0)
        return glm::dvec3(0.0);
    const glm::dvec3 c = fromHueChroma(h, 1.0, 1.0); // the fully saturated colour of that hue
    const glm::dvec3 d = c - dot3(c, kLuma);
    const double m = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
    return d * (a / m);
}

glm::dvec3 adjustColor(glm::dvec3 e, const Adjustments& a) {
    e = sanitize(e);
    const double stops = sanitizeParam(a.exposure, -32.0, 32.0, 0.0);
    e = applyLinearGains(e, whiteBalanceGains(a.temperature, a.tint) * lut::math::exp2(stops));
    e = adjustContrast(e, a.contrast);
    e = adjustLiftGammaGain(e, glm::dvec3(a.liftMaster) + a.lift, a.gammaMaster * a.gamma,
                            a.gainMaster * a.gain);
    e = adjustSaturation(e, a.saturation);
    e = adjustCurves(e, a.curveMaster, a.curveRed, a.curveGreen, a.curveBlue);
    e = adjustHueCurves(e, a.hueVsHue, a.hueVsSat, a.hueVsLum);
    return e;
}

void applyAdjustments(const Lut3D& base, const Adjustments& a, Lut3D& dst, int nthreads) {
    if (&dst == &base)
        throw Error("applyAdjustments: destination may not alias the source");
    dst = base; // keeps size, domain, title and comments
    if (base.empty() || a.isNeutral())
        return;
    const auto& in = base.entries();
    auto& out = dst.entries();
    const int count = static_cast<int>(in.size());
    // Below a few thousand entries threads cost more than they save.
    const int n = base.size();
    const bool mixIdentity = sanitizeParam(a.strength, 0.0, 2.0, 1.0) != 1.0;
    parallelFor(count, count < 4096 ? 1 : nthreads, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            glm::dvec3 v = adjustColor(glm::dvec3(in[static_cast<std::size_t>(i)]), a);
            if (mixIdentity) {
                const glm::vec3 input = base.latticeInput(i % n, (i / n) % n, i / (n * n));
                v = adjustStrength(glm::dvec3(input), v, a.strength);
            }
            out[static_cast<std::size_t>(i)] = glm::vec3(v);
        }
    });
}

Lut3D applyAdjustments(const Lut3D& base, const Adjustments& a, int nthreads) {
    Lut3D out;
    applyAdjustments(base, a, out, nthreads);
    return out;
}

} // namespace lut
