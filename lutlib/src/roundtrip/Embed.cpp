// SPDX-License-Identifier: Apache-2.0
// Embedding a neutral LUT patch and its marker frame into a screenshot; see lut/roundtrip/Embed.h
// and docs/roundtrip.md.
#include "lut/roundtrip/Embed.h"

#include "lut/Error.h"
#include "lut/Lut3D.h"
#include "lut/roundtrip/LutDigest.h"
#include "roundtrip/MarkerFrame.h"

#include <cmath>
#include <string>

namespace lut {

const char* toString(PatchCorner c) {
    switch (c) {
    case PatchCorner::TopLeft:
        return "top-left";
    case PatchCorner::TopRight:
        return "top-right";
    case PatchCorner::BottomLeft:
        return "bottom-left";
    case PatchCorner::BottomRight:
        return "bottom-right";
    }
    return "?";
}

PatchCorner parseCorner(std::string_view name) {
    if (name == "top-left")
        return PatchCorner::TopLeft;
    if (name == "top-right")
        return PatchCorner::TopRight;
    if (name == "bottom-left")
        return PatchCorner::BottomLeft;
    if (name == "bottom-right")
        return PatchCorner::BottomRight;
    throw Error("unknown corner '" + std::string(name) +
                "' (expected top-left, top-right, bottom-left or bottom-right)");
}

LutLayout defaultPatchLayout(int size) {
    const int level = static_cast<int>(std::lround(std::sqrt(static_cast<double>(size))));
    return level * level == size && level >= 3 ? LutLayout::Hald : LutLayout::Pilot;
}

PatchLattice effectiveLattice(const EmbedOptions& o) {
    const PatchLattice chosen =
        o.lattice ? *o.lattice
                  : (o.target == LutPurpose::Raw ? PatchLattice::Uniform : PatchLattice::Smash);
    if (chosen == PatchLattice::Smash && o.originalLut)
        return PatchLattice::SmashStage;
    if (chosen == PatchLattice::SmashStage && !o.originalLut)
        return PatchLattice::Smash;
    return chosen;
}

namespace {

// The frame's position along one axis: `margin` from the near edge (or the far one), moved
// inwards until the patch's first entry (2 cells in) sits on the JPEG grid when asked and possible.
int framePosition(int imageSize, int frameSize, int margin, int cell, bool far, bool align) {
    int pos = far ? imageSize - margin - frameSize : margin;
    if (!align)
        return pos;
    for (int shift = 0; shift < kJpegGrid; ++shift) {
        const int p = far ? pos - shift : pos + shift;
        if (p < 0 || p + frameSize > imageSize)
            break;
        if ((p + 2 * cell) % kJpegGrid == 0)
            return p;
    }
    return pos;
}

} // namespace

PatchPlacement embedPatch(const ImageView& image, const EmbedOptions& o) {
    if (o.bitDepth != 8 && o.bitDepth != 16 && o.bitDepth != 32)
        throw Error("embed: bit depth must be 8, 16 or 32, not " + std::to_string(o.bitDepth));
    if (o.margin < 0)
        throw Error("embed: negative margin");
    if (o.originalLut && o.target == LutPurpose::Raw)
        throw Error("embed: an original LUT is for the smash target (a raw LUT does not depend on "
                    "the stage's LUT)");
    if (o.originalLut && o.originalLut->empty())
        throw Error("embed: the original LUT is empty");
    const PatchLattice lattice = effectiveLattice(o);
    const int size = lattice == PatchLattice::Smash        ? kSmashLatticeSize
                     : lattice == PatchLattice::SmashStage ? kSmashLutSize
                                                           : o.size;
    const LutLayout layout = o.layout ? *o.layout : defaultPatchLayout(size);
    int scale = o.scale > 0 ? o.scale : kDefaultPatchScale;
    int fwPx = 0, fhPx = 0;
    patchFrameSize(layout, size, scale, fwPx, fhPx);
    while (o.scale == 0 && scale > 1 &&
           (static_cast<long long>(fwPx) + o.margin > image.width ||
            static_cast<long long>(fhPx) + o.margin > image.height))
        patchFrameSize(layout, size, --scale, fwPx, fhPx);
    if (static_cast<long long>(fwPx) + o.margin > image.width ||
        static_cast<long long>(fhPx) + o.margin > image.height)
        throw Error("embed: the " + std::to_string(size) + "^3 " + toString(layout) +
                    " patch at scale " + std::to_string(scale) + " needs " +
                    std::to_string(fwPx + o.margin) + "x" + std::to_string(fhPx + o.margin) +
                    " pixels with its margin, the screenshot is " + std::to_string(image.width) +
                    "x" + std::to_string(image.height) + " (use a smaller --scale or --size)");
    PatchPlacement p;
    p.lattice = lattice;
    p.layout = layout;
    p.size = size;
    p.scale = scale;
    p.cell = scale;
    p.bitDepth = o.bitDepth;
    p.frameWidth = fwPx;
    p.frameHeight = fhPx;
    p.target = o.target;
    if (o.originalLut)
        p.stageDigest = lutDigest(*o.originalLut);
    const bool right = o.corner == PatchCorner::TopRight || o.corner == PatchCorner::BottomRight;
    const bool bottom = o.corner == PatchCorner::BottomLeft || o.corner == PatchCorner::BottomRight;
    p.frameX = framePosition(image.width, fwPx, o.margin, scale, right, o.alignToJpegGrid);
    p.frameY = framePosition(image.height, fhPx, o.margin, scale, bottom, o.alignToJpegGrid);

    const int k = scale;
    int cw = 0, ch = 0;
    detail::patchCells(layout, size, cw, ch);
    const int fw = cw + 4, fh = ch + 4;
    auto fillCell = [&](int cx, int cy, float v) {
        for (int y = 0; y < k; ++y)
            for (int x = 0; x < k; ++x) {
                float* px = image.pixel(p.frameX + cx * k + x, p.frameY + cy * k + y);
                px[0] = px[1] = px[2] = v;
                px[3] = 1.0f;
            }
    };
    // Outer ring: the checkerboard; inner ring: the header, repeated.
    for (int cy = 0; cy < fh; ++cy)
        for (int cx = 0; cx < fw; ++cx)
            if (cx == 0 || cy == 0 || cx == fw - 1 || cy == fh - 1)
                fillCell(cx, cy, ((cx + cy) & 1) ? 0.0f : 1.0f);
    detail::MarkerHeader header;
    header.lattice = lattice;
    header.bitDepth = o.bitDepth;
    header.layout = layout;
    header.size = size;
    header.scale = scale;
    header.target = p.target;
    header.stageDigest = p.stageDigest;
    const auto bits = detail::headerBits(header);
    const int headerLength = detail::headerBitCount(header.version);
    const auto ring = detail::innerRing(fw, fh);
    for (std::size_t i = 0; i < ring.size(); ++i)
        fillCell(ring[i].first, ring[i].second, bits[i % headerLength] ? 1.0f : 0.0f);

    Lut3D neutral(size);
    if (lattice == PatchLattice::SmashStage) {
        neutral = stagePatchInputs(*o.originalLut, size, o.bitDepth);
    } else {
        for (int b = 0; b < size; ++b)
            for (int g = 0; g < size; ++g)
                for (int r = 0; r < size; ++r)
                    neutral.at(r, g, b) = glm::vec3(patchInputValue(lattice, r, size, o.bitDepth),
                                                    patchInputValue(lattice, g, size, o.bitDepth),
                                                    patchInputValue(lattice, b, size, o.bitDepth));
    }
    drawLut(neutral, layout, image, p.patchX(), p.patchY(), k);
    return p;
}

} // namespace lut
