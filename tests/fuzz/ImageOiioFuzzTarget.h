// SPDX-License-Identifier: Apache-2.0
#pragma once
// Fuzz target for the images OpenImageIO reads on lutkit's behalf (issue 29): TIFF, JPEG, HDR,
// DPX, PSD, GIF, tiled and multi-part OpenEXR, IFF, WebP; and BMP and TGA, which lutkit reads
// natively since (BmpCodec.cpp, TgaCodec.cpp). The input is the file itself (seeds are real
// files: tests/fuzz/make_image_seeds.sh), named by what its first bytes say it is (.tga when they
// say nothing: TGA has no magic number). Every path a command takes is run:
//   - the pre-open rule and the header (readImageInfo, as preview and the editor ask first);
//   - apply: every part streamed through a LUT into a scratch file of the same format where
//     lutkit writes it (else TIFF), tiles kept, codec errors checked after every read;
//   - preview: the first image as a float frame (readImage).
// Images over 1 megapixel are only looked at, not decoded: how much memory a declared size may
// take is the budget's (--max-memory) and the pre-open rule's, checked on the header alone.
// Contract: lut::Error or a result. A file apply accepts through OpenImageIO has every row:
// OpenImageIO's own whole read of it (ImageInput::read_image, errors checked the same way) must
// succeed too and agree on the size, so no missing pixel passes as grey or black (the oracle is
// OpenImageIO's read, not lutkit's streaming, tiling or error handling).
#include "FuzzTargets.h"

#include "ImageFuzzTarget.h"

#include "lut/formats/ApplyImage.h"
#include "lut/formats/ImageIO.h"
#include "lut/interp/PixelChain.h"
#include "lut/io/OutputPolicy.h"

#include <OpenImageIO/imageio.h>

#include <cstring>
#include <memory>

namespace lut::fuzz {

// The extension OpenImageIO's reader is picked by, from the file's magic number.
inline std::string imageExtensionFor(const std::uint8_t* data, std::size_t size) {
    auto starts = [&](const char* magic, std::size_t n) {
        return size >= n && std::memcmp(data, magic, n) == 0;
    };
    if (starts("II*\0", 4) || starts("MM\0*", 4) || starts("II+\0", 4) || starts("MM\0+", 4))
        return ".tif";
    if (starts("\xff\xd8\xff", 3))
        return ".jpg";
    if (starts("BM", 2))
        return ".bmp";
    if (starts("#?", 2))
        return ".hdr";
    if (starts("SDPX", 4) || starts("XPDS", 4))
        return ".dpx";
    if (starts("8BPS", 4))
        return ".psd";
    if (starts("GIF", 3))
        return ".gif";
    if (starts("\x76\x2f\x31\x01", 4))
        return ".exr";
    if (starts("FOR4", 4))
        return ".iff";
    if (starts("RIFF", 4))
        return ".webp";
    if (starts("\x89PNG", 4))
        return ".png";
    return ".tga";
}

// OpenImageIO's own read of the whole first image: false when it fails or reports an error.
inline bool oiioReadsWhole(const std::string& path, int& width, int& height) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        (void)OIIO::geterror();
        return false;
    }
    const OIIO::ImageSpec& spec = in->spec();
    width = spec.width;
    height = spec.height;
    std::vector<float> pixels(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
    const bool ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data());
    const bool error = in->has_error();
    (void)in->geterror();
    return ok && !error;
}

inline Outcome runImageOiio(const std::uint8_t* data, std::size_t size) {
    if (size < 4)
        return Outcome::Refused;
    const std::string ext = imageExtensionFor(data, size);
    const std::string path = writeScratch("oiio" + ext, data, size);
    const std::string written = (scratchDir() / ("out" + ext)).string();
    try {
        const formats::ImageInfo info = formats::readImageInfo(path);
        invariant(info.width > 0 && info.height > 0 && info.channels > 0,
                  "readImageInfo accepted an image without pixels");
        invariant(static_cast<std::uint64_t>(info.width) * info.height <= limits::kMaxImagePixels,
                  "readImageInfo accepted an image over the pixel limit");
        if (static_cast<std::uint64_t>(info.width) * info.height * info.subimages > (1u << 20))
            return Outcome::Accepted;
    } catch (const lut::Error&) {
        return Outcome::Refused;
    }
    bool applied = false;
    formats::ApplyImageReport report;
    try {
        PixelChain chain;
        chain.setLut(fuzzGradingLut(), Interpolation::Tetrahedral);
        formats::ApplyImageOptions o;
        o.threads = 1;
        const bool writable = ext == ".tif" || ext == ".exr" || ext == ".jpg" || ext == ".bmp" ||
                              ext == ".tga" || ext == ".hdr" || ext == ".dpx" || ext == ".png";
        const std::string out = writable ? written : (scratchDir() / "out.tif").string();
        report = formats::applyToImage(path, checkOutput(out, ExistingOutput::Replace), chain, o);
        applied = true;
    } catch (const lut::Error&) {
    }
    // BMP and TGA are read natively (BmpCodec.cpp, TgaCodec.cpp, which check their own data):
    // OpenImageIO is no oracle of theirs (it refuses ImageMagick's RLE BMPs, and writes past its
    // rows on an RLE8 BMP with a grey map), so it is not run on them.
    const bool native = ext == ".bmp" || ext == ".tga";
    if (applied && !native) {
        int w = 0, h = 0;
        invariant(oiioReadsWhole(path, w, h),
                  "apply accepted a file OpenImageIO's own whole read refuses (missing pixels)");
        invariant(w == report.input.width && h == report.input.height,
                  "apply's size differs from OpenImageIO's");
    }
    try {
        const formats::LoadedImage img = formats::readImage(path);
        invariant(img.image.width() == img.info.width && img.image.height() == img.info.height,
                  "readImage's pixels differ from its info");
    } catch (const lut::Error&) {
        return applied ? Outcome::Accepted : Outcome::Refused;
    }
    return Outcome::Accepted;
}

} // namespace lut::fuzz
