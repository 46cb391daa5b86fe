// SPDX-License-Identifier: Apache-2.0
#include "Notes.h"

#include "lut/io/FileNames.h"

namespace lut::cli {

bool isShown(const Diagnostic& d, const Verbosity& v) {
    return d.severity != Diagnostic::Severity::Info || !v.quiet;
}

void printDiagnostics(std::ostream& os, const Diagnostics& diags, const Verbosity& v,
                      const std::string& prefix) {
    for (const auto& d : diags)
        if (isShown(d, v))
            os << prefix << printable(d.str()) << "\n";
}

std::string layoutDetail(const LutFile& file, bool layoutGiven, const std::string& option) {
    if (layoutGiven || (file.format != "strip" && file.format != "hald"))
        return {};
    return "LUT image read in layout " + file.dialect +
           " (chosen from the picture; name another with " + option + ")";
}

const char* severityWord(Diagnostic::Severity s) {
    switch (s) {
    case Diagnostic::Severity::Info:
        return "note";
    case Diagnostic::Severity::Warning:
        return "warning";
    case Diagnostic::Severity::Error:
        return "error";
    }
    return "note";
}

} // namespace lut::cli
