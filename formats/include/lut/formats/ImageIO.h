#pragma once
// Image files through OpenImageIO: the stored values, no colour conversion, as float RGBA.
#include "lut/Image.h"

#include <string>

namespace lut::formats {

struct ImageInfo {
    int width = 0;
    int height = 0;
    int channels = 0; // channels in the file (1 = grey, 2 = grey+alpha, 3, 4)
    int bitDepth = 0; // 8 or 16 for integer files, 32 for float (half counts as 32), 0 other
    bool isFloat = false;
    std::string format; // OIIO format name ("png", "openexr", "tiff", ...)
    // What the file says about its pixels (empty when it says nothing): the colour space
    // ("sRGB", "Linear", ...: OIIO's oiio:ColorSpace) and a JPEG's chroma subsampling ("4:2:0",
    // "4:2:2", "4:4:4": jpeg:subsampling).
    std::string colorSpace;
    std::string chromaSubsampling;
};

struct LoadedImage {
    Image image; // RGBA float: 8/16-bit values v become v/255 or v/65535; grey is replicated,
                 // missing alpha is 1
    ImageInfo info;
};

// Reads the first subimage. Throws lut::Error naming the file (and LimitError for images larger
// than lut::limits::kMaxImagePixels, refused before any pixel buffer is allocated).
LoadedImage readImage(const std::string& path);
ImageInfo readImageInfo(const std::string& path);

struct ImageWriteOptions {
    int bitDepth = 8;    // 8, 16 (rounded to nearest, clamped) or 32 (float)
    bool dither = false; // 8/16-bit: ordered (4x4 Bayer) dither before rounding
    bool alpha = true;   // write the alpha channel (else RGB)
};

// Writes atomically (temporary file in the same folder, renamed when complete). The format
// comes from the extension. Throws lut::Error naming the file, e.g. for a bit depth the format
// cannot store (PNG has no float).
void writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options);

} // namespace lut::formats
