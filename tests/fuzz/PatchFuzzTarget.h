// SPDX-License-Identifier: Apache-2.0
#pragma once
// Fuzz target for the embed/extract patch finder: findPatch, readPatch and extractLut (raw target;
// smash and the one-call form when byte 0 asks, see extractChecked) on
//   byte 0 even: an image file (byte 1: extension, rest: the file), read as extract reads it;
//   byte 0 odd:  a screenshot with a real patch embedded (bytes 1-4: width, height, background,
//                embed options), then mutated by the rest of the bytes, 4 at a time
//                (x, y, what, value): set a channel, add to it, copy a pixel from a shifted place,
//                or blank a run of pixels. The image is handed over in memory.
// Contract: a found patch is inside the image; extractLut returns a finite LUT or throws
// lut::Error; nothing else escapes.
#include "FuzzTargets.h"

#include "lut/formats/ImageIO.h"
#include "lut/roundtrip/Embed.h"
#include "lut/roundtrip/Extract.h"
#include "lut/roundtrip/PatchFinder.h"
#include "lut/roundtrip/PatchReader.h"

namespace lut::fuzz {

// flags bit 1: also the smash target (slow: it fits the game's display); bit 2: also the
// one-call form that finds the patch again.
inline void extractChecked(const Image& image, std::uint8_t flags) {
    const FindResult found = findPatch(image.view());
    if (found.status == FindStatus::Found) {
        const PatchPlacement& p = found.placement;
        invariant(p.frameX >= 0 && p.frameY >= 0 && p.frameX + p.frameWidth <= image.width() &&
                      p.frameY + p.frameHeight <= image.height(),
                  "a found patch's frame lies outside the image");
        try {
            const PatchReading reading = readPatch(image.view(), p);
            for (LutPurpose t : {LutPurpose::Raw, LutPurpose::Smash}) {
                if (t == LutPurpose::Smash && !(flags & 2))
                    continue;
                lut::ExtractOptions o;
                o.target = t;
                o.nthreads = 1;
                const ExtractResult r = extractLut(reading, o);
                for (const auto& v : r.lut.entries())
                    for (int c = 0; c < 3; ++c)
                        invariant(std::isfinite(v[c]), "extracted LUT has a non-finite entry");
            }
        } catch (const lut::Error&) {
        }
    }
    if (!(flags & 4))
        return;
    // The one-call form finds again on its own.
    try {
        lut::ExtractOptions o;
        o.nthreads = 1;
        (void)extractLut(image.view(), o);
    } catch (const lut::Error&) {
    }
}

inline Outcome runPatch(const std::uint8_t* data, std::size_t size) {
    if (size < 5)
        return Outcome::Refused;
    if ((data[0] & 1) == 0) {
        static const char* const kExtensions[] = {".png", ".tif", ".bmp", ".tga", ".jpg", ".exr"};
        const std::string path =
            writeScratch(std::string("patch") + kExtensions[data[1] % 6], data + 2, size - 2);
        try {
            const formats::ImageInfo info = formats::readImageInfo(path);
            if (static_cast<std::uint64_t>(info.width) * info.height > (1u << 20))
                return Outcome::Accepted;
            const formats::LoadedImage img = formats::readImage(path);
            extractChecked(img.image, data[0]);
        } catch (const lut::Error&) {
            return Outcome::Refused;
        }
        return Outcome::Accepted;
    }
    // A real patch: the game-display lattice (296x32 at scale 2) or a small uniform one.
    EmbedOptions eo;
    const std::uint8_t opt = data[4];
    eo.lattice = (opt & 1) ? PatchLattice::Uniform : PatchLattice::Smash;
    if (eo.lattice == PatchLattice::Uniform)
        eo.size = 2 + (opt >> 1) % 7; // 2..8
    eo.scale = 1 + ((opt >> 4) & 1);
    eo.corner = static_cast<PatchCorner>((opt >> 5) & 3);
    eo.margin = (opt >> 7) ? 0 : 4;
    const int width = 310 + data[1] % 64, height = 48 + data[2] % 48;
    Image image(width, height, data[3] / 255.0f);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.pixel(x, y)[3] = 1.0f;
    try {
        (void)embedPatch(image.view(), eo);
    } catch (const lut::Error&) {
        return Outcome::Refused; // does not fit
    }
    // Mutations, 4 bytes each.
    for (std::size_t i = 5; i + 4 <= size; i += 4) {
        const int x = data[i] * width / 256, y = data[i + 1] * height / 256;
        const int what = data[i + 2] & 3, c = (data[i + 2] >> 2) % 3;
        const float value = data[i + 3] / 255.0f;
        float* px = image.pixel(x, y);
        switch (what) {
        case 0:
            px[c] = value;
            break;
        case 1:
            px[c] += (data[i + 3] - 128) / 255.0f;
            break;
        case 2: {
            const int sx = (x + data[i + 3]) % width, sy = (y + (data[i + 3] >> 4)) % height;
            const float* src = image.pixel(sx, sy);
            std::copy(src, src + 4, px);
            break;
        }
        default:
            for (int k = 0; k < data[i + 3] % 32 && x + k < width; ++k)
                image.pixel(x + k, y)[c] = data[i + 2] >= 128 ? 1.0f : 0.0f;
            break;
        }
    }
    extractChecked(image, data[0]);
    return Outcome::Accepted;
}

} // namespace lut::fuzz
