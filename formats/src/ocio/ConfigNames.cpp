// SPDX-License-Identifier: Apache-2.0
// What the active config names, for the shells' completion (`lutkit --names KIND`) and for the
// colour spaces a warning suggests (lut/formats/ColorConfig.h: configNames, spacesHolding).
#include "lut/formats/ColorConfig.h"

#include <algorithm>
#include <cmath>

namespace lut::formats {

namespace {

void addOnce(std::vector<std::string>& out, const std::string& name) {
    if (!name.empty() && std::find(out.begin(), out.end(), name) == out.end())
        out.push_back(name);
}

} // namespace

std::vector<std::string> configNames(const std::string& kind, const std::string& given) {
    const ColorConfig config = ColorConfig::load(given);
    std::vector<std::string> out;
    if (kind == "spaces") {
        const auto spaces = config.colorSpaces();
        for (const auto& s : spaces)
            addOnce(out, s);
        for (const auto& s : spaces)
            for (const auto& a : config.info(s).aliases)
                addOnce(out, a);
        for (const auto& r : config.roles())
            addOnce(out, r);
    } else if (kind == "looks") {
        out = config.looks();
    } else if (kind == "displays") {
        out = config.displays();
    } else if (kind == "views") {
        for (const auto& d : config.displays())
            for (const auto& v : config.views(d))
                addOnce(out, v);
    } else if (kind.rfind("views:", 0) == 0) {
        const std::string display = kind.substr(6);
        const auto displays = config.displays();
        if (std::find(displays.begin(), displays.end(), display) != displays.end())
            out = config.views(display);
    } else {
        throw Error("unknown kind of names '" + kind +
                    "' (spaces, looks, displays, views or views:DISPLAY)");
    }
    return out;
}

std::vector<std::string> spacesHolding(float value, const std::string& given) {
    std::vector<std::string> reaching, linear;
    if (std::isnan(value) || (value >= 0.0f && value <= 1.0f))
        return reaching;
    const ColorConfig config = ColorConfig::load(given);
    for (const auto& name : config.colorSpaces()) {
        const ColorSpaceInfo info = config.info(name);
        if (!info.isHdrLinear())
            continue;
        linear.push_back(name);
        // An lg2 allocation [min, max] in stops: the space's values reach 2^max.
        if (value > 1.0f && info.lg2Allocation && info.allocationVars.size() >= 2 &&
            static_cast<double>(value) > std::exp2(static_cast<double>(info.allocationVars[1])))
            continue;
        reaching.push_back(name);
    }
    return reaching.empty() ? linear : reaching;
}

} // namespace lut::formats
