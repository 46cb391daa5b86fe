// SPDX-License-Identifier: Apache-2.0
#pragma once
// Formats by name and extension. Two formats may claim one extension: read() tries each in turn
// and, if all fail, throws one error that lists every format's reason.
#include "lut/io/Format.h"

#include <memory>
#include <string>
#include <vector>

namespace lut {

class FormatRegistry {
public:
    static FormatRegistry& instance(); // filled by lut::formats::registerBuiltinFormats()

    void add(std::unique_ptr<Format> format);
    // By name or alias (lut/io/Format.h's FormatAlias).
    const Format* byName(const std::string& name) const;
    // Adds the setting an alias implies to options ("resolve_cube": cube:dialect=resolve);
    // nothing for a format's own name.
    void applyAlias(const std::string& name, FormatOptions& options) const;
    std::vector<const Format*> forExtension(const std::string& path) const;
    // The first format that writes files with path's extension, or nullptr.
    const Format* writerForPath(const std::string& path) const;
    std::vector<const Format*> all() const;

    // formatName "" = pick by extension; an alias applies its setting (applyAlias).
    LutFile read(const std::string& path, const FormatOptions& options,
                 const std::string& formatName = {}) const;
    Diagnostics write(const std::string& path, const LutFile& lut, const FormatOptions& options,
                      const std::string& formatName = {}) const;

private:
    std::vector<std::unique_ptr<Format>> m_formats;
};

} // namespace lut
