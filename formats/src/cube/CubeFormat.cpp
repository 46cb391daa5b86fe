// SPDX-License-Identifier: Apache-2.0
// The .cube format in the registry ("cube", extension ".cube"): the reader (CubeReader.cpp,
// CubeParser.h), the writer (CubeWriter.cpp) and the validator (CubeValidator.cpp) live beside it.
#include "Formats.h"

#include "lut/Limits.h"
#include "lut/formats/Cube.h"
#include "lut/io/Format.h"
#include "lut/ops/Resample.h"

namespace lut::formats {

namespace {

class CubeFormat final : public Format {
public:
    std::string name() const override { return "cube"; }
    std::string description() const override {
        return ".cube 1D/3D LUT, Adobe 1.0 and Resolve dialects (text)";
    }
    std::vector<std::string> extensions() const override { return {".cube"}; }
    // OpenColorIO's baker names (ociobakelut --format): the Resolve dialect writes a shaper as
    // LUT_1D + LUT_3D, the Iridas/Adobe one bakes it into the cube.
    std::vector<FormatAlias> aliases() const override {
        return {{"resolve_cube", kCubeDialectAttribute, "resolve"},
                {"iridas_cube", kCubeDialectAttribute, "adobe"}};
    }
    bool holdsShaper() const override { return true; }
    bool holdsShaperFor(const FormatOptions& options) const override {
        const auto d = options.attribute(kCubeDialectAttribute);
        return !(d && *d == "adobe");
    }
    // "# LUTKIT_PURPOSE smash", a comment line (CubeWriter.cpp).
    bool keepsPurpose(const std::string&, LutPurpose) const override { return true; }
    LutFile read(const std::string& path, const FormatOptions& options) const override {
        CubeReadOptions o;
        o.strict = options.strict;
        return readCube(path, o);
    }
    LutFile readMemory(std::string_view bytes, const std::string& name,
                       const FormatOptions& options) const override {
        if (bytes.size() > limits::kMaxLutFileBytes)
            throw LimitError(name + ": " + std::to_string(bytes.size()) +
                             " bytes, over the limit of " +
                             std::to_string(limits::kMaxLutFileBytes) + " for a LUT file");
        CubeReadOptions o;
        o.strict = options.strict;
        return parseCube(bytes, name, o);
    }
    // The text is made in memory (the editor's export preview asks for it at every adjustment).
    std::string writeMemory(const LutFile& lut, const std::string& name,
                            const FormatOptions& options, Diagnostics* diagnostics) const override {
        CubeWriteOptions wo;
        if (const auto d = options.attribute(kCubeDialectAttribute)) {
            if (*d == "resolve")
                wo.dialect = CubeWriteOptions::Dialect::Resolve;
            else if (*d == "adobe")
                wo.dialect = CubeWriteOptions::Dialect::Adobe;
            else
                throw Error(name + ": unknown .cube dialect '" + *d + "' (adobe or resolve)");
        }
        Diagnostics d;
        std::string text;
        if (options.size != 0 && lut.cube && options.size != lut.cube->size()) {
            LutFile resized = lut;
            resized.cube = resample(*lut.cube, options.size, Interpolation::Tetrahedral);
            text = writeCubeString(resized, &d, wo);
            d.insert(d.begin(), {Diagnostic::Severity::Info, name, 0, 0,
                                 "3D table resampled from " + std::to_string(lut.cube->size()) +
                                     "^3 to " + std::to_string(options.size) + "^3 (tetrahedral)"});
        } else {
            text = writeCubeString(lut, &d, wo);
        }
        for (auto& x : d)
            if (x.path.empty())
                x.path = name;
        if (diagnostics)
            *diagnostics = std::move(d);
        return text;
    }
};

} // namespace

std::unique_ptr<Format> makeCubeFormat() {
    return std::make_unique<CubeFormat>();
}

Diagnostic resolveCubeReadersWarning(const std::string& path, const std::string& kept,
                                     const std::string& tableAlone,
                                     const std::string& iridasWrites) {
    Diagnostic d;
    d.severity = Diagnostic::Severity::Warning;
    d.path = path;
    d.message = "a 1D shaper then a 3D table (DaVinci Resolve's .cube, which OpenColorIO reads "
                "too), kept because " +
                kept + (tableAlone.empty() ? std::string() : " (" + tableAlone + ")") +
                "; ffmpeg's lut3d, Photoshop's Color Lookup and most game engines read a 3D "
                "table alone: --format iridas_cube writes one (" +
                iridasWrites + ")";
    return d;
}

} // namespace lut::formats
