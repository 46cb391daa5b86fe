// SPDX-License-Identifier: Apache-2.0
#pragma once
// OpenColorIO configs for lutkit's colour management (apply, convert, preview and bake with
// --config/--from/--to/--look/--display/--view, named as ocioconvert and ociobakelut name them).
//
// Which config: --config FILE, else the one $OCIO names, else lutkit's own (share/lutkit/ocio/
// config.ocio, installed with the program and copied into the build tree; docs/colour.md lists its
// spaces: linear Rec.709, sRGB and Rec.709 displays, ACEScg, ACEScct, ACES2065-1, CIE XYZ, a log2
// shaper, Raw). OpenColorIO 2.1 has no built-in configs, hence our own.
//
// Names are checked here, with the config's own lists, so a misspelt colour space is one line
// naming the config and the names it has (ColorOptionError: bad usage, exit 2 in lutkit).
#include "lut/Error.h"

#include <memory>
#include <string>
#include <vector>

namespace lut::formats {

enum class ConfigSource { Option, Environment, Shipped };

struct ConfigLocation {
    std::string path;
    ConfigSource source = ConfigSource::Shipped;
    // "config.ocio (--config)", "/studio/config.ocio ($OCIO)", ".../lutkit/ocio/config.ocio
    // (lutkit's own)"
    std::string describe() const;
};

// lutkit's own config: <executable>/../share/lutkit/ocio/config.ocio (installed, or the build
// tree's copy), else the install prefix's; "" when none exists.
std::string shippedConfigPath();

// given (--config) if not empty, else $OCIO if set and not empty, else shippedConfigPath().
// Throws lut::Error when there is none.
ConfigLocation locateConfig(const std::string& given = {});

// A colour-management option that names something the config does not have (a colour space,
// look, display or view), or options that do not go together: bad usage. `known` lists what the
// config has, for "did you mean".
class ColorOptionError : public Error {
public:
    ColorOptionError(const std::string& message, std::string kind = {}, std::string value = {},
                     std::vector<std::string> known = {});
    const std::string& kind() const { return m_kind; } // "colour space", "look", ...
    const std::string& value() const { return m_value; }
    const std::vector<std::string>& known() const { return m_known; }

private:
    std::string m_kind, m_value;
    std::vector<std::string> m_known;
};

struct ColorSpaceInfo {
    std::string name;
    std::vector<std::string> aliases;
    std::string family;
    std::string encoding; // "scene-linear", "log", "sdr-video", "hdr-video", "data" or ""
    std::string description;
    bool isData = false;
    // Allocation "lg2" with its variables [min, max(, offset)] in stops: the range a linear space
    // uses (what ociobakelut's shaper follows).
    bool lg2Allocation = false;
    std::vector<float> allocationVars;

    // Scene-linear or lg2-allocated: values above 1 are usual, a shaper is needed to bake it.
    bool isHdrLinear() const;
};

class ColorConfig {
public:
    // Throws lut::Error naming the file when OpenColorIO cannot load it.
    static ColorConfig load(const ConfigLocation& location);
    static ColorConfig load(const std::string& given = {}) { return load(locateConfig(given)); }

    const ConfigLocation& location() const;
    std::vector<std::string> colorSpaces() const;
    std::vector<std::string> roles() const;
    std::vector<std::string> displays() const;
    std::vector<std::string> views(const std::string& display) const;
    std::vector<std::string> looks() const;
    std::string defaultDisplay() const;
    std::string defaultView(const std::string& display) const;

    // The colour space a name, alias or role stands for. Throws ColorOptionError.
    std::string colorSpace(const std::string& nameAliasOrRole) const;
    ColorSpaceInfo info(const std::string& nameAliasOrRole) const;
    // The config's sRGB-encoded colour space: the first of "sRGB - Texture", "srgb_tx",
    // "Utility - sRGB - Texture", "sRGB", "srgb" it has (lutkit preview's frames are sRGB-encoded
    // or linear sRGB). Throws ColorOptionError when it has none.
    std::string srgbSpace() const;
    // Each look of an OCIO look list ("a, +b, -c") exists. Throws ColorOptionError.
    void checkLooks(const std::string& looks) const;
    // display exists and has view. Throws ColorOptionError.
    void checkDisplayView(const std::string& display, const std::string& view) const;

    // What OpenColorIO logged while loading (warnings), as diagnostics.
    const Diagnostics& diagnostics() const;

    struct Impl; // formats/src/ocio/ColorConfigImpl.h: the OCIO config
    const Impl& impl() const { return *m_impl; }

private:
    std::shared_ptr<const Impl> m_impl;
};

// The names of the active config (`given`, else $OCIO, else lutkit's own) a shell completes for a
// colour-management option, one kind at a time: "spaces" (colour spaces, then their aliases, then
// the roles), "looks", "displays", "views" (every display's, each once) or "views:DISPLAY" (that
// display's). Throws lut::Error when there is no config or it cannot be read, and for another kind.
std::vector<std::string> configNames(const std::string& kind, const std::string& given = {});

// The colour spaces of the active config whose images hold `value`, a value outside the [0, 1] a
// LUT is usually made for (DomainStats::worst of lutkit apply): above 1 or below 0 are scene-linear
// values, so its scene-linear spaces (encoding scene-linear, or an lg2 allocation), above 1 those
// whose allocation reaches `value` (or that give none) when there are some. In the config's order;
// empty for a value in [0, 1] or NaN, and for a config without a scene-linear space. Throws
// lut::Error when there is no config or it cannot be read.
std::vector<std::string> spacesHolding(float value, const std::string& given = {});

} // namespace lut::formats
