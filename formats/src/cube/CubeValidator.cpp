// SPDX-License-Identifier: Apache-2.0
// Validating a .cube file: the parser in strict mode, its departures and its one error returned
// as diagnostics instead of thrown.
#include "cube/CubeParser.h"

namespace lut::formats {

std::string describeCube(const LutFile& lut) {
    std::string s = lut.dialect.empty() ? "cube" : lut.dialect;
    if (lut.shaper && lut.cube)
        return s + " 1D " + std::to_string(lut.shaper->size()) + " + 3D, " +
               std::to_string(lut.cube->size()) + "^3";
    if (lut.cube)
        return s + " 3D, " + std::to_string(lut.cube->size()) + "^3";
    if (lut.shaper)
        return s + " 1D, " + std::to_string(lut.shaper->size());
    return s;
}

std::string CubeValidation::summary() const {
    return lut ? describeCube(*lut) : std::string();
}

CubeValidation validateCube(const std::string& path, bool strict) {
    CubeValidation v;
    Diagnostics diags;
    try {
        const FileBytes bytes = cube::readCubeFile(path);
        CubeReadOptions options;
        options.strict = strict;
        cube::CubeParser parser(bytes.view(), path, options, diags);
        v.lut = parser.parse();
        v.diagnostics = v.lut->diagnostics;
        v.departures = parser.departures();
    } catch (const ParseError& e) {
        v.diagnostics = std::move(diags);
        // what() is "path:line:col: message (found '...')"; keep the part after the place.
        std::string prefix = e.path();
        if (e.line() > 0) {
            prefix += ":" + std::to_string(e.line());
            if (e.column() > 0)
                prefix += ":" + std::to_string(e.column());
        }
        prefix += ": ";
        std::string what = e.what();
        if (what.compare(0, prefix.size(), prefix) == 0)
            what.erase(0, prefix.size());
        v.diagnostics.push_back(
            {Diagnostic::Severity::Error, e.path(), e.line(), e.column(), what});
    } catch (const Error& e) {
        v.diagnostics = std::move(diags);
        v.diagnostics.push_back({Diagnostic::Severity::Error, {}, 0, 0, e.what()});
    }
    v.ok = v.lut.has_value();
    if (strict)
        for (const auto& d : v.diagnostics)
            if (d.severity != Diagnostic::Severity::Info)
                v.ok = false;
    return v;
}

} // namespace lut::formats
