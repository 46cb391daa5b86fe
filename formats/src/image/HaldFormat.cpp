// SPDX-License-Identifier: Apache-2.0
// Hald CLUT images (ImageMagick, G'MIC, FFmpeg haldclut, lutgen): level L, an L^3 x L^3 picture
// holding an N^3 LUT with N = L^2, linear index i = r + N*g + N^2*b at x = i mod L^3,
// y = i div L^3 (strip-layouts.md). Values are the stored 8/16-bit or float samples.
//
// "hald" shares .png/.tif/.exr with the "strip" format, which the registry picks by extension;
// so "hald" claims no extension and is reached by --format hald, while "strip" turns to the same
// code for --layout hald and for square images (the only size Hald has, and no strip layout
// has). Sizes that are not a square are written at the next larger square (33 -> 36).
#include "Formats.h"
#include "image/LutImage.h"
#include "imageio/ImageHeaderChecks.h"

#include "lut/Error.h"

#include <cmath>
#include <string>

namespace lut::formats {

int haldSizeFor(int size) {
    int level =
        static_cast<int>(std::ceil(std::sqrt(static_cast<double>(size < 4 ? 4 : size)) - 1e-9));
    if (level < 2)
        level = 2;
    if (level > kMaxHaldLevel)
        level = kMaxHaldLevel;
    return level * level;
}

int haldLevelOf(int size) {
    int level = static_cast<int>(std::floor(std::sqrt(static_cast<double>(size)) + 1e-9));
    return level < 1 ? 1 : level;
}

std::string haldSizeText(int size) {
    const int level = haldLevelOf(size);
    const int edge = level * level * level;
    return std::to_string(size) + "^3 (Hald level " + std::to_string(level) + ", " +
           std::to_string(edge) + "x" + std::to_string(edge) + ")";
}

namespace {

class HaldFormat final : public Format {
public:
    std::string name() const override { return "hald"; }
    std::string description() const override {
        return "Hald CLUT image (level L: L^3 x L^3 pixels, N = L^2), PNG/TIFF 8/16-bit or float "
               "EXR";
    }
    std::vector<std::string> extensions() const override { return {}; }
    bool keepsPurpose(const std::string& path, LutPurpose) const override {
        return lutImageKeepsPurpose(path);
    }

    LutFile read(const std::string& path, const FormatOptions& options) const override {
        checkLayout(path, options);
        return readLutImage(path, options, LutLayout::Hald);
    }
    std::uint64_t maxStreamBytes(std::string_view head) const override {
        return imageStreamBytes(head);
    }
    Diagnostics write(const std::string& path, const LutFile& lut,
                      const FormatOptions& options) const override {
        checkLayout(path, options);
        return writeLutImage(path, lut, options, LutLayout::Hald);
    }
    LutFile readMemory(std::string_view bytes, const std::string& name,
                       const FormatOptions& options) const override {
        checkLayout(name, options);
        return readLutImageMemory(bytes, name, options, LutLayout::Hald);
    }
    std::string writeMemory(const LutFile& lut, const std::string& name,
                            const FormatOptions& options, Diagnostics* diagnostics) const override {
        checkLayout(name, options);
        return writeLutImageMemory(name, lut, options, LutLayout::Hald, diagnostics);
    }

private:
    static void checkLayout(const std::string& path, const FormatOptions& options) {
        if (options.layout && *options.layout != LutLayout::Hald)
            throw Error(path + ": the hald format stores the hald layout only, not '" +
                        toString(*options.layout) + "'");
    }
};

} // namespace

std::unique_ptr<Format> makeHaldFormat() {
    return std::make_unique<HaldFormat>();
}

} // namespace lut::formats
