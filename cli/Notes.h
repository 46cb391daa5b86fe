// SPDX-License-Identifier: Apache-2.0
#pragma once
// What lutkit says besides its results: the library's diagnostics, one line each. Notes (Info)
// appear only when they change what the user gets and -q silences them; warnings and errors are
// always shown; -v shows more detail.
//
// -q, the one rule for every command: nothing but warnings and errors, on standard error. The
// command line (CommandLine.cpp) holds a QuietReport around every command run with -q, so what a
// command prints to std::cout (its report: "read", "wrote", the tables) goes nowhere, while the
// data the user asked for still comes out: an output file written to standard output (written
// to the file descriptor, never through std::cout) and --json (asked for by name, so -q does not
// silence it). printDiagnostics sends a shown diagnostic to standard error under -q.
#include "lut/Error.h"
#include "lut/LutFile.h"

#include <ostream>
#include <streambuf>
#include <string>

namespace lut::cli {

struct Verbosity {
    bool quiet = false;   // -q: no notes, no progress bar
    bool verbose = false; // -v: more detail (each subcommand's --help says what)
};

// While it lives (and `on`), std::cout writes nowhere; its destructor puts the stream back.
class QuietReport {
public:
    explicit QuietReport(bool on);
    ~QuietReport();
    QuietReport(const QuietReport&) = delete;
    QuietReport& operator=(const QuietReport&) = delete;

private:
    bool m_on = false;
};

// Whether -q silences the report of a command run with these options: -q given and no --json.
template <class Options> bool reportSilenced(const Options& o) {
    if constexpr (requires { o.verbosity.quiet; }) {
        if constexpr (requires { o.json; })
            if (o.json)
                return false;
        return o.verbosity.quiet;
    } else {
        return false;
    }
}

// Where std::cout's report goes from now on (Outputs.cpp: standard error once the data is on
// standard output). Under a QuietReport it is where the report goes after the command.
void redirectReport(std::streambuf* to);

// Whether a diagnostic is shown at this verbosity.
bool isShown(const Diagnostic& d, const Verbosity& v);

// Every shown diagnostic of diags as `prefix + d.str()`, one per line; under -q (warnings and
// errors only) a diagnostic meant for the report (os is not std::cerr) goes to standard error
// instead, since the report is silenced.
void printDiagnostics(std::ostream& os, const Diagnostics& diags, const Verbosity& v,
                      const std::string& prefix = "  ");
// One diagnostic the same way (nothing when it is not shown); moved to standard error under -q,
// as "lutkit: " + d.str() when it names no file.
void printDiagnostic(std::ostream& os, const Diagnostic& d, const Verbosity& v,
                     const std::string& prefix = "  ");

// -v: how a LUT image was read when the user named no layout, e.g. "LUT image read in layout
// unreal (chosen from the picture; name another with --in-layout)"; "" for other files.
std::string layoutDetail(const LutFile& file, bool layoutGiven, const std::string& option);

// How lutkit names a severity in a message: "note", "warning", "error".
const char* severityWord(Diagnostic::Severity s);

} // namespace lut::cli
