// SPDX-License-Identifier: Apache-2.0
// OpenColorIO processors as pixel steps, and the conversions around a LUT.
#include "lut/formats/ColorTransform.h"

#include "ocio/ColorConfigImpl.h"
#include "ocio/OcioFacts.h"
#include "ocio/OcioStructure.h"

#include "lut/interp/Sampler.h"

namespace lut::formats {

struct ColorTransform::Impl {
    OCIO::ConstCPUProcessorRcPtr rgba; // F32 RGBA packed, OCIO's default optimisation (speed)
    OCIO::ConstCPUProcessorRcPtr rgb;  // lossless optimisation (baking, measuring)
    bool noOp = false;
    bool crosstalk = false;
    std::string description;
};

namespace {

std::shared_ptr<ColorTransform::Impl> build(const ColorConfig& config,
                                            const OCIO::ConstTransformRcPtr& transform,
                                            std::string description) {
    const auto& cfg = config.impl().config;
    OcioSession session(config.location().path);
    auto impl = std::make_shared<ColorTransform::Impl>();
    try {
        const auto processor = cfg->getProcessor(transform);
        impl->rgba = processor->getOptimizedCPUProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                                         OCIO::OPTIMIZATION_DEFAULT);
        impl->rgb = faithfulCpu(processor); // what bake samples: unoptimised (OcioFacts.h)
        impl->noOp = impl->rgba->isNoOp() && impl->rgb->isNoOp();
        impl->crosstalk = impl->rgba->hasChannelCrosstalk();
    } catch (const std::exception& e) {
        throw Error(config.location().path + ": OpenColorIO cannot build the conversion " +
                    description + ": " + ocioMessage(e.what()));
    }
    impl->description = std::move(description);
    return impl;
}

} // namespace

std::shared_ptr<const ColorTransform> ColorTransform::convert(const ColorConfig& config,
                                                              const std::string& from,
                                                              const std::string& to,
                                                              const std::string& looks) {
    const std::string src = config.colorSpace(from), dst = config.colorSpace(to);
    std::string what = src + " -> " + dst;
    OCIO::ConstTransformRcPtr t;
    if (!looks.empty()) {
        config.checkLooks(looks);
        auto lt = OCIO::LookTransform::Create();
        lt->setSrc(src.c_str());
        lt->setDst(dst.c_str());
        lt->setLooks(looks.c_str());
        t = lt;
        what += " (look " + looks + ")";
    } else {
        auto ct = OCIO::ColorSpaceTransform::Create();
        ct->setSrc(src.c_str());
        ct->setDst(dst.c_str());
        t = ct;
    }
    auto out = std::shared_ptr<ColorTransform>(new ColorTransform);
    out->m_impl = build(config, t, what);
    return out;
}

std::shared_ptr<const ColorTransform> ColorTransform::toDisplay(const ColorConfig& config,
                                                                const std::string& from,
                                                                const std::string& display,
                                                                const std::string& view,
                                                                const std::string& looks) {
    const std::string src = config.colorSpace(from);
    config.checkDisplayView(display, view);
    std::string what = src + " -> " + display + " / " + view;
    OCIO::ConstTransformRcPtr t;
    auto dv = OCIO::DisplayViewTransform::Create();
    dv->setSrc(src.c_str());
    dv->setDisplay(display.c_str());
    dv->setView(view.c_str());
    if (!looks.empty()) {
        config.checkLooks(looks);
        // The looks go first, in the source space's terms, as ocioconvert's LegacyViewingPipeline.
        auto group = OCIO::GroupTransform::Create();
        auto lt = OCIO::LookTransform::Create();
        lt->setSrc(src.c_str());
        lt->setDst(src.c_str());
        lt->setLooks(looks.c_str());
        group->appendTransform(lt);
        group->appendTransform(dv);
        t = group;
        what += " (look " + looks + ")";
    } else {
        t = dv;
    }
    auto out = std::shared_ptr<ColorTransform>(new ColorTransform);
    out->m_impl = build(config, t, what);
    return out;
}

void ColorTransform::processPixels(float* rgba, std::size_t count) const {
    if (m_impl->noOp || count == 0)
        return;
    applyRgba(m_impl->rgba, rgba, count);
}

void ColorTransform::processRgb(float* rgb, std::size_t count) const {
    if (m_impl->noOp || count == 0)
        return;
    OCIO::PackedImageDesc desc(rgb, static_cast<long>(count), 1, 3);
    m_impl->rgb->apply(desc);
}

bool ColorTransform::isNoOp() const {
    return m_impl->noOp;
}

bool ColorTransform::hasChannelCrosstalk() const {
    return m_impl->crosstalk;
}

