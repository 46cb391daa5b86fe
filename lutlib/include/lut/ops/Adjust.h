// SPDX-License-Identifier: Apache-2.0
#pragma once
// LUT authoring operations: grading adjustments applied to the *entries* of a Lut3D (its output
// colours), so an edited LUT carries the edit with it when it is exported.
//
// The entries of a grading LUT are display-encoded colours (the Smash LUT holds gamma-space
// values, .cube grades for SDR do the same). The operations work in two spaces:
//
//   e   = entry value (encoded)
//   lin = spow(e, 2.2)                            decode with the pure 2.2 gamma the game uses
//   lin = lin * wb(temperature, tint)             white balance, luminance-preserving gains
//   lin = lin * 2^exposure                        exposure in stops
//   e   = spow(lin, 1/2.2)                        back to encoded
//   e   = (e - 0.5) * (1 + contrast) + 0.5        contrast about mid grey (encoded 0.5)
//   e   = spow(gain * (e + lift * (1 - e)), 1 / gamma)     lift/gamma/gain per channel
//   e   = Y + saturation * (e - Y),  Y = dot(e, Rec.709 luma weights)
//   e_c = curveC(curveMaster(e_c))                tone curves (lut/ops/Curve.h), c = R, G, B
//   hue curves, all read at the HSV hue h (degrees) of the colour entering this step:
//   e   = rotateHue(e, hueVsHue(h))               hue shift in degrees; keeps max and min channel
//   e   = Y + max(0, 1 + hueVsSat(h)) * (e - Y)   saturation by hue, luminance Y kept
//   e   = e * max(0, 1 + hueVsLum(h) * w)         luminance by hue, w = C / max(max channel, C)
//   out = (1 - strength) * in + strength * e      LUT strength (applyAdjustments only): mix with
//                                                 the identity, in = the entry's lattice input
//
// with spow(x, p) = sign(x) * |x|^p (odd extension, so negative entries stay defined) and
//   wb = (2^( 0.25 * temperature), 2^(-0.25 * tint), 2^(-0.25 * temperature)) / dot(that, luma),
// i.e. positive temperature is warmer (more red, less blue), positive tint is magenta (less
// green), and white's luminance is unchanged.
//
// Lift/gamma/gain is the Resolve-style form above (lift raises black and leaves white, gain
// scales, gamma bends the middle), per channel: a colour wheel sets the three channels of one
// of them, colorWheelOffset() turns a wheel position into channel values. Hue curves: HSV hue
// with 0 = red, 60 = yellow, 120 = green, 180 = cyan, 240 = blue, 300 = magenta; C = max - min
// channel, so greys (C = 0) are never changed by them and the change fades in with chroma.
// Strength 0 gives the identity LUT, 1 the graded LUT, values above 1 (up to 2) extrapolate
// (exaggerate the grade); it is clamped to [0, 2].
//
// Extreme values: NaN entries are treated as 0, infinities and magnitudes above
// limits::kMaxColorValue (65504) are clamped to it before and after; parameters are clamped to the
// ranges below (gamma to [0.01, 100], contrast to [-1, 10]), so output entries are always finite.
// Computation is in double precision; only the stored entries are float.
#include "lut/Lut3D.h"
#include "lut/ops/Curve.h"

#include <glm/vec3.hpp>

namespace lut {

struct Adjustments {
    double exposure = 0.0;    // stops, applied in linear light
    double contrast = 0.0;    // slope 1 + contrast about encoded 0.5; -1 = flat grey
    double saturation = 1.0;  // 0 = grey, 1 = unchanged
    double temperature = 0.0; // -1 (cool) .. +1 (warm); one unit = half a stop red vs blue
    double tint = 0.0;        // -1 (green) .. +1 (magenta)
    // Lift, gamma and gain: a master value combined with a per-channel value
    // (lift = liftMaster + lift[c], gamma = gammaMaster * gamma[c], gain = gainMaster * gain[c]).
    double liftMaster = 0.0;
    double gammaMaster = 1.0;
    double gainMaster = 1.0;
    glm::dvec3 lift{0.0};
    glm::dvec3 gamma{1.0};
    glm::dvec3 gain{1.0};
    // Tone curves on encoded values: master first, then the channel's own.
    Curve curveMaster{CurveKind::Tone};
    Curve curveRed{CurveKind::Tone};
    Curve curveGreen{CurveKind::Tone};
    Curve curveBlue{CurveKind::Tone};
    // Hue curves, y per hue: hue shift in degrees; saturation change (-1 = grey, 0 = unchanged,
    // 1 = double); luminance change (-1 = black at full chroma, 0 = unchanged, 1 = double).
    Curve hueVsHue{CurveKind::Hue};
    Curve hueVsSat{CurveKind::Hue};
    Curve hueVsLum{CurveKind::Hue};
    double strength = 1.0; // mix with the identity: 0 = neutral LUT, 1 = full grade, <= 2

    // True when applying these adjustments leaves every entry as it is (neutral curves, e.g.
    // points on the diagonal, count as neutral).
    bool isNeutral() const;
    bool operator==(const Adjustments&) const = default;
};

// Each operation on one encoded colour (NaN/Inf handled as described above).
glm::dvec3 adjustWhiteBalance(glm::dvec3 e, double temperature, double tint);
glm::dvec3 adjustExposure(glm::dvec3 e, double stops);
glm::dvec3 adjustContrast(glm::dvec3 e, double contrast);
glm::dvec3 adjustLiftGammaGain(glm::dvec3 e, glm::dvec3 lift, glm::dvec3 gamma, glm::dvec3 gain);
glm::dvec3 adjustSaturation(glm::dvec3 e, double saturation);
glm::dvec3 adjustCurves(glm::dvec3 e, const Curve& master, const Curve& red, const Curve& green,
                        const Curve& blue);
glm::dvec3 adjustHueCurves(glm::dvec3 e, const Curve& hueVsHue, const Curve& hueVsSat,
                           const Curve& hueVsLum);
// (1 - strength) * input + strength * e, strength clamped to [0, 2] (NaN = 1).
glm::dvec3 adjustStrength(glm::dvec3 input, glm::dvec3 e, double strength);

// A colour wheel position as per-channel values that leave luminance unchanged: the direction
// of HSV hue `hueDegrees` in the plane of zero luma change, scaled so the channel moving most
// moves by `amount` (e.g. lift = liftMaster + colorWheelOffset(h, 0.05)).
glm::dvec3 colorWheelOffset(double hueDegrees, double amount);

// The white-balance gains in linear light for (temperature, tint).
glm::dvec3 whiteBalanceGains(double temperature, double tint);

// All adjustments in the documented order, on one encoded colour (strength excepted: it needs
// the lattice input, see applyAdjustments).
glm::dvec3 adjustColor(glm::dvec3 e, const Adjustments& a);

// A copy of `base` (same size, domain, title, comments) whose entries went through
// adjustColor and then adjustStrength with the entry's lattice input. Runs on up to nthreads
// threads (0 = all cores).
Lut3D applyAdjustments(const Lut3D& base, const Adjustments& a, int nthreads = 0);
// The same, writing into dst (resized/overwritten as needed; may not alias base).
void applyAdjustments(const Lut3D& base, const Adjustments& a, Lut3D& dst, int nthreads = 0);

} // namespace lut
