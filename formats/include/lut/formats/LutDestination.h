// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where a LUT goes, decided once: what the user said (--format, --target, --size, --layout,
// --level) and what the output file is (its writer) resolved into one destination that every
// command writing a LUT uses (convert, its folder form, extract, match, compose, mix). The rules
// live here and nowhere else:
//  - the writer: the format named, else the one that writes the path's extension (none: writer
//    is null, and requireWriter() says so when the command comes to write);
//  - what the LUT is for (lut/LutPurpose.h): the purpose said (--target), else the game's LUT for
//    the game's format (a .nutexb: the game applies it), else what the input is for;
//  - the lattice: the size asked for; a Hald level L asks for N = L^2 in a Hald image (a LUT
//    image output only, not with another layout); the one size the format stores (a .nutexb's
//    16^3, reshade's 32^3); a new table's size when none is asked (newTableSize: the fixed size,
//    else 16^3 for a LUT image, else the caller's).
// A request that cannot be (a Hald level for a .cube) throws RequestError
// (lut/formats/RequestError.h), bad usage; the front end prints its text and never reads it.
#include "lut/LutPurpose.h"
#include "lut/formats/RequestError.h"
#include "lut/io/Format.h"
#include "lut/io/Layout.h"

#include <optional>
#include <string>

namespace lut::formats {

// The registry name of the game's LUT format (Smash Ultimate's .nutexb, lut/formats/Nutexb.h):
// what a folder is converted to when no format is named.
constexpr const char* kGameLutFormat = "nutexb";

// A LUT image's lattice when nothing asks for another (a 256x16 strip, a level-4 Hald image):
// lutkit neutral's and the editor's strips.
constexpr int kLutImageSize = 16;

// Whether `path` is a file in the game's own format (a .nutexb by its extension): the game's LUT
// by what it is, whatever it holds (lutkit's drop on a .nutexb refuses it).
bool isGameFormatPath(const std::string& path);

// What the user said about the output.
struct LutDestinationRequest {
    std::string path;                  // the output file ("-" = standard output)
    std::string format;                // writer name ("" = by the path's extension)
    std::optional<LutPurpose> purpose; // what it is for (--target); nullopt = the rule above
    int size = 0;                      // lattice size N asked for (0 = the format's, the table's)
    std::optional<LutLayout> layout;   // LUT image layout asked for
    int haldLevel = 0;                 // Hald level L (0 = none): N = L^2, layout hald
};

// Why the destination's purpose is what it is.
enum class DestinationPurpose {
    Input,      // none fixed: what the input is for
    Said,       // --target
    GameFormat, // the game's format (a .nutexb): the game's LUT
};

struct LutDestination {
    std::string path;
    std::string format;             // as requested ("" = by extension)
    const Format* writer = nullptr; // the format that writes it (null: none writes the path)
    // What the output is for when the destination fixes it (nullopt: what the input is for).
    std::optional<LutPurpose> purpose;
    DestinationPurpose purposeFrom = DestinationPurpose::Input;
    int size = 0;                    // lattice size asked for (a Hald level's L^2), 0 = none
    std::optional<LutLayout> layout; // LUT image layout (hald for a Hald level)
    int haldLevel = 0;
    bool hald = false;  // a Hald image is written (N = L^2 only)
    bool image = false; // a LUT image (strip or Hald) is written
    int fixedSize = 0;  // the one lattice size the writer stores with this layout (0 = any)

    // What the output is for, for an input that is for `input`.
    LutPurpose purposeFor(LutPurpose input) const { return purpose.value_or(input); }
    // The output is the game's LUT (said, or the game's format).
    bool forGame() const { return purpose == LutPurpose::Smash; }
    // The writer is the game's own format (a .nutexb).
    bool gameFormat() const;
    // The writer, or lut::Error "PATH: no format writes '.ext' files (name the output format:
    // --format)".
    const Format& requireWriter() const;
    // The lattice size of a new table written here (a neutral, the editor's export of its
    // document): the size asked for, else the format's fixed size, else kLutImageSize for a LUT
    // image, else `otherwise` (0 = the table's own).
    int newTableSize(int otherwise) const;
};

// Resolves the request (the registry's built-in formats registered first). Throws RequestError
// for a Hald level with another layout or a non-image output.
LutDestination resolveLutDestination(const LutDestinationRequest& request);

} // namespace lut::formats
