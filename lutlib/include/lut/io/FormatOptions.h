// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a caller can ask of a format reader or writer. The typed fields are the options several
// formats share; an option that only one format understands is a named attribute
// ("nutexb:name"), documented with that format and ignored by every other one (the way
// OpenImageIO's ImageSpec carries format-specific settings).
#include "lut/io/Layout.h"

#include <map>
#include <optional>
#include <string>

namespace lut {

struct FormatOptions {
    // LUT images: the layout to read or write (nullopt: auto-detect on read, the format's
    // default on write).
    std::optional<LutLayout> layout;
    int size = 0;        // lattice size when sampling foreign formats or writing (0 = own/default)
    int bitDepth = 0;    // integer outputs: 8, 16 or 32 (float); 0 = the format's default
    bool dither = false; // 8/16-bit outputs: ordered dither instead of plain rounding
    bool strict = false; // report every departure from the format's spec as a diagnostic

    // Format-specific settings, "format:name" -> value. Unknown names are ignored.
    std::map<std::string, std::string> attributes;

    void setAttribute(const std::string& name, std::string value) {
        attributes[name] = std::move(value);
    }
    // The attribute's value, or nullopt when it was not set.
    std::optional<std::string> attribute(const std::string& name) const {
        const auto it = attributes.find(name);
        if (it == attributes.end())
            return std::nullopt;
        return it->second;
    }
};

} // namespace lut
