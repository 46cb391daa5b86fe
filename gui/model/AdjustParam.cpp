#include "AdjustParam.h"

#include "lut/Error.h"

#include <algorithm>
#include <cmath>

namespace lut::gui {

const std::vector<AdjustParamInfo>& adjustParams() {
    using P = AdjustParam;
    static const std::vector<AdjustParamInfo> params = {
        {P::Exposure, "exposure", "Exposure (stops)", "Tone", -5.0, 5.0, 0.0, 2, false},
        {P::Contrast, "contrast", "Contrast", "Tone", -1.0, 1.0, 0.0, 2, false},
        {P::Saturation, "saturation", "Saturation", "Tone", 0.0, 3.0, 1.0, 2, false},
        {P::Temperature, "temperature", "Temperature", "White balance", -1.0, 1.0, 0.0, 2, false},
        {P::Tint, "tint", "Tint", "White balance", -1.0, 1.0, 0.0, 2, false},
        {P::LiftMaster, "lift", "Lift", "Lift", -0.5, 0.5, 0.0, 3, false},
        {P::LiftR, "lift.r", "Lift R", "Lift", -0.5, 0.5, 0.0, 3, false},
        {P::LiftG, "lift.g", "Lift G", "Lift", -0.5, 0.5, 0.0, 3, false},
        {P::LiftB, "lift.b", "Lift B", "Lift", -0.5, 0.5, 0.0, 3, false},
        {P::GammaMaster, "gamma", "Gamma", "Gamma", 0.25, 4.0, 1.0, 3, true},
        {P::GammaR, "gamma.r", "Gamma R", "Gamma", 0.25, 4.0, 1.0, 3, true},
        {P::GammaG, "gamma.g", "Gamma G", "Gamma", 0.25, 4.0, 1.0, 3, true},
        {P::GammaB, "gamma.b", "Gamma B", "Gamma", 0.25, 4.0, 1.0, 3, true},
        {P::GainMaster, "gain", "Gain", "Gain", 0.25, 4.0, 1.0, 3, true},
        {P::GainR, "gain.r", "Gain R", "Gain", 0.25, 4.0, 1.0, 3, true},
        {P::GainG, "gain.g", "Gain G", "Gain", 0.25, 4.0, 1.0, 3, true},
        {P::GainB, "gain.b", "Gain B", "Gain", 0.25, 4.0, 1.0, 3, true},
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
    }
}

int paramToSlider(const AdjustParamInfo& info, double value, int steps) {
    if (!std::isfinite(value))
        value = info.defaultValue;
    value = std::clamp(value, info.min, info.max);
    double t = info.logScale ? std::log(value / info.min) / std::log(info.max / info.min)
                             : (value - info.min) / (info.max - info.min);
    return static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * steps));
}

double sliderToParam(const AdjustParamInfo& info, int position, int steps) {
    const double t = std::clamp(static_cast<double>(position) / std::max(steps, 1), 0.0, 1.0);
    double v = info.logScale ? info.min * std::pow(info.max / info.min, t)
                             : info.min + t * (info.max - info.min);
    // The default's own position gives the default exactly, so a slider can return to neutral.
    if (position == paramToSlider(info, info.defaultValue, steps))
        return info.defaultValue;
    const double scale = std::pow(10.0, info.decimals + 1);
    return std::clamp(std::round(v * scale) / scale, info.min, info.max);
}

} // namespace lut::gui
