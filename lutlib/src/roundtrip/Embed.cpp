// Embedding a neutral LUT patch and its marker frame into a screenshot; see lut/roundtrip/Embed.h
// and docs/roundtrip.md.
#include "lut/roundtrip/Embed.h"

#include "lut/Error.h"
#include "lut/Lut3D.h"
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

PatchPlacement embedPatch(const ImageView& image, const EmbedOptions& o) {
    if (o.bitDepth != 8 && o.bitDepth != 16 && o.bitDepth != 32)
        throw Error("embed: bit depth must be 8, 16 or 32, not " + std::to_string(o.bitDepth));
    if (o.margin < 0)
        throw Error("embed: negative margin");
    const int size = o.lattice == PatchLattice::Smash ? kSmashLatticeSize : o.size;
    const LutLayout layout = o.layout ? *o.layout : defaultPatchLayout(size);
    int fwPx = 0, fhPx = 0;
    patchFrameSize(layout, size, o.scale, fwPx, fhPx);
    if (static_cast<long long>(fwPx) + o.margin > image.width ||
        static_cast<long long>(fhPx) + o.margin > image.height)
        throw Error("embed: the " + std::to_string(size) + "^3 " + toString(layout) +
                    " patch at scale " + std::to_string(o.scale) + " needs " +
                    std::to_string(fwPx + o.margin) + "x" + std::to_string(fhPx + o.margin) +
                    " pixels with its margin, the screenshot is " + std::to_string(image.width) +
                    "x" + std::to_string(image.height) + " (use a smaller --size or --scale)");
    PatchPlacement p;
    p.lattice = o.lattice;
    p.layout = layout;
    p.size = size;
    p.scale = o.scale;
    p.cell = o.scale;
    p.bitDepth = o.bitDepth;
    p.frameWidth = fwPx;
    p.frameHeight = fhPx;
    const bool right = o.corner == PatchCorner::TopRight || o.corner == PatchCorner::BottomRight;
    const bool bottom = o.corner == PatchCorner::BottomLeft || o.corner == PatchCorner::BottomRight;
    p.frameX = right ? image.width - o.margin - fwPx : o.margin;
    p.frameY = bottom ? image.height - o.margin - fhPx : o.margin;

    const int k = o.scale;
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
    header.lattice = o.lattice;
    header.bitDepth = o.bitDepth;
    header.layout = layout;
    header.size = size;
    header.scale = o.scale;
    const auto bits = detail::headerBits(header);
    const auto ring = detail::innerRing(fw, fh);
    for (std::size_t i = 0; i < ring.size(); ++i)
        fillCell(ring[i].first, ring[i].second, bits[i % detail::kHeaderBits] ? 1.0f : 0.0f);

    Lut3D neutral(size);
    for (int b = 0; b < size; ++b)
        for (int g = 0; g < size; ++g)
            for (int r = 0; r < size; ++r)
                neutral.at(r, g, b) = glm::vec3(patchInputValue(o.lattice, r, size, o.bitDepth),
                                                patchInputValue(o.lattice, g, size, o.bitDepth),
                                                patchInputValue(o.lattice, b, size, o.bitDepth));
    drawLut(neutral, layout, image, p.patchX(), p.patchY(), k);
    return p;
}

} // namespace lut
