#pragma once
// Image files: their stored values as float RGBA, no colour conversion (LUT images, screenshots
// for the round trip, preview frames). Read and written in chunks of rows: the native codecs
// (PNG, OpenEXR scanline files, PNM) are linked in; every other format goes through OpenImageIO,
// in a module loaded on first use (formats/src/imageio/ImageIOModuleApi.h says why). Streaming a
// LUT through an image without a float frame: lut/formats/ApplyImage.h.
#include "lut/Image.h"
#include "lut/Progress.h"

#include <memory>
#include <string>
#include <vector>

namespace lut::formats {

// The type of a stored sample. 10- and 12-bit files (DPX) are UInt16 with bitsPerSample 10/12.
enum class PixelType { UInt8, UInt16, Half, Float };
const char* toString(PixelType type); // "uint8", "uint16", "half", "float"
inline int bytesPerSample(PixelType type) {
    return type == PixelType::UInt8 ? 1 : type == PixelType::Float ? 4 : 2;
}

struct ImageInfo {
    int width = 0;
    int height = 0;
    int channels = 0; // channels in the file (1 = grey, 2 = grey+alpha, 3, 4, more)
    int bitDepth = 0; // 8 or 16 for integer files, 32 for float (half counts as 32)
    bool isFloat = false;
    std::string format; // OIIO's format name ("png", "openexr", "tiff", "pnm", ...)
    PixelType type = PixelType::UInt8;
    int bitsPerSample = 8;                 // as stored: 8, 10, 12, 16 (half too), 32
    std::string compression;               // as OpenImageIO names it ("zip", "none", "lzw")
    std::vector<std::string> channelNames; // "R", "G", "B", "A", "Y", "Z" ...
    int alphaChannel = -1;                 // index of alpha, -1 = none
    // What the file says about its pixels (empty when it says nothing): the colour space
    // ("sRGB", "Linear", ...: OIIO's oiio:ColorSpace; a PNG's sRGB chunk, or "Linear" for a
    // gAMA of 1.0) and a JPEG's chroma subsampling ("4:2:0",
    // "4:2:2", "4:4:4": jpeg:subsampling).
    std::string colorSpace;
    std::string chromaSubsampling;
};

// What a file carries besides its pixels (PNG chunks, EXR header attributes, TIFF/EXIF tags, the
// ICC profile), as read; writers copy it. Opaque: lut::formats' own.
class ImageMetadata;

struct LoadedImage {
    Image image; // RGBA float: 8/16-bit values v become v/255 or v/65535; grey is replicated,
                 // missing alpha is 1
    ImageInfo info;
    std::shared_ptr<const ImageMetadata> metadata;
};

// Reads the first subimage ("-" = standard input; `format` names its format, else it is told
// from its first bytes). Throws lut::Error naming the file (truncated and corrupt files too:
// never grey pixels), LimitError for images larger than lut::limits::kMaxImagePixels or
// declaring more pixels than their bytes can hold, refused before any pixel buffer is allocated.
// FIFOs, devices and folders are refused before they are opened. With `progress`, the rows
// decoded so far are reported and a cancel stops the read at the next chunk of rows
// (CancelledError naming the file).
LoadedImage readImage(const std::string& path, const std::string& format = {},
                      const Progress* progress = nullptr);
ImageInfo readImageInfo(const std::string& path, const std::string& format = {});

struct ImageWriteOptions {
    ImageWriteOptions(int bits = 8, bool ditherOn = false, bool withAlpha = true)
        : bitDepth(bits), dither(ditherOn), alpha(withAlpha) {}
    int bitDepth = 8;    // 8, 16 (rounded to nearest, clamped; half for OpenEXR) or 32 (float)
    bool dither = false; // 8/16-bit: ordered (4x4 Bayer) dither before rounding
    bool alpha = true;   // write the alpha channel (else RGB)
    std::shared_ptr<const ImageMetadata> metadata; // copied into the file where it fits
    std::string compression;                       // "" = the format's default
    std::string format; // the format for "-" and devices ("png"; "" = from the extension)
    // Rows written so far; a cancel stops the write at the next chunk of rows (CancelledError
    // naming the file), the old file left as it was.
    const Progress* progress = nullptr;
};

// Writes through lut::OutputFile (lut/io/OutputFile.h): a regular file via a temporary file
// checked and renamed when complete; "-" and special files in place. The format comes from the
// extension. Throws lut::Error naming the file, e.g. for a bit depth the format cannot store (PNG
// has no float). Callers apply the overwrite rule first (lut/io/OutputPolicy.h): this replaces.
void writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options);

} // namespace lut::formats
