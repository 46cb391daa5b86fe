// SPDX-License-Identifier: Apache-2.0
#pragma once
// OpenColorIO conversions as pixel steps (lut/PixelProcessor.h), and the plan `lutkit apply`,
// `convert` and `preview` follow: the LUT runs in the colour space it was made for, with OCIO's
// CPU processor (optimised, float RGBA, used from every worker thread at once) converting the
// image into that space before it and out of it after it.
//
//   image (--from) --[--look]--> LUT input (--lut-space) --LUT--> LUT output (--lut-output-space)
//                   --> --to, or the (--display, --view) pair
//
// Every colour space may be a name, an alias or a role of the config (lut/formats/ColorConfig.h).
#include "lut/Lut3D.h"
#include "lut/PixelProcessor.h"
#include "lut/formats/ColorConfig.h"
#include "lut/interp/Interpolation.h"
#include "lut/interp/PixelChain.h"

#include <cstddef>
#include <memory>
#include <string>

namespace lut::formats {

class ColorTransform final : public PixelProcessor {
public:
    // from -> to, through the looks when given (OCIO's LookTransform; "" = a plain conversion).
    static std::shared_ptr<const ColorTransform> convert(const ColorConfig& config,
                                                         const std::string& from,
                                                         const std::string& to,
                                                         const std::string& looks = {});
    // from -> a display's view (OCIO's DisplayViewTransform, as ocioconvert --view).
    static std::shared_ptr<const ColorTransform>
    toDisplay(const ColorConfig& config, const std::string& from, const std::string& display,
              const std::string& view, const std::string& looks = {});

    // Images: OCIO's default optimisation (fast; it may approximate inverted tables).
    void processPixels(float* rgba, std::size_t count) const override;
    // Packed RGB with the lossless optimisation: what bakes sample and measure against.
    void processRgb(float* rgb, std::size_t count) const;
    bool isNoOp() const;
    bool hasChannelCrosstalk() const;
    // "ACEScg -> sRGB", "ACEScct -> sRGB / Standard (look Punchy)"
    const std::string& description() const;

    struct Impl; // formats/src/ocio: the OCIO processors
    const Impl& impl() const { return *m_impl; }

private:
    std::shared_ptr<const Impl> m_impl;
};

// What the colour options ask for (all empty = no colour management).
struct ColorSpec {
    std::string config;         // --config ("" = $OCIO, else lutkit's own)
    std::string from;           // the input image's colour space
    std::string lutSpace;       // the space the LUT takes its input in ("" = from)
    std::string lutOutputSpace; // the space of the LUT's output ("" = lutSpace)
    std::string to;             // the output's colour space ("" = the LUT's output space)
    std::string looks;          // applied between from and lutSpace
    std::string display, view;  // instead of to: a display's view (either may be "": default)

    bool any() const;
};

struct ColorPlan {
    ConfigLocation config;
    std::string lutInputSpace, lutOutputSpace;    // resolved names ("" without a colour spec)
    std::shared_ptr<const ColorTransform> before; // image -> LUT input; null = nothing to do
    std::shared_ptr<const ColorTransform> after;  // LUT output -> output; null = nothing to do
    Diagnostics diagnostics;                      // what OCIO logged loading the config
    // "colour: ACEScg -> ACEScct, LUT, ACEScct -> sRGB (config .../config.ocio (lutkit's own))"
    std::string describe() const;
};

// Resolves every name against the config and builds the two conversions. Throws
// ColorOptionError for unknown names or options that do not go together (--to with --display,
// --lut-space without --from), lut::Error when the config cannot be read.
ColorPlan planColor(const ColorSpec& spec);

// What lutkit preview does with the colour options: its frames are sRGB-encoded (screenshots) or
// linear sRGB (EXR scenes), so `before` converts --from (with --look) to the config's sRGB space
// (ColorConfig::srgbSpace; values above 1 stay), and `after` converts the preview's
// display-encoded sRGB to --to. --lut-space, --lut-output-space, --display and --view are refused.
ColorPlan planPreviewColor(const ColorSpec& spec);

// The chain `lutkit apply` runs on every chunk of pixels (lut/interp/PixelChain.h): the conversion
// into the LUT's space (a step before the LUT), the LUT (whose domain the chain watches: values
// outside it are counted, since the sampler clamps them), the conversion out (a step after it).
PixelChain lutPixelChain(const ColorPlan& plan, const Lut3D& lut, Interpolation interp);
// The same for a LUT file as it is meant to be applied: its 1D shaper, then its table, exactly.
PixelChain lutPixelChain(const ColorPlan& plan, const LutFile& file, Interpolation interp);

} // namespace lut::formats
