// lutkit validate: parse LUT files and report problems with file:line:col. .cube files get the
// full treatment (lut::formats::validateCube: strict departures from Adobe 1.0); other formats are
// read through the registry and reported ok or failed.
#include "cmd_validate.h"

#include "Commands.h"

#include "lut/Error.h"
#include "lut/formats/Cube.h"
#include "lut/formats/Registry.h"
#include "lut/io/FileNames.h"
#include "lut/io/Format.h"

#include <iostream>

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
    const bool isCube = o.format == "cube" || (o.format.empty() && extensionOf(path) == ".cube");
    if (isCube) {
        const formats::CubeValidation v = formats::validateCube(path, o.strict);
        for (const Diagnostic& d : v.diagnostics) {
            if (d.severity == Diagnostic::Severity::Error) {
                // Errors without a place already name the file in their message.
                std::cerr << (d.path.empty() ? "lutkit: error: " + d.message : d.str()) << "\n";
                continue;
            }
            std::cout << d.str() << "\n";
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
        const LutFile f = formats::readLut(path, options, o.format);
        bool ok = true;
        for (const Diagnostic& d : f.diagnostics) {
            std::cout << d.str() << "\n";
            if (o.strict && d.severity != Diagnostic::Severity::Info)
                ok = false;
        }
        if (ok)
            std::cout << path << ": ok (" << describe(f) << ")\n";
        return ok;
    } catch (const Error& e) {
        std::cerr << "lutkit: error: " << e.what() << "\n";
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

} // namespace lut::cli