const std::string& ColorTransform::description() const {
    return m_impl->description;
}

bool ColorSpec::any() const {
    return !config.empty() || !from.empty() || !lutSpace.empty() || !lutOutputSpace.empty() ||
           !to.empty() || !looks.empty() || !display.empty() || !view.empty();
}

std::string ColorPlan::describe() const {
    std::string s = "colour: ";
    s += before ? before->description() + ", " : "";
    s += "LUT";
    s += after ? ", " + after->description() : "";
    return s + " (config " + config.describe() + ")";
}

ColorPlan planColor(const ColorSpec& spec) {
    ColorPlan plan;
    if (!spec.any())
        return plan;
    if (!spec.to.empty() && (!spec.display.empty() || !spec.view.empty()))
        throw ColorOptionError("--to and --display/--view both name the output: give one");
    const bool needsFrom = !spec.lutSpace.empty() || !spec.looks.empty();
    if (needsFrom && spec.from.empty())
        throw ColorOptionError(std::string(spec.looks.empty() ? "--lut-space" : "--look") +
                               " needs --from (the input image's colour space)");
    const ColorConfig config = ColorConfig::load(spec.config);
    plan.config = config.location();
    plan.diagnostics = config.diagnostics();
    const std::string from = spec.from.empty() ? std::string() : config.colorSpace(spec.from);
    plan.lutInputSpace = spec.lutSpace.empty() ? from : config.colorSpace(spec.lutSpace);
    plan.lutOutputSpace =
        spec.lutOutputSpace.empty() ? plan.lutInputSpace : config.colorSpace(spec.lutOutputSpace);
    if (plan.lutOutputSpace.empty() &&
        (!spec.to.empty() || !spec.display.empty() || !spec.view.empty()))
        throw ColorOptionError("--to/--display need the space the LUT's output is in: give "
                               "--from (and --lut-space or --lut-output-space when the LUT works "
                               "in another space)");
    if (!from.empty() && (from != plan.lutInputSpace || !spec.looks.empty()))
        plan.before = ColorTransform::convert(config, from, plan.lutInputSpace, spec.looks);
    if (!spec.display.empty() || !spec.view.empty()) {
        const std::string display = spec.display.empty() ? config.defaultDisplay() : spec.display;
        const std::string view = spec.view.empty() ? config.defaultView(display) : spec.view;
        plan.after = ColorTransform::toDisplay(config, plan.lutOutputSpace, display, view);
    } else if (!spec.to.empty()) {
        const std::string to = config.colorSpace(spec.to);
        if (to != plan.lutOutputSpace)
            plan.after = ColorTransform::convert(config, plan.lutOutputSpace, to);
    }
    if (plan.before && plan.before->isNoOp())
        plan.before.reset();
    if (plan.after && plan.after->isNoOp())
        plan.after.reset();
    return plan;
}

ColorPlan planPreviewColor(const ColorSpec& spec) {
    ColorPlan plan;
    if (!spec.any())
        return plan;
    if (!spec.lutSpace.empty() || !spec.lutOutputSpace.empty() || !spec.display.empty() ||
        !spec.view.empty())
        throw ColorOptionError("lutkit preview takes --from, --look and --to: its LUT works on "
                               "the game's sRGB display values");
    if (!spec.looks.empty() && spec.from.empty())
        throw ColorOptionError("--look needs --from (the input image's colour space)");
    const ColorConfig config = ColorConfig::load(spec.config);
    plan.config = config.location();
    plan.diagnostics = config.diagnostics();
    const std::string srgb = config.srgbSpace();
    plan.lutInputSpace = plan.lutOutputSpace = srgb;
    if (!spec.from.empty())
        plan.before = ColorTransform::convert(config, spec.from, srgb, spec.looks);
    if (!spec.to.empty() && config.colorSpace(spec.to) != srgb)
        plan.after = ColorTransform::convert(config, srgb, spec.to);
    return plan;
}

PixelChain lutPixelChain(const ColorPlan& plan, const Lut3D& lut, Interpolation interp) {
    LutFile file;
    file.cube = lut;
    return lutPixelChain(plan, file, interp);
}

PixelChain lutPixelChain(const ColorPlan& plan, const LutFile& file, Interpolation interp) {
    PixelChain chain;
    if (plan.before)
        chain.addBefore(
            "colour: " + plan.lutInputSpace,
            [t = plan.before](float* rgba, std::size_t n) { t->processPixels(rgba, n); });
    chain.setLut(file, interp);
    if (plan.after)
        chain.addAfter("colour: out of " + plan.lutOutputSpace,
                       [t = plan.after](float* rgba, std::size_t n) { t->processPixels(rgba, n); });
    return chain;
}

} // namespace lut::formats
