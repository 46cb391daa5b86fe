// SPDX-License-Identifier: Apache-2.0
// Makes a neutral (identity) LUT and writes it for two games: as Smash Ultimate's
// color_grading_lut.nutexb and as a 256x16 LUT strip in Unreal's layout, ready to grade in an
// image editor.
//   api_neutral_lut OUT_DIR
// Checks, exiting 1 on the first failure: both files read back as an exact identity (a 16^3
// neutral LUT's entries i/15 are whole 8-bit codes, 17 * i, so nothing may be lost), and the strip
// is 256x16 pixels.
#include "lut/Lut3D.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"

#include <cstdio>
#include <exception>
#include <string>

namespace {

int fail(const std::string& what) {
    std::fprintf(stderr, "api_neutral_lut: %s\n", what.c_str());
    return 1;
}

int run(const std::string& outDir) {
    lut::LutFile neutral;
    neutral.cube = lut::Lut3D::identity(16);

    const std::string nutexb = outDir + "/color_grading_lut.nutexb";
    lut::formats::writeLut(nutexb, neutral); // the format comes from the extension

    // Images can hold a LUT in several layouts; name the one the target engine reads.
    lut::FormatOptions strip;
    strip.layout = lut::parseLayout("unreal");
    const std::string png = outDir + "/neutral_unreal.png";
    lut::formats::writeLut(png, neutral, strip);

    for (const auto& [path, options] : {std::pair{nutexb, lut::FormatOptions{}}, {png, strip}}) {
        const lut::LutFile back = lut::formats::readLut(path, options);
        const lut::Lut3D table = back.toLut3D();
        if (table.size() != 16 || !table.isIdentity(0.0f))
            return fail(path + " does not read back as the neutral 16^3 LUT (largest deviation " +
                        std::to_string(table.maxDeviationFromIdentity()) + ")");
        std::printf("%s: neutral %d^3 (%s)\n", path.c_str(), table.size(), back.format.c_str());
    }
    const lut::formats::ImageInfo info = lut::formats::readImageInfo(png);
    if (info.width != 256 || info.height != 16)
        return fail(png + " is " + std::to_string(info.width) + "x" + std::to_string(info.height) +
                    ", expected 256x16");
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: api_neutral_lut OUT_DIR\n");
        return 2;
    }
    try {
        return run(argv[1]);
    } catch (const std::exception& e) {
        return fail(e.what());
    }
}
