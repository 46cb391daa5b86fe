// SPDX-License-Identifier: Apache-2.0
#pragma once
// The editable adjustment parameters as data: one id per number in lut::Adjustments (the curves
// and colour wheels edit the same struct through their own widgets), with the label, range and
// default the editor's sliders use. Plain C++ (no Qt).
#include "lut/ops/Adjust.h"

#include <string>
#include <vector>

namespace lut::gui {

enum class AdjustParam {
    Exposure,
    Contrast,
    Saturation,
    Temperature,
    Tint,
    LiftMaster,
    LiftR,
    LiftG,
    LiftB,
    GammaMaster,
    GammaR,
    GammaG,
    GammaB,
    GainMaster,
    GainR,
    GainG,
    GainB,
    Strength,
};

struct AdjustParamInfo {
    AdjustParam id;
    std::string key;   // stable name for settings and logs: "exposure", "lift.r", ...
    std::string label; // what the editor shows
    std::string group; // "Tone", "White balance", "Lift", "Gamma", "Gain"
    double min;        // what a spin box, a script or the command line accepts
    double max;
    double defaultValue;
    int decimals;
    bool logScale;    // slider moves in log space (gamma, gain multipliers)
    double sliderMin; // the slider's span: the useful range, so a pixel is a fine step;
    double sliderMax; // typed values beyond it are kept (the slider then sits at its end)
};

// Every parameter, in the order the editor shows them.
const std::vector<AdjustParamInfo>& adjustParams();
const AdjustParamInfo& adjustParamInfo(AdjustParam id);

double getParam(const Adjustments& a, AdjustParam id);
void setParam(Adjustments& a, AdjustParam id, double value);

// Slider position (0..steps) <-> value over the slider's span, linear or logarithmic per
// parameter; values are clamped to the span.
int paramToSlider(const AdjustParamInfo& info, double value, int steps);
double sliderToParam(const AdjustParamInfo& info, int position, int steps);

} // namespace lut::gui
