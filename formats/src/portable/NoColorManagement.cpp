// SPDX-License-Identifier: Apache-2.0
// The portable editions (docs/portable.md) have no OpenColorIO: colour management (--config,
// --from, --to, --display, --view, --look), the config's names and `bake` are refused with one
// line naming the edition. Without colour options, apply and preview run the LUT alone, as the
// Linux build does (the plan is empty: formats/src/ocio/ColorTransform.cpp).
#include "lut/formats/Bake.h"
#include "lut/formats/ColorConfig.h"
#include "lut/formats/ColorTransform.h"
#include "lut/formats/Edition.h"
#include "lut/formats/LibraryMessages.h"

namespace lut::formats {

namespace {

[[noreturn]] void refuse(const std::string& what) {
    throw ColorOptionError(notInEdition(what, "OpenColorIO", "convert in another program first"));
}

} // namespace

std::string ConfigLocation::describe() const {
    return path;
}

std::string shippedConfigPath() {
    return {};
}

ConfigLocation locateConfig(const std::string&) {
    refuse("colour management (an OpenColorIO config)");
}

ColorOptionError::ColorOptionError(const std::string& message, std::string kind, std::string value,
                                   std::vector<std::string> known)
    : Error(message), m_kind(std::move(kind)), m_value(std::move(value)),
      m_known(std::move(known)) {}

bool ColorSpaceInfo::isHdrLinear() const {
    return false;
}

ColorConfig ColorConfig::load(const ConfigLocation&) {
    refuse("colour management (an OpenColorIO config)");
}

std::vector<std::string> configNames(const std::string&, const std::string&) {
    refuse("colour management (an OpenColorIO config)");
}

std::vector<std::string> spacesHolding(float, const std::string&) {
    refuse("colour management (an OpenColorIO config)");
}

bool ColorSpec::any() const {
    return !config.empty() || !from.empty() || !lutSpace.empty() || !lutOutputSpace.empty() ||
           !to.empty() || !looks.empty() || !display.empty() || !view.empty();
}

std::string ColorPlan::describe() const {
    return "colour: LUT";
}

ColorPlan planColor(const ColorSpec& spec) {
    if (spec.any())
        refuse("colour management (--config, --from, --to, --display, --view, --look)");
    return {};
}

ColorPlan planPreviewColor(const ColorSpec& spec) {
    return planColor(spec);
}

PixelChain lutPixelChain(const ColorPlan&, const Lut3D& lut, Interpolation interp) {
    LutFile file;
    file.cube = lut;
    return lutPixelChain(ColorPlan{}, file, interp);
}

PixelChain lutPixelChain(const ColorPlan&, const LutFile& file, Interpolation interp) {
    PixelChain chain;
    chain.setLut(file, interp);
    return chain;
}

BakeReport bake(const std::string&, const BakeOptions&) {
    throw Error(notInEdition("lutkit bake", "OpenColorIO"));
}

void captureLibraryMessages() {}

} // namespace lut::formats
