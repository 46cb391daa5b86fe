// SPDX-License-Identifier: Apache-2.0
#include "Notes.h"

#include "lut/io/FileNames.h"

#include <iostream>

namespace lut::cli {

namespace {

// A stream buffer that takes every byte and keeps none.
class NullBuffer : public std::streambuf {
protected:
    int overflow(int c) override { return traits_type::not_eof(c); }
    std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

NullBuffer g_nowhere;
std::streambuf* g_afterQuiet = nullptr; // std::cout's buffer while a QuietReport holds it

} // namespace

QuietReport::QuietReport(bool on) : m_on(on && g_afterQuiet == nullptr) {
    if (!m_on)
        return;
    std::cout.flush();
    g_afterQuiet = std::cout.rdbuf(&g_nowhere);
}

QuietReport::~QuietReport() {
    if (!m_on)
        return;
    std::cout.rdbuf(g_afterQuiet);
    g_afterQuiet = nullptr;
}

void redirectReport(std::streambuf* to) {
    if (g_afterQuiet)
        g_afterQuiet = to;
    else
        std::cout.rdbuf(to);
}

bool isShown(const Diagnostic& d, const Verbosity& v) {
    return d.severity != Diagnostic::Severity::Info || !v.quiet;
}

void printDiagnostics(std::ostream& os, const Diagnostics& diags, const Verbosity& v,
                      const std::string& prefix) {
    for (const auto& d : diags)
        printDiagnostic(os, d, v, prefix);
}

void printDiagnostic(std::ostream& os, const Diagnostic& d, const Verbosity& v,
                     const std::string& prefix) {
    if (!isShown(d, v))
        return;
    if (v.quiet && &os != &std::cerr) // the report is silenced: the warnings go to stderr
        std::cerr << (d.path.empty() ? "lutkit: " : "") << printable(d.str()) << "\n";
    else
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
