// SPDX-License-Identifier: Apache-2.0
#include "AdjustParam.h"

#include "lut/Error.h"

#include <algorithm>
#include <cmath>

namespace lut::gui {

const std::vector<AdjustParamInfo>& adjustParams() {
    using P = AdjustParam;
    // Exposure: ±10 stops typed, the slider spans ±3 (~0.02 stop per pixel on a 300-pixel
    // slider, a tenth of that with Shift held).
    static const std::vector<AdjustParamInfo> params = {
        {P::Exposure, "exposure", "Exposure (stops)", "Tone", -10.0, 10.0, 0.0, 3, false, -3.0,
         3.0},
        {P::Contrast, "contrast", "Contrast", "Tone", -1.0, 1.0, 0.0, 3, false, -1.0, 1.0},
        {P::Saturation, "saturation", "Saturation", "Tone", 0.0, 3.0, 1.0, 3, false, 0.0, 2.0},
        {P::Temperature, "temperature", "Temperature", "White balance", -1.0, 1.0, 0.0, 3, false,
         -1.0, 1.0},
        {P::Tint, "tint", "Tint", "White balance", -1.0, 1.0, 0.0, 3, false, -1.0, 1.0},
        {P::LiftMaster, "lift", "Lift", "Lift", -0.5, 0.5, 0.0, 3, false, -0.25, 0.25},
        {P::LiftR, "lift.r", "Lift R", "Lift", -0.5, 0.5, 0.0, 3, false, -0.25, 0.25},
        {P::LiftG, "lift.g", "Lift G", "Lift", -0.5, 0.5, 0.0, 3, false, -0.25, 0.25},
        {P::LiftB, "lift.b", "Lift B", "Lift", -0.5, 0.5, 0.0, 3, false, -0.25, 0.25},
        {P::GammaMaster, "gamma", "Gamma", "Gamma", 0.25, 4.0, 1.0, 3, true, 0.5, 2.0},
        {P::GammaR, "gamma.r", "Gamma R", "Gamma", 0.25, 4.0, 1.0, 3, true, 0.5, 2.0},
        {P::GammaG, "gamma.g", "Gamma G", "Gamma", 0.25, 4.0, 1.0, 3, true, 0.5, 2.0},
        {P::GammaB, "gamma.b", "Gamma B", "Gamma", 0.25, 4.0, 1.0, 3, true, 0.5, 2.0},
        {P::GainMaster, "gain", "Gain", "Gain", 0.25, 4.0, 1.0, 3, true, 0.5, 2.0},
        {P::GainR, "gain.r", "Gain R", "Gain", 0.25, 4.0, 1.0, 3, true, 0.5, 2.0},
        {P::GainG, "gain.g", "Gain G", "Gain", 0.25, 4.0, 1.0, 3, true, 0.5, 2.0},
        {P::GainB, "gain.b", "Gain B", "Gain", 0.25, 4.0, 1.0, 3, true, 0.5, 2.0},
        {P::Strength, "strength", "LUT strength", "Strength", 0.0, 2.0, 1.0, 3, false, 0.0, 2.0},
    };
    return params;
}

const AdjustParamInfo& adjustParamInfo(AdjustParam id) {
    for (const auto& p : adjustParams())
        if (p.id == id)
            return p;
    throw Error("unknown adjustment parameter");
}

double getParam(const Adjustments& a, AdjustParam id) {
    using P = AdjustParam;
    switch (id) {
    case P::Exposure:
        return a.exposure;
    case P::Contrast:
        return a.contrast;
    case P::Saturation:
        return a.saturation;
    case P::Temperature:
        return a.temperature;
    case P::Tint:
        return a.tint;
    case P::LiftMaster:
        return a.liftMaster;
    case P::LiftR:
        return a.lift.x;
    case P::LiftG:
        return a.lift.y;
    case P::LiftB:
        return a.lift.z;
    case P::GammaMaster:
        return a.gammaMaster;
    case P::GammaR:
        return a.gamma.x;
    case P::GammaG:
        return a.gamma.y;
    case P::GammaB:
        return a.gamma.z;
    case P::GainMaster:
        return a.gainMaster;
    case P::GainR:
        return a.gain.x;
    case P::GainG:
        return a.gain.y;
    case P::GainB:
        return a.gain.z;
    case P::Strength:
        return a.strength;
    }
    return 0.0;
}

void setParam(Adjustments& a, AdjustParam id, double v) {
    using P = AdjustParam;
    switch (id) {
    case P::Exposure:
        a.exposure = v;
        break;
    case P::Contrast:
        a.contrast = v;
        break;
    case P::Saturation:
        a.saturation = v;
        break;
    case P::Temperature:
        a.temperature = v;
        break;
    case P::Tint:
        a.tint = v;
        break;
    case P::LiftMaster:
        a.liftMaster = v;
        break;
    case P::LiftR:
        a.lift.x = v;
        break;
    case P::LiftG:
        a.lift.y = v;
        break;
    case P::LiftB:
        a.lift.z = v;
        break;
    case P::GammaMaster:
        a.gammaMaster = v;
        break;
    case P::GammaR:
        a.gamma.x = v;
        break;
    case P::GammaG:
        a.gamma.y = v;
        break;
    case P::GammaB:
        a.gamma.z = v;
        break;
    case P::GainMaster:
        a.gainMaster = v;
        break;
    case P::GainR:
        a.gain.x = v;
        break;
    case P::GainG:
        a.gain.y = v;
        break;
    case P::GainB:
        a.gain.z = v;
        break;
    case P::Strength:
        a.strength = v;
        break;
    }
}

int paramToSlider(const AdjustParamInfo& info, double value, int steps) {
    if (!std::isfinite(value))
        value = info.defaultValue;
    const double lo = info.sliderMin, hi = info.sliderMax;
    value = std::clamp(value, lo, hi);
    double t = info.logScale ? std::log(value / lo) / std::log(hi / lo) : (value - lo) / (hi - lo);
    return static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * steps));
}

double sliderToParam(const AdjustParamInfo& info, int position, int steps) {
    const double lo = info.sliderMin, hi = info.sliderMax;
    const double t = std::clamp(static_cast<double>(position) / std::max(steps, 1), 0.0, 1.0);
    double v = info.logScale ? lo * std::pow(hi / lo, t) : lo + t * (hi - lo);
    // The default's own position gives the default exactly, so a slider can return to neutral.
    if (position == paramToSlider(info, info.defaultValue, steps))
        return info.defaultValue;
    const double scale = std::pow(10.0, info.decimals + 1);
    return std::clamp(std::round(v * scale) / scale, lo, hi);
}

} // namespace lut::gui
