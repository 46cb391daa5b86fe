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

// The game's stage LUT named by --original-lut (lut/pipeline/StageLut.h: a file with a shaper is
// sampled at the game's 16^3 lattice, the error said), its diagnostics printed to stderr.
Lut3D readStageLut(const std::string& path, const Verbosity& verbosity);

// The file as one 3D table, its diagnostics printed to stderr; a file with a shaper is sampled at
// the table's size over the shaper's range (lut::sampleOnLattice) and the error that costs between
// lattice points is said.
Lut3D readLutTable(const std::string& path, const Verbosity& verbosity);

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
                   const Verbosity& verbosity);

// "max 1.2e-03 (0.31 8-bit steps), mean ..., 12.3 ms" with the sanitized-entry note.
std::string costText(const ErrorStats& error, std::size_t sanitizedEntries);

} // namespace lut::cli
