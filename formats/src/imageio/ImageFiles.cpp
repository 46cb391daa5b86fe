// SPDX-License-Identifier: Apache-2.0
// Image file names and the write policy: see lut/formats/ImageFiles.h. No codec here (names
// only), so callers do not open anything to ask.
#include "lut/formats/ImageFiles.h"

#include "imageio/ImageCodec.h"

#include "lut/io/FileNames.h"

#include <algorithm>
#include <set>

namespace lut::formats {

namespace {

std::string upper(std::string s) {
    for (auto& c : s)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

bool onlyEightBit(const std::string& f) {
    return f == "jpeg" || f == "bmp" || f == "gif" || f == "targa" || f == "tga" || f == "webp";
}
bool holdsSixteen(const std::string& f) {
    return f == "png" || f == "tiff" || f == "pnm" || f == "dpx" || f == "psd" || f == "sgi";
}
bool holdsFloat(const std::string& f) {
    return f == "openexr" || f == "tiff" || f == "hdr" || f == "pfm";
}
int maxChannels(const std::string& f) {
    if (f == "openexr" || f == "tiff")
        return 1 << 10;
    if (f == "jpeg" || f == "pnm" || f == "hdr")
        return 3;
    return 4;
}

} // namespace

bool isImageExtension(const std::string& path) {
    static const std::set<std::string> exts = {".png", ".jpg", ".jpeg", ".tif",  ".tiff", ".exr",
                                               ".bmp", ".tga", ".hdr",  ".webp", ".dpx",  ".psd",
                                               ".gif", ".ppm", ".pgm",  ".pnm"};
    return exts.count(extensionOf(path)) > 0;
}

bool canHoldAlpha(const std::string& pathOrFormat) {
    const std::string f = canonicalImageFormat(pathOrFormat);
    // GIF has a transparent colour, but OpenImageIO 2.4's GIF writer writes every pixel opaque
    // (gifoutput.cpp, measured in tests/robust/write_matrix.py): alpha is dropped, and said so.
    return f != "jpeg" && f != "bmp" && f != "hdr" && f != "pnm" && f != "gif";
}

ImageWriteOptions renderedImageWriteOptions(const ImageInfo& in, const std::string& outPath,
                                            int requestedBitDepth) {
    ImageWriteOptions w;
    const std::string f = canonicalImageFormat(outPath);
    w.alpha = (in.channels == 2 || in.channels >= 4) && canHoldAlpha(outPath);
    if (requestedBitDepth) {
        w.bitDepth = requestedBitDepth;
    } else if (!in.isFloat && (in.bitDepth == 8 || in.bitDepth == 16)) {
        w.bitDepth = in.bitDepth == 16 && (onlyEightBit(f) || (!holdsSixteen(f) && !holdsFloat(f)))
                         ? 8
                         : in.bitDepth;
    } else if (holdsFloat(f) && f != "tiff") {
        w.bitDepth = 32;
    } else if (f == "png" || f == "tiff") {
        w.bitDepth = 16;
    } else {
        w.bitDepth = 8;
    }
    return w;
}

bool appliedLayoutIsRendered(const ImageInfo& in, const std::string& outPath, int requested) {
    const std::string f = canonicalImageFormat(outPath);
    if (f != "png" && f != "pnm")
        return false;
    if (in.isFloat || (in.bitDepth != 8 && in.bitDepth != 16) || in.bitsPerSample != in.bitDepth ||
        (requested != 0 && requested != in.bitDepth))
        return false;
    if (in.channels != 3 || in.alphaChannel >= 0 || in.subimages != 1 || in.mipLevels != 1)
        return false;
    const ImageWriteOptions w = renderedImageWriteOptions(in, outPath, requested);
    return w.bitDepth == in.bitDepth && !w.alpha &&
           appliedImageLayout(in, outPath, requested).type == in.type;
}

RenderedLayout appliedImageLayout(const ImageInfo& in, const std::string& out, int requested) {
    RenderedLayout l;
    const std::string f = canonicalImageFormat(out);
    const std::string name = f == "openexr" ? "OpenEXR" : upper(f);
    auto note = [&](Diagnostic::Severity s, const std::string& msg) {
        Diagnostic d;
        d.severity = s;
        d.message = msg;
        l.diagnostics.push_back(d);
    };
    if (requested == 8) {
        l.type = PixelType::UInt8;
    } else if (requested == 16) {
        if (onlyEightBit(f))
            throw Error(out + ": " + name + " stores 8 bits per channel only");
        l.type = f == "openexr" ? PixelType::Half : PixelType::UInt16;
    } else if (requested == 32) {
        if (!holdsFloat(f))
            throw Error(out + ": " + name + " stores " + (onlyEightBit(f) ? "8" : "8 or 16") +
                        " bits per channel, not float (use .exr or .tif)");
        l.type = PixelType::Float;
    } else {
        l.type = in.type;
        const bool isFloat = in.type == PixelType::Half || in.type == PixelType::Float;
        if (f == "hdr") {
            l.type = PixelType::Float;
        } else if (isFloat && !holdsFloat(f)) {
            l.type = onlyEightBit(f) ? PixelType::UInt8 : PixelType::UInt16;
            note(Diagnostic::Severity::Info, std::string(toString(in.type)) +
                                                 " values written as " +
                                                 (l.type == PixelType::UInt8 ? "8" : "16") +
                                                 "-bit " + name + " (rounded, clamped to [0, 1])");
        } else if (in.type == PixelType::Half && f == "hdr") {
            l.type = PixelType::Float;
        } else if (in.type == PixelType::UInt16 && onlyEightBit(f)) {
            l.type = PixelType::UInt8;
            note(Diagnostic::Severity::Info,
                 "16-bit values written as 8-bit " + name + " (the format has 8 bits per channel)");
        } else if (!isFloat && f == "openexr") {
            // OpenEXR has no normalised integers: half keeps every 8-bit value, float every 16.
            l.type = in.type == PixelType::UInt8 ? PixelType::Half : PixelType::Float;
        }
    }
    if (in.isFloat && l.type == PixelType::UInt8 && f != "openexr")
        note(Diagnostic::Severity::Warning,
             "linear-light float values written to an 8-bit " + name +
                 ": values above 1 clip and dark tones band (write .exr or .tif, or --bit-depth "
                 "16 where the format has it)");
    if (l.type == in.type && f == canonicalImageFormat(in.format))
        l.bitsPerSample = in.bitsPerSample;
    if ((f == "openexr" || f == "tiff") && f == canonicalImageFormat(in.format))
        l.keepCompression = in.compression;

    // Channels: colour, alpha, then the input's others, as far as the format holds them.
    std::vector<std::string> names = in.channelNames;
    const bool named = std::find(names.begin(), names.end(), "R") != names.end();
    if (!named) {
        const bool alpha = in.alphaChannel >= 0 || in.channels == 2 || in.channels == 4;
        names = {"R", "G", "B"};
        if (alpha)
            names.emplace_back("A");
    }
    if (!canHoldAlpha(f)) {
        const auto a = std::find(names.begin(), names.end(), "A");
        if (a != names.end()) {
            names.erase(a);
            note(Diagnostic::Severity::Info,
                 "alpha dropped: " + name +
                     (f == "gif" ? " is written opaque (OpenImageIO's GIF writer)"
                                 : " has no alpha channel"));
        }
    }
    const int maxCh = maxChannels(f);
    if (static_cast<int>(names.size()) > maxCh) {
        std::vector<std::string> kept, dropped;
        for (const auto& n : names)
            (n == "R" || n == "G" || n == "B" || n == "A" ? kept : dropped).push_back(n);
        std::string list;
        for (const auto& n : dropped)
            list += (list.empty() ? "" : ", ") + n;
        note(Diagnostic::Severity::Warning,
             "channels " + list + " dropped: " + name + " holds R, G, B and alpha only");
        names = kept;
    }
    // OpenImageIO 2.4's WebP writer takes colour with alpha to a 2.2 power, divides it by alpha
    // and back, on 8-bit values (webpoutput.cpp): what it stores is not what it was given.
    if (f == "webp" && std::find(names.begin(), names.end(), "A") != names.end())
        note(Diagnostic::Severity::Warning,
             "WEBP with alpha: OpenImageIO's WebP writer changes colour where there is alpha "
             "(tones below 15/255 become 0, colour under partial alpha shifts): write .png "
             "or .tif to keep it");
    l.channelNames = names;
    return l;
}

} // namespace lut::formats
