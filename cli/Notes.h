// SPDX-License-Identifier: Apache-2.0
#pragma once
// What lutkit says besides its results: the library's diagnostics, one line each. Notes (Info)
// appear only when they change what the user gets and -q silences them; warnings and errors are
// always shown; -v shows more detail.
#include "lut/Error.h"
#include "lut/LutFile.h"

#include <ostream>
#include <string>

namespace lut::cli {

struct Verbosity {
    bool quiet = false;   // -q: no notes, no progress bar
    bool verbose = false; // -v: more detail (each subcommand's --help says what)
};

// Whether a diagnostic is shown at this verbosity.
bool isShown(const Diagnostic& d, const Verbosity& v);

// Every shown diagnostic of diags as `prefix + d.str()`, one per line.
void printDiagnostics(std::ostream& os, const Diagnostics& diags, const Verbosity& v,
                      const std::string& prefix = "  ");

// -v: how a LUT image was read when the user named no layout, e.g. "LUT image read in layout
// unreal (chosen from the picture; name another with --in-layout)"; "" for other files.
std::string layoutDetail(const LutFile& file, bool layoutGiven, const std::string& option);

// How lutkit names a severity in a message: "note", "warning", "error".
const char* severityWord(Diagnostic::Severity s);

} // namespace lut::cli
