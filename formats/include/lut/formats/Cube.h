// SPDX-License-Identifier: Apache-2.0
#pragma once
// The .cube format (Adobe Cube LUT Specification 1.0 and the DaVinci Resolve dialect): reading
// from memory or a file, writing to a string or a file, and strict validation against the Adobe
// spec. The format is also registered in the FormatRegistry as "cube" (extension ".cube").
// What is accepted and refused is detailed in formats/src/cube/CubeParser.h (reading) and
// formats/src/cube/CubeWriter.cpp (writing).
#include "lut/Error.h"
#include "lut/LutFile.h"

#include <optional>
#include <string>
#include <string_view>

namespace lut::formats {

struct CubeReadOptions {
    // Report every departure from the Adobe 1.0 spec (CR LF, BOM, long lines, lower-case or
    // repeated keywords, Resolve keywords, ...) as a Warning diagnostic in LutFile::diagnostics.
    // Departures never make the read fail; errors do in either mode.
    bool strict = false;
};

// Parses .cube text. `path` is used only in messages. Throws lut::ParseError (path, 1-based
// physical line and column, offending text) on any error; the result's dialect is "adobe" or
// "resolve", format is "cube".
LutFile parseCube(std::string_view text, const std::string& path = "<memory>",
                  const CubeReadOptions& options = {});

// Reads a .cube file (read whole into memory). Also throws lut::Error if it cannot be opened, is
// not a regular file (a FIFO, a directory, a device...) or changes while it is read, and
// lut::LimitError if it is larger than lut::limits::kMaxLutFileBytes.
LutFile readCube(const std::string& path, const CubeReadOptions& options = {});

// FormatOptions attribute for the registry's "cube" writer: "adobe" or "resolve" (what the aliases
// iridas_cube and resolve_cube, OpenColorIO's names, set); unset = CubeWriteOptions::Dialect::Auto.
constexpr const char* kCubeDialectAttribute = "cube:dialect";

struct CubeWriteOptions {
    enum class Dialect {
        Auto,   // Resolve when the file has a shaper and a cube, Adobe otherwise
        Adobe,  // a shaper + cube file is baked into one 3D table (with a diagnostic)
        Resolve // LUT_*_INPUT_RANGE instead of DOMAIN_* (needs equal domain on all channels)
    };
    Dialect dialect = Dialect::Auto;
    // Digits after the decimal point; < 0 = shortest text that reads back as the same float.
    int decimals = -1;
};

// The .cube text for lut. `diagnostics` (optional) receives what was changed or lost (baked
// shaper, non-finite values replaced, quotes in the title). Throws lut::Error if lut is empty.
std::string writeCubeString(const LutFile& lut, Diagnostics* diagnostics = nullptr,
                            const CubeWriteOptions& options = {});

// Writes lut to path atomically (temporary file renamed into place); returns the diagnostics.
Diagnostics writeCube(const std::string& path, const LutFile& lut,
                      const CubeWriteOptions& options = {});

// The outcome of validating one file: never throws for bad content or unreadable files.
struct CubeValidation {
    std::optional<LutFile> lut; // set when the file parsed
    // Departures from the spec (Warning), notes (Info) and, if it failed, the error (Error).
    Diagnostics diagnostics;
    bool parsed() const { return lut.has_value(); }
    // Number of departures found (including those only counted in an "and N more" line).
    int departures = 0;
    // True if it parsed and (when validated strictly) has no Warning or Error diagnostic.
    bool ok = false;
    // "adobe 3D, 33^3", "adobe 1D, 1024", "resolve 1D 1024 + 3D, 33^3" ("" if not parsed).
    std::string summary() const;
};

CubeValidation validateCube(const std::string& path, bool strict);

// Short description of what a .cube LutFile holds, as in CubeValidation::summary().
std::string describeCube(const LutFile& lut);

// The one warning for a .cube written as a 1D shaper then a 3D table (the Resolve dialect) where
// the user named no form: ffmpeg's lut3d ("Invalid data found"), Photoshop's Color Lookup and
// most game engines refuse it; --format iridas_cube writes the one 3D table they read. `kept`
// says why the shaper is there ("the look needs it"); `tableAlone`, when not empty, what the one
// table costs, as the command printed it ("the table alone would be max ... from the match").
Diagnostic resolveCubeReadersWarning(const std::string& path, const std::string& kept,
                                     const std::string& tableAlone,
                                     const std::string& iridasWrites);

} // namespace lut::formats
