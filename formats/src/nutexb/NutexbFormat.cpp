// SPDX-License-Identifier: Apache-2.0
// nutexb: Smash Ultimate texture files, here the 3D colour-grading LUT (nutexb.md, byte-exact).
//
// The bytes (footer, tiling, reading, writing) are in NutexbCodec.{h,cpp} and BlockLinear.{h,cpp};
// this file is the registry adapter.
//
// Writing: 16^3 unless FormatOptions::size says otherwise (the game's LUTs are 16^3; the tiling
// is general, so any N works), block-linear unless the attribute nutexb:tiling is "linear", name
// from the attribute nutexb:name or color_grading_lut (lut/formats/Nutexb.h). A neutral 16^3 file
// is byte-identical to the reference the game tools write (SHA-256 in nutexb.md, asserted in
// tests).
#include "Formats.h"
#include "LutPrep.h"
#include "nutexb/NutexbCodec.h"

#include "lut/Error.h"
#include "lut/io/Format.h"
#include "lut/io/InputFile.h"
#include "lut/smash/SmashConstants.h"

namespace lut::formats {

namespace {

class NutexbFormat final : public Format {
public:
    std::string name() const override { return "nutexb"; }
    std::string description() const override {
        return "Smash Ultimate nutexb 3D texture (color_grading_lut.nutexb), RGBA8, block-linear "
               "tiled or linear";
    }
    std::vector<std::string> extensions() const override { return {".nutexb"}; }
    // The game's LUTs are 16^3; FormatOptions::size still writes any other N.
    int fixedSize() const override { return kSmashLutSize; }
    int storedBitDepth() const override { return 8; }
    // A .nutexb is the game's LUT by its format: an edit written as one reads back as the game's.
    bool keepsPurpose(const std::string&, LutPurpose purpose) const override {
        return purpose == LutPurpose::Smash;
    }

    LutFile read(const std::string& path, const FormatOptions&) const override {
        // Nothing larger than a 256^3 volume is read; the footer's sizes are then checked against
        // the bytes the file holds before anything is sized from them.
        const FileBytes bytes =
            readFileBytes(path, static_cast<std::size_t>(nutexb::maxFileSize()));
        return nutexb::readBytes(bytes.view(), path);
    }
    LutFile readMemory(std::string_view bytes, const std::string& name,
                       const FormatOptions&) const override {
        return nutexb::readBytes(bytes, name);
    }
    // The header is a footer: any bytes may start a volume, up to a 256^3 one.
    std::uint64_t maxStreamBytes(std::string_view) const override { return nutexb::maxFileSize(); }

    // The bytes are made in memory (the editor's export preview asks for them at every
    // adjustment).
    std::string writeMemory(const LutFile& file, const std::string& name,
                            const FormatOptions& options, Diagnostics* diagnostics) const override {
        Diagnostics diags;
        if (options.bitDepth != 0 && options.bitDepth != 8)
            diags.push_back(makeDiagnostic(Diagnostic::Severity::Warning, name,
                                           "nutexb stores 8-bit values: bit depth " +
                                               std::to_string(options.bitDepth) + " ignored"));
        if (options.dither)
            diags.push_back(makeDiagnostic(Diagnostic::Severity::Warning, name,
                                           "nutexb values are rounded to nearest: dither ignored"));
        const int size = options.size > 0 ? options.size : kSmashLutSize;
        const Lut3D lut = prepareUnitLut(file, size, name, diags);
        std::size_t clamped = 0;
        const std::string tiling =
            options.attribute(nutexb::kTilingAttribute).value_or("block-linear");
        if (tiling != "block-linear" && tiling != "linear")
            throw Error(name + ": " + nutexb::kTilingAttribute + " is '" + tiling +
                        "', expected block-linear or linear");
        std::string bytes =
            nutexb::writeBytes(lut, options.attribute(nutexb::kNameAttribute).value_or(""),
                               tiling == "block-linear", &clamped);
        addClampDiagnostic(clamped, 8, name, diags);
        addQuantizationDiagnostic(lut, 8, name, diags);
        if (diagnostics)
            *diagnostics = std::move(diags);
        return bytes;
    }
};

} // namespace

std::unique_ptr<Format> makeNutexbFormat() {
    return std::make_unique<NutexbFormat>();
}

} // namespace lut::formats
