// SPDX-License-Identifier: Apache-2.0
// The one list of built-in formats. Each format file exposes a factory declared in Formats.h.
#include "lut/formats/Registry.h"

#include "lut/io/BuiltinLut.h"

#include "Formats.h"

#include <mutex>

namespace lut::formats {

void registerBuiltinFormats() {
    static std::once_flag once;
    std::call_once(once, [] {
        auto& r = FormatRegistry::instance();
        (void)r;
        // FORMAT LIST (keep one line per format)
        r.add(makeCubeFormat());
        r.add(makeNutexbFormat());
        r.add(makeStripFormat());
        r.add(makeHaldFormat());
        r.add(makeSpi3dFormat()); // before the OpenColorIO reader: read and written here
        r.add(makeOcioReadFormat());
        for (auto& f : makeOcioBakeFormats())
            r.add(std::move(f));
    });
}

LutFile readLut(const std::string& path, const FormatOptions& options,
                const std::string& formatName) {
    if (isBuiltinLutName(path)) {
        // A LUT known by name (lut/io/BuiltinLut.h), never a file.
        LutFile f;
        f.cube = builtinLut(path);
        f.format = "builtin";
        f.dialect = path.substr(kBuiltinLutPrefix.size());
        // It says what it is for: a LUT the game applies (as a .nutexb is), else an edit.
        f.purpose = isBuiltinGameLut(path) ? LutPurpose::Smash : LutPurpose::Raw;
        return f;
    }
    registerBuiltinFormats();
    return FormatRegistry::instance().read(path, options, formatName);
}

Diagnostics writeLut(const std::string& path, const LutFile& lut, const FormatOptions& options,
                     const std::string& formatName) {
    registerBuiltinFormats();
    return FormatRegistry::instance().write(path, lut, options, formatName);
}

} // namespace lut::formats
