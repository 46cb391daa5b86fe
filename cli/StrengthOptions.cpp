// SPDX-License-Identifier: Apache-2.0
#include "StrengthOptions.h"

#include "Vocabulary.h"

#include "lut/io/FileNames.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <sstream>

namespace lut::cli {

namespace {

// 0..2, NaN refused (CLI::Range lets NaN through: every comparison with it is false).
CLI::Validator amountRange() {
    return CLI::Validator(
        [](std::string& value) -> std::string {
            double v = 0;
            if (!CLI::detail::lexical_cast(value, v) || !(v >= 0.0 && v <= 2.0))
                return "Value " + value + " not in range 0 to 2";
            return {};
        },
        "FLOAT in [0 - 2]", "AMOUNT");
}

} // namespace

void addStrengthOptions(CLI::App& sub, StrengthOptions& t) {
    const std::string group = "Strength (the LUT blended with neutral)";
    sub.add_option("--strength", t.strength,
                   "how much of the LUT: 0 = neutral, 1 = the LUT (default), up to 2 "
                   "exaggerates; blended with neutral in lightness and chroma (Oklab)")
        ->check(amountRange())
        ->group(group);
    sub.add_option_function<double>(
           "--luma-strength", [&t](const double& v) { t.luma = v; },
           "the lightness part only (Oklab L; with --strength-blend reshade the RGB length, "
           "ReShade's \"LUT luma amount\"), 0..2 (default: --strength)")
        ->check(amountRange())
        ->group(group);
    sub.add_option_function<double>(
           "--chroma-strength", [&t](const double& v) { t.chroma = v; },
           "the colour part only (Oklab a, b; with --strength-blend reshade the RGB direction, "
           "ReShade's \"LUT chroma amount\"), 0..2 (default: --strength)")
        ->check(amountRange())
        ->group(group);
    sub.add_option_function<std::string>(
           "--strength-blend",
           [&t](const std::string& v) {
               t.blend = v == "reshade" ? StrengthBlend::ReShade : StrengthBlend::Oklab;
           },
           "how the strengths blend: oklab (default: lightness and chroma in a perceptual space) "
           "or reshade (as ReShade's LUT.fx sliders: the RGB vector's length and direction, for "
           "strips made for ReShade)")
        ->type_name("BLEND")
        ->check(choicesValidator(strengthBlendChoices()))
        ->group(group);
}

std::string strengthText(const StrengthOptions& options) {
    const StrengthAmounts a = strengthAmounts(options);
    if (a.luma == 1.0 && a.chroma == 1.0)
        return {};
    std::ostringstream s;
    if (a.luma == a.chroma)
        s << a.luma;
    else
        s << "luma " << a.luma << ", chroma " << a.chroma;
    s << (a.blend == StrengthBlend::ReShade
              ? " (blended with neutral as ReShade's LUT.fx: RGB length and direction)"
              : " (blended with neutral in Oklab)");
    return s.str();
}

Lut3D strengthLut(Lut3D lut, const std::string& name, const StrengthOptions& options,
                  const Verbosity& verbosity) {
    if (isFullStrength(options))
        return lut;
    if (verbosity.verbose)
        std::cerr << "lutkit: " << printable(name) << ": at strength " << strengthText(options)
                  << "\n";
    return applyStrength(lut, options);
}

} // namespace lut::cli
