// Image file names: see lut/formats/ImageFiles.h. No OpenImageIO here (names only), so callers do
// not load the image module to ask.
#include "lut/formats/ImageFiles.h"
#include "lut/io/FileNames.h"

#include "lut/io/Format.h"

#include <set>

namespace lut::formats {

bool isImageExtension(const std::string& path) {
    static const std::set<std::string> exts = {".png", ".jpg", ".jpeg", ".tif", ".tiff",
                                               ".exr", ".bmp", ".tga",  ".hdr", ".webp",
                                               ".dpx", ".psd", ".gif"};
    return exts.count(extensionOf(path)) > 0;
}

bool canHoldAlpha(const std::string& path) {
    const std::string e = extensionOf(path);
    return e != ".jpg" && e != ".jpeg" && e != ".bmp" && e != ".hdr";
}

ImageWriteOptions renderedImageWriteOptions(const ImageInfo& in, const std::string& outPath,
                                            int requestedBitDepth) {
    ImageWriteOptions w;
    const std::string e = extensionOf(outPath);
    w.alpha = (in.channels == 2 || in.channels >= 4) && canHoldAlpha(outPath);
    if (requestedBitDepth) {
        w.bitDepth = requestedBitDepth;
    } else if (!in.isFloat && (in.bitDepth == 8 || in.bitDepth == 16)) {
        const bool only8 = e == ".jpg" || e == ".jpeg" || e == ".bmp" || e == ".gif";
        w.bitDepth = in.bitDepth == 16 && only8 ? 8 : in.bitDepth;
    } else if (e == ".exr" || e == ".hdr" || e == ".pfm") {
        w.bitDepth = 32;
    } else if (e == ".png" || e == ".tif" || e == ".tiff") {
        w.bitDepth = 16;
    } else {
        w.bitDepth = 8;
    }
    return w;
}

} // namespace lut::formats
