// SPDX-License-Identifier: Apache-2.0
#pragma once
// One concrete LUT file format. Formats live in formats/ and are registered from one list
// (lut/io/FormatRegistry.h).
#include "lut/LutFile.h"
#include "lut/io/FormatOptions.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lut {

// Another name a format answers to (e.g. OpenColorIO's "cinespace" for "csp"), optionally with a
// format-specific setting it implies ("resolve_cube" = "cube" with "cube:dialect" = "resolve").
struct FormatAlias {
    std::string name;
    std::string attribute; // "" = none
    std::string value;
};

class Format {
public:
    virtual ~Format();
    virtual std::string name() const = 0; // "cube", "nutexb", "strip"...
    virtual std::string description() const = 0;
    virtual std::vector<std::string> extensions() const = 0; // lower case, with dot: ".cube"
    // Other names accepted for this format (by --format and FormatRegistry::byName).
    virtual std::vector<FormatAlias> aliases() const { return {}; }
    virtual bool canRead() const { return true; }
    virtual bool canWrite() const { return true; }
    // A format reads and writes bytes in memory: the file, standard input and output, the
    // editor's export preview, archives and tests all go through these. `name` stands for the
    // data in messages (the file's path, "-", "the export") and gives the extension where a format
    // needs one. Returns, for a write, diagnostics about what was lost (quantisation, resampling,
    // a dropped shaper...).
    virtual LutFile readMemory(std::string_view bytes, const std::string& name,
                               const FormatOptions& options) const = 0;
    virtual std::string writeMemory(const LutFile& lut, const std::string& name,
                                    const FormatOptions& options,
                                    Diagnostics* diagnostics = nullptr) const = 0;

    // The same for a file, a convenience over the bytes. read(): the file's bytes (up to
    // lut::limits::kMaxLutFileBytes, lut/io/InputFile.h) to readMemory(). write(): writeMemory()'s
    // bytes put on disk atomically (lut::writeFileAtomically: a temporary file beside the output,
    // checked, renamed into place; an old file untouched when the write fails). A format
    // overrides them only where a file is read or written otherwise (a LUT image's codecs take
    // paths, a .cube's header is checked before the file is read whole); the result equals the
    // memory forms' on the same bytes. The one place a temporary folder remains is OpenColorIO's
    // reader (it opens files by path only: formats/src/ocio/OcioTemporaryFile.h).
    virtual LutFile read(const std::string& path, const FormatOptions& options) const;
    virtual Diagnostics write(const std::string& path, const LutFile& lut,
                              const FormatOptions& options) const;

    // What the written file can hold, so callers (lutkit convert) can resample and report the
    // error before writing: the one lattice size the format stores (0 = any) and the integer bit
    // depth of its values (0 = float or varies with options).
    virtual int fixedSize() const { return 0; }
    // The same for a write with these options (a LUT image's layout may fix the size: reshade and
    // unity-32 are 32^3).
    virtual int fixedSizeFor(const FormatOptions& options) const {
        (void)options;
        return fixedSize();
    }
    virtual int storedBitDepth() const { return 0; }
    // Whether the written file keeps a 1D shaper and a 3D table's input range (domain) as they
    // are (.cube's Resolve dialect, .clf, .ctf, .csp), so an HDR or log input needs no resampling.
    virtual bool holdsShaper() const { return false; }
    // The same for a write with these options (.cube's Adobe dialect, --format iridas_cube, has
    // no shaper).
    virtual bool holdsShaperFor(const FormatOptions& options) const {
        (void)options;
        return holdsShaper();
    }
    // Whether a file this format writes at `path` says what its LUT is for (LutFile::purpose,
    // lut/LutPurpose.h) so that it reads back with that purpose: its LUTKIT_PURPOSE tag in a
    // comment or a description, or the format itself (a .nutexb is the game's LUT, and only that).
    // lut::writeLutFile warns when it does not (docs/roundtrip.md, "What the file says it is for").
    virtual bool keepsPurpose(const std::string& path, LutPurpose purpose) const {
        (void)path;
        (void)purpose;
        return false;
    }

    // Standard input is read whole before a reader sees it, so each format says how long a
    // stream that starts with `head` (its first 1 MiB, or all of it) can be in this format: 0 when
    // it cannot be one. The default, for text formats: no NUL byte in head, and up to
    // lut::limits::kMaxLutFileBytes.
    virtual std::uint64_t maxStreamBytes(std::string_view head) const;
};

} // namespace lut
