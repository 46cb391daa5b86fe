#pragma once
#include "lut/LutFile.h"

#include <memory>
#include <string>
#include <vector>

namespace lut {

// Options understood by format readers and writers; each format uses what applies to it.
struct FormatOptions {
    std::string layout;  // LUT image layout: pilot, unity, smush, hald ("" = auto/default)
    int size = 0;        // lattice size when sampling foreign formats or writing (0 = own/default)
    int bitDepth = 0;    // image output: 8, 16 or 32 (float); 0 = the format's default
    bool dither = false; // 8-bit image output: ordered dither instead of plain rounding
    bool strict = false; // report every departure from the spec as a diagnostic
    bool tiled = true;   // nutexb: block-linear tiled (true) or linear rows
    std::string name;    // nutexb name field ("" = color_grading_lut)
};

// One concrete file format. Formats live in formats/ and are registered from one list.
class Format {
public:
    virtual ~Format();
    virtual std::string name() const = 0; // "cube", "nutexb", "png-strip"...
    virtual std::string description() const = 0;
    virtual std::vector<std::string> extensions() const = 0; // lower case, with dot: ".cube"
    virtual bool canRead() const { return true; }
    virtual bool canWrite() const { return true; }
    virtual LutFile read(const std::string& path, const FormatOptions& options) const = 0;
    // Writes atomically (temporary file renamed into place). Returns diagnostics about what was
    // lost (quantisation, resampling, dropped shaper...).
    virtual Diagnostics write(const std::string& path, const LutFile& lut,
                              const FormatOptions& options) const = 0;
    // What the written file can hold, so callers (lutkit convert) can resample and report the
    // error before writing: the one lattice size the format stores (0 = any) and the integer bit
    // depth of its values (0 = float or varies with options).
    virtual int fixedSize() const { return 0; }
    virtual int storedBitDepth() const { return 0; }
};

// Formats by name and extension. Two formats may claim one extension: read() tries each in
// turn and, if all fail, throws one error that lists every format's reason.
class FormatRegistry {
public:
    static FormatRegistry& instance(); // filled by lut::formats::registerBuiltinFormats()

    void add(std::unique_ptr<Format> format);
    const Format* byName(const std::string& name) const;
    std::vector<const Format*> forExtension(const std::string& path) const;
    // The first format that writes files with path's extension, or nullptr.
    const Format* writerForPath(const std::string& path) const;
    std::vector<const Format*> all() const;

    // formatName "" = pick by extension.
    LutFile read(const std::string& path, const FormatOptions& options,
                 const std::string& formatName = {}) const;
    Diagnostics write(const std::string& path, const LutFile& lut, const FormatOptions& options,
                      const std::string& formatName = {}) const;

private:
    std::vector<std::unique_ptr<Format>> m_formats;
};

// Lower-cased extension of path including the dot ("" if none).
std::string extensionOf(const std::string& path);

} // namespace lut
