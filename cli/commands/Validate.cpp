// SPDX-License-Identifier: Apache-2.0
// lutkit validate: parse LUT files and report problems with file:line:col. .cube files get the
// full treatment (lut::formats::validateCube: strict departures from Adobe 1.0); other formats are
// read through the registry and reported ok or failed.
#include "commands/Validate.h"

#include "Usage.h"
#include "Vocabulary.h"

#include "lut/Error.h"
#include "lut/formats/Cube.h"
#include "lut/formats/Registry.h"
#include "lut/io/FileNames.h"
#include "lut/io/Format.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lut::cli {

namespace {

std::string describe(const LutFile& f) {
    std::string s = f.format;
    if (!f.dialect.empty())
        s += " " + f.dialect;
    if (f.shaper && f.cube)
        return s + " 1D " + std::to_string(f.shaper->size()) + " + 3D, " +
               std::to_string(f.cube->size()) + "^3";
    if (f.cube)
        return s + " 3D, " + std::to_string(f.cube->size()) + "^3";
    if (f.shaper)
        return s + " 1D, " + std::to_string(f.shaper->size());
    return s;
}

// One file; returns true if it passes.
bool validateOne(const std::string& path, const ValidateOptions& o) {
    const bool isCube =
        o.inFormat == "cube" || (o.inFormat.empty() && extensionOf(path) == ".cube");
    if (isCube) {
        const formats::CubeValidation v = formats::validateCube(path, o.strict);
        for (const Diagnostic& d : v.diagnostics) {
            if (d.severity == Diagnostic::Severity::Error) {
                // Errors without a place already name the file in their message.
                std::cerr << printable(d.path.empty() ? "lutkit: error: " + d.message : d.str())
                          << "\n";
                continue;
            }
            printDiagnostic(std::cout, d, o.verbosity, "");
        }
        if (!v.parsed())
            return false;
        if (v.ok) {
            std::cout << path << ": ok (" << v.summary() << ")\n";
            return true;
        }
        std::cout << path << ": " << v.departures << " departure" << (v.departures == 1 ? "" : "s")
                  << " from the Adobe .cube 1.0 spec (" << v.summary() << ")\n";
        return false;
    }
    try {
        FormatOptions options;
        options.strict = o.strict;
        options.layout = o.inLayout;
        const LutFile f = formats::readLut(path, options, o.inFormat);
        bool ok = true;
        for (const Diagnostic& d : f.diagnostics) {
            printDiagnostic(std::cout, d, o.verbosity, "");
            if (o.strict && d.severity != Diagnostic::Severity::Info)
                ok = false;
        }
        if (o.verbosity.verbose)
            if (const std::string d = layoutDetail(f, o.inLayout.has_value(), "--in-layout");
                !d.empty())
                std::cout << path << ": " << d << "\n";
        if (ok)
            std::cout << path << ": ok (" << describe(f) << ")\n";
        return ok;
    } catch (const Error& e) {
        std::cerr << "lutkit: error: " << printable(e.what()) << "\n";
        return false;
    }
}

} // namespace

int runValidate(const ValidateOptions& o) {
    formats::registerBuiltinFormats();
    bool allOk = true;
    for (const std::string& path : o.inputs)
        allOk = validateOne(path, o) && allOk;
    return allOk ? kExitOk : kExitFailure;
}

CLI::App* setupValidate(CLI::App& app, std::function<void(const ValidateOptions&)> onParsed) {
    auto o = std::make_shared<ValidateOptions>();
    auto* sub = app.add_subcommand(
        "validate", "Check LUT files: errors with file:line:col; --strict also lists every "
                    "departure from the Adobe .cube 1.0 spec");
    sub->add_option("FILE", o->inputs, "LUT files to check")->required()->type_name("FILE");
    sub->add_flag("--strict", o->strict,
                  "report every departure from the Adobe 1.0 spec as a warning and fail on any");
    addInputFormat(*sub, o->inFormat);
    addLayout(*sub, "--in-layout", o->inLayout, "LUT images: the layout (default: detected)");
    addVerbosity(*sub, o->verbosity, "also say how each LUT image was read");
    addMovedOption(*sub, "--format",
                   "validate reads LUTs: name their format with --in-format (--format is the "
                   "output format of the commands that write)");
    sub->footer("Examples:\n"
                "  lutkit validate grade.cube\n"
                "  lutkit validate --strict *.cube            # fail on any departure from Adobe "
                "1.0\n"
                "  lutkit validate lut.txt --in-format cube");
    sub->callback([o, onParsed] { onParsed(*o); });
    return sub;
}

} // namespace lut::cli
