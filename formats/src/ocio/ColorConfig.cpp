// SPDX-License-Identifier: Apache-2.0
// Finding and loading OpenColorIO configs, and checking the names users give against them.
#include "lut/formats/ColorConfig.h"

#include "ocio/ColorConfigImpl.h"
#include "ocio/OcioConfigChecks.h"

#include "lut/io/FileNames.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace lut::formats {

namespace {

constexpr const char* kShippedRelative = "share/lutkit/ocio/config.ocio";

bool isFile(const std::string& p) {
    std::error_code ec;
    return std::filesystem::is_regular_file(p, ec);
}

std::string listText(const std::vector<std::string>& names) {
    std::string s;
    for (std::size_t i = 0; i < names.size(); ++i)
        s += (i ? ", " : "") + names[i];
    return s;
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    const auto e = s.find_last_not_of(" \t");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

} // namespace

std::string ConfigLocation::describe() const {
    switch (source) {
    case ConfigSource::Option:
        return path + " (--config)";
    case ConfigSource::Environment:
        return path + " ($OCIO)";
    case ConfigSource::Shipped:
        break;
    }
    return path + " (lutkit's own)";
}

std::string shippedConfigPath() {
    std::vector<std::string> candidates;
    if (const std::string exe = executableDir(); !exe.empty())
        candidates.push_back(exe + "/../" + kShippedRelative);
#ifdef LUTKIT_INSTALL_PREFIX
    candidates.push_back(std::string(LUTKIT_INSTALL_PREFIX) + "/" + kShippedRelative);
#endif
#ifdef LUTKIT_BUILD_SHARE_DIR
    candidates.push_back(std::string(LUTKIT_BUILD_SHARE_DIR) + "/lutkit/ocio/config.ocio");
#endif
    for (const auto& c : candidates)
        if (isFile(c))
            return std::filesystem::weakly_canonical(c).string();
    return {};
}

ConfigLocation locateConfig(const std::string& given) {
    if (!given.empty())
        return {given, ConfigSource::Option};
    if (const char* env = std::getenv("OCIO"); env && *env)
        return {env, ConfigSource::Environment};
    const std::string shipped = shippedConfigPath();
    if (shipped.empty())
        throw Error("no OpenColorIO config: name one with --config FILE or $OCIO (lutkit's own, " +
                    std::string(kShippedRelative) + " next to the program, is missing)");
    return {shipped, ConfigSource::Shipped};
}

ColorOptionError::ColorOptionError(const std::string& message, std::string kind, std::string value,
                                   std::vector<std::string> known)
    : Error(message), m_kind(std::move(kind)), m_value(std::move(value)),
      m_known(std::move(known)) {}

bool ColorSpaceInfo::isHdrLinear() const {
    return !isData && (encoding == "scene-linear" || lg2Allocation);
}

namespace {

// OpenColorIO 2.1 loads a config in time quadratic in its colour spaces (3,000: 15 s; 20,000:
// over 15 min), so a hostile config could hang a batch. The largest real configs hold a few
// hundred (ACES 1.0.3: 182 colour spaces and looks); 1,000 load in about 2 s. Counted in the
// text, before OpenColorIO parses it: every colour space, named transform and look is a YAML
// node with its tag.
constexpr std::size_t kMaxConfigEntries = 1000;

void checkConfigSize(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::size_t entries = 0;
    for (const char* tag : {"!<ColorSpace>", "!<NamedTransform>", "!<Look>"})
        for (std::size_t at = text.find(tag); at != std::string::npos; at = text.find(tag, at + 1))
            ++entries;
    if (entries > kMaxConfigEntries)
        throw LimitError(path + ": the OpenColorIO config defines " + std::to_string(entries) +
                         " colour spaces, named transforms and looks, over the limit of " +
                         std::to_string(kMaxConfigEntries) +
                         " (OpenColorIO's load time grows with the square of their number)");
}

} // namespace

ColorConfig ColorConfig::load(const ConfigLocation& location) {
    auto impl = std::make_shared<Impl>();
    impl->location = location;
    if (!isFile(location.path))
        throw Error(
            location.path + ": cannot open the OpenColorIO config: " +
            (std::filesystem::exists(location.path) ? "not a regular file" : "no such file") +
            (location.source == ConfigSource::Environment ? " (named by $OCIO)" : ""));
    // OCIO reads the whole config into memory: no config is near this size.
    constexpr std::uintmax_t kMaxConfigBytes = std::uintmax_t(64) << 20;
    std::error_code ec;
    if (const auto size = std::filesystem::file_size(location.path, ec);
        !ec && size > kMaxConfigBytes)
        throw LimitError(location.path + ": the OpenColorIO config is " + std::to_string(size) +
                         " bytes, over the limit of " + std::to_string(kMaxConfigBytes) + " bytes");
    checkConfigSize(location.path);
    OcioSession session(location.path);
    try {
        auto config = OCIO::Config::CreateFromFile(location.path.c_str());
        config->validate();
        checkOcioConfig(config, location.path); // the files it names, cycles
        impl->config = config;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        const OcioReason r = shortOcioMessage(location.path, ocioMessage(e.what()));
        throw Error(location.path + (r.line > 0 ? ":" + std::to_string(r.line) : "") +
                    (r.line > 0 && r.column > 0 ? ":" + std::to_string(r.column) : "") +
                    ": OpenColorIO cannot read the config: " + r.text);
    }
    session.appendDiagnostics(impl->diagnostics);
    ColorConfig c;
    c.m_impl = std::move(impl);
    return c;
}

const ConfigLocation& ColorConfig::location() const {
    return m_impl->location;
}

const Diagnostics& ColorConfig::diagnostics() const {
    return m_impl->diagnostics;
}

std::vector<std::string> ColorConfig::colorSpaces() const {
    std::vector<std::string> out;
    const auto& c = m_impl->config;
    for (int i = 0;
         i < c->getNumColorSpaces(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL); ++i)
        out.emplace_back(
            c->getColorSpaceNameByIndex(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL, i));
    return out;
}

std::vector<std::string> ColorConfig::roles() const {
    std::vector<std::string> out;
    for (int i = 0; i < m_impl->config->getNumRoles(); ++i)
        out.emplace_back(m_impl->config->getRoleName(i));
    return out;
}

std::vector<std::string> ColorConfig::displays() const {
    std::vector<std::string> out;
    for (int i = 0; i < m_impl->config->getNumDisplays(); ++i)
        out.emplace_back(m_impl->config->getDisplay(i));
    return out;
}

std::vector<std::string> ColorConfig::views(const std::string& display) const {
    std::vector<std::string> out;
    for (int i = 0; i < m_impl->config->getNumViews(display.c_str()); ++i)
        out.emplace_back(m_impl->config->getView(display.c_str(), i));
    return out;
}

std::vector<std::string> ColorConfig::looks() const {
    std::vector<std::string> out;
    for (int i = 0; i < m_impl->config->getNumLooks(); ++i)
        out.emplace_back(m_impl->config->getLookNameByIndex(i));
    return out;
}

std::string ColorConfig::defaultDisplay() const {
    return m_impl->config->getDefaultDisplay();
}

std::string ColorConfig::defaultView(const std::string& display) const {
    return m_impl->config->getDefaultView(display.c_str());
}

std::string ColorConfig::colorSpace(const std::string& name) const {
    const auto cs = m_impl->config->getColorSpace(name.c_str()); // names, aliases and roles
    if (cs)
        return cs->getName();
    std::vector<std::string> known = colorSpaces();
    for (const auto& r : roles())
        known.push_back(r);
    throw ColorOptionError("unknown colour space '" + name + "' in " + m_impl->location.describe() +
                               " (colour spaces: " + listText(colorSpaces()) +
                               "; roles: " + listText(roles()) + ")",
                           "colour space", name, known);
}

ColorSpaceInfo ColorConfig::info(const std::string& name) const {
    const auto cs = m_impl->config->getColorSpace(colorSpace(name).c_str());
    ColorSpaceInfo i;
    i.name = cs->getName();
    for (std::size_t a = 0; a < cs->getNumAliases(); ++a)
        i.aliases.emplace_back(cs->getAlias(a));
    i.family = cs->getFamily();
    i.encoding = cs->getEncoding();
    i.description = cs->getDescription();
    i.isData = cs->isData();
    i.lg2Allocation = cs->getAllocation() == OCIO::ALLOCATION_LG2;
    i.allocationVars.resize(static_cast<std::size_t>(cs->getAllocationNumVars()));
    if (!i.allocationVars.empty())
        cs->getAllocationVars(i.allocationVars.data());
    return i;
}

std::string ColorConfig::srgbSpace() const {
    for (const char* n : {"sRGB - Texture", "srgb_tx", "Utility - sRGB - Texture", "sRGB", "srgb"})
        if (const auto cs = m_impl->config->getColorSpace(n))
            return cs->getName();
    throw ColorOptionError(
        m_impl->location.describe() +
        " has no sRGB colour space (looked for \"sRGB - Texture\", srgb_tx, "
        "\"Utility - sRGB - Texture\", sRGB): lutkit preview converts through it");
}

void ColorConfig::checkLooks(const std::string& looks) const {
    std::stringstream ss(looks);
    std::string item;
    const auto known = this->looks();
    while (std::getline(ss, item, ',')) {
        // OCIO look lists: "a, +b, -c" and alternatives "a | b".
        std::stringstream alt(item);
        std::string one;
        while (std::getline(alt, one, '|')) {
            std::string n = trim(one);
            if (!n.empty() && (n[0] == '+' || n[0] == '-'))
                n = trim(n.substr(1));
            if (n.empty() || std::find(known.begin(), known.end(), n) != known.end())
                continue;
            throw ColorOptionError(
                "unknown look '" + n + "' in " + m_impl->location.describe() +
                    (known.empty() ? " (it has no looks)" : " (looks: " + listText(known) + ")"),
                "look", n, known);
        }
    }
}

void ColorConfig::checkDisplayView(const std::string& display, const std::string& view) const {
    const auto displays = this->displays();
    if (std::find(displays.begin(), displays.end(), display) == displays.end())
        throw ColorOptionError("unknown display '" + display + "' in " +
                                   m_impl->location.describe() +
                                   " (displays: " + listText(displays) + ")",
                               "display", display, displays);
    const auto views = this->views(display);
    if (std::find(views.begin(), views.end(), view) == views.end())
        throw ColorOptionError("display '" + display + "' has no view '" + view + "' in " +
                                   m_impl->location.describe() + " (views: " + listText(views) +
                                   ")",
                               "view", view, views);
}

} // namespace lut::formats
