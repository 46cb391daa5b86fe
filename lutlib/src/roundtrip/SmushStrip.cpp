// SPDX-License-Identifier: Apache-2.0
// Smush-LUT's .lut.png strip; see lut/roundtrip/SmushStrip.h.
#include "lut/roundtrip/SmushStrip.h"

#include "lut/Error.h"
#include "lut/io/Layout.h"

#include <cmath>
#include <string>

namespace lut {

namespace {
// The default stage LUT's values along each axis, as Smush-LUT's first versions drew them.
constexpr int kAxisBytes[kSmushStripSize] = {0,   15,  30,  46,  64,  82,  101, 121,
                                             140, 158, 176, 193, 209, 224, 240, 255};
} // namespace

std::vector<float> smushStripAxis() {
    std::vector<float> axis(kSmushStripSize);
    for (int i = 0; i < kSmushStripSize; ++i)
        axis[i] = static_cast<float>(kAxisBytes[i]) / 255.0f;
    return axis;
}

bool isSmushStripName(std::string_view name) {
    const std::size_t slash = name.find_last_of("/\\\\");
    const std::string_view base = slash == std::string_view::npos ? name : name.substr(slash + 1);
    return base.find(".lut.") != std::string_view::npos;
}

PatchReading readSmushStrip(const ImageView& img) {
    const int n = kSmushStripSize;
    if (img.width < n * n || img.height < n)
        throw Error("a Smush-LUT strip needs at least " + std::to_string(n * n) + "x" +
                    std::to_string(n) + " pixels, the image is " + std::to_string(img.width) + "x" +
                    std::to_string(img.height));
    PatchReading out;
    PatchPlacement& p = out.placement;
    p.lattice = PatchLattice::SmushLegacy;
    p.layout = LutLayout::Pilot;
    p.size = n;
    p.scale = p.cell = 1;
    p.bitDepth = 8;
    p.frameX = p.frameY = -2; // no frame: patchX() and patchY() are 0
    p.frameWidth = n * n;
    p.frameHeight = n;
    p.headerVersion = 0;
    p.target = LutPurpose::Smash;
    out.values = lutFromImage(img, LutLayout::Pilot, n);
    out.axis = smushStripAxis();
    out.blockSpread = Lut3D(n);
    bool all8 = true;
    for (const auto& v : out.values.entries())
        for (int c = 0; c < 3; ++c) {
            const double x = static_cast<double>(v[c]) * 255.0;
            all8 = all8 && std::fabs(x - std::round(x)) < 0.02;
        }
    out.storedBits = all8 ? 8 : 32;
    return out;
}

} // namespace lut
