// SPDX-License-Identifier: Apache-2.0
// Sony Pictures Imageworks .spi3d: OCIO 2.1 reads it but its Baker cannot write it, so we
// write it ourselves ("SPILUT 1.0", "3 3", "N N N", then one "r g b  R G B" line per lattice
// point with its indices; no domain, no shaper) and read it back through OCIO like the rest.
#include "EncodedFormat.h"
#include "Formats.h"
#include "LutPrep.h"

#include "lut/Error.h"

#include <cstdio>

namespace lut::formats {

namespace {

class Spi3dFormat final : public EncodedFormat {
public:
    std::string name() const override { return "spi3d"; }
    std::string description() const override {
        return "Sony Imageworks .spi3d (written here, read via OpenColorIO)";
    }
    std::vector<std::string> extensions() const override { return {".spi3d"}; }
    bool canRead() const override { return false; }
    LutFile read(const std::string& path, const FormatOptions&) const override {
        throw Error(path + ": read it with the 'ocio' format");
    }
    std::string writeMemory(const LutFile& file, const std::string& path,
                            const FormatOptions& options, Diagnostics* diagnostics) const override {
        Diagnostics diags;
        const Lut3D lut = prepareUnitLut(file, options.size, path, diags);
        const int n = lut.size();
        std::string text = "SPILUT 1.0\n3 3\n" + std::to_string(n) + " " + std::to_string(n) + " " +
                           std::to_string(n) + "\n";
        text.reserve(text.size() + static_cast<std::size_t>(n) * n * n * 48);
        char buf[160];
        for (int r = 0; r < n; ++r)
            for (int g = 0; g < n; ++g)
                for (int b = 0; b < n; ++b) {
                    const glm::vec3 v = lut.at(r, g, b);
                    // %.9g: every float reads back as itself.
                    std::snprintf(buf, sizeof buf, "%d %d %d %.9g %.9g %.9g\n", r, g, b,
                                  double(v.x), double(v.y), double(v.z));
                    text += buf;
                }
        if (diagnostics)
            *diagnostics = std::move(diags);
        return text;
    }
};

} // namespace

std::unique_ptr<Format> makeSpi3dFormat() {
    return std::make_unique<Spi3dFormat>();
}

} // namespace lut::formats
