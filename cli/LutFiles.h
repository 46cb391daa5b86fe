// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the LUT-maths subcommands (diff, compose, invert, resize, smooth, mix, plot, adjust) share:
// reading a LUT file as one 3D table, writing a result in any format, and the one line that says
// what an operation cost.
#include "Notes.h"

#include "lut/ErrorStats.h"
#include "lut/Lut3D.h"
#include "lut/LutFile.h"
#include "lut/io/Layout.h"

#include <optional>
#include <ostream>
#include <vector>

#include <string>

namespace lut::cli {

// The LUT that apply and preview take with --lut (--lut-layout when it is an image): its
// diagnostics printed to stderr, and with -v how its layout was chosen.
LutFile readCommandLut(const std::string& path, const std::optional<LutLayout>& layout,
                       const Verbosity& verbosity);

// The file as one 3D table, its diagnostics printed to stderr; a file with a shaper is sampled at
// the table's size (lut::sampleOnLattice) over 0..1 where the shaper's range holds it (the one
// rule, lut/formats/DisplayRange.h), else over that range, and the error that costs between
// lattice points is said. `purpose` (optional) receives what the file is for (lut/LutPurpose.h;
// `given`: a flag's value).
Lut3D readLutTable(const std::string& path, const Verbosity& verbosity,
                   PurposeDecision* purpose = nullptr,
                   std::optional<LutPurpose> given = std::nullopt);
// The purpose a result carries on: what the input said or was told, nullopt when it was only
// assumed (an assumption is not turned into a statement in the output).
std::optional<LutPurpose> knownPurpose(const PurposeDecision& decision);

struct WrittenLut {
    std::string format; // the writer's name
    Diagnostics diagnostics;
};

// Writes file to path (format: "" = by extension, else a name or alias), never over one of the
// inputs.
WrittenLut writeLutFile(const std::string& path, const LutFile& file, const std::string& format,
                        const std::vector<std::string>& inputs);

// writeLutFile for one table, then "wrote PATH: FORMAT, N^3" and the writer's diagnostics on os.
void writeLutTable(std::ostream& os, const std::string& path, const Lut3D& lut,
                   const std::string& format, const std::vector<std::string>& inputs,
                   const Verbosity& verbosity, std::optional<LutPurpose> purpose = std::nullopt);

// "max 1.2e-03 (0.31 8-bit steps), mean ..., 12.3 ms" with the sanitized-entry note.
std::string costText(const ErrorStats& error, std::size_t sanitizedEntries);

} // namespace lut::cli
