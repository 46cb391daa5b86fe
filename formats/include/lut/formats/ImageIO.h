// SPDX-License-Identifier: Apache-2.0
#pragma once
// Image files: their stored values as float RGBA, no colour conversion (LUT images, screenshots
// for the round trip, preview frames). Read and written in chunks of rows: the native codecs
// (PNG, OpenEXR scanline files, PNM) are linked in; every other format goes through OpenImageIO,
// in a module loaded on first use (formats/src/imageio/ImageIOModuleApi.h says why). Streaming a
// LUT through an image without a float frame: lut/formats/ApplyImage.h.
#include "lut/Error.h"
#include "lut/Image.h"
#include "lut/Progress.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
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
    // Tiled files (OpenEXR, TIFF, IFF): the tile size, read tile row by tile row and kept when
    // the output format has tiles; 0 = scanlines or strips.
    int tileWidth = 0;
    int tileHeight = 0;
    // Images in the file: OpenEXR parts, TIFF pages, GIF frames, PSD layers OpenImageIO lists,
    // and each one's MIP levels. 1 for a plain image; this describes the first level of the first.
    int subimages = 1;
    int mipLevels = 1; // of this subimage
    int subimage = 0;  // which one this is (from 0), and which of its MIP levels
    int mipLevel = 0;
    // Memory the decoder itself holds while reading besides the caller's rows (formats whose
    // reader decodes the whole image at once: TGA, BMP, GIF, PSD, WebP, IFF, DPX, an interlaced
    // PNG), to reserve before decoding.
    std::uint64_t decoderBytes = 0;
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

// A file holding several images (OpenEXR parts, TIFF pages, GIF frames) where one is read:
// "PATH: holds N images (OpenEXR parts); ..." naming how to pick one.
class MultiImageError : public Error {
public:
    MultiImageError(const std::string& path, int count, const std::string& kind);
    int count() const { return m_count; }
    const std::string& kind() const { return m_kind; } // "OpenEXR parts", "TIFF pages", ...

private:
    int m_count;
    std::string m_kind;
};
// readImage's `subimage` for "the file's only image": a file holding several is refused with
// MultiImageError. MIP levels below the first (texture files) are not read.
constexpr int kOnlyImage = -1;
// What a file's subimages are called: "OpenEXR parts", "TIFF pages", "GIF frames", "subimages".
std::string subimageKind(const std::string& format);

// Reads one image ("-" = standard input; `format` names its format, else it is told
// from its first bytes). Throws lut::Error naming the file (truncated and corrupt files too:
// never grey pixels), LimitError for images larger than lut::limits::kMaxImagePixels or
// declaring more pixels than their bytes can hold, refused before any pixel buffer is allocated.
// FIFOs, devices and folders are refused before they are opened. With `progress`, the rows
// decoded so far are reported and a cancel stops the read at the next chunk of rows
// (CancelledError naming the file). `subimage`: which image of a file that holds several
// (kOnlyImage: the file must hold one).
LoadedImage readImage(const std::string& path, const std::string& format = {},
                      const Progress* progress = nullptr, int subimage = kOnlyImage);
// The same from bytes in memory (the editor's export preview, Format::readMemory): `name` stands
// for the data in every message and its extension is what OpenImageIO is told, as a file's path
// would be; the format is told from the bytes as for a file. The same plausibility rule, codecs
// (OpenImageIO through its in-memory reader) and errors as readImage; nothing is written to or
// read from disk, except for a format whose OpenImageIO reader opens files by name only (GIF,
// SGI, FITS, HEIF ...: every one but TIFF, JPEG, OpenEXR, DPX, WebP, IFF, BMP, TGA, HDR, PSD,
// which read through its in-memory reader): those get the bytes in a private temporary file.
// Empty bytes are refused ("NAME: is empty").
LoadedImage readImageMemory(std::string_view bytes, const std::string& name,
                            const std::string& format = {}, const Progress* progress = nullptr,
                            int subimage = kOnlyImage);
// The same image without its frame: the rows as float RGBA (as readImage converts them), a
// chunk at a time, handed to `rows` with the first row's index, in order, in a buffer reused
// for the next chunk (a few MiB at most). For a caller that needs one pass over a picture or a
// part of it (check --image, atlas info/split, match's subsample of a large picture): memory
// stays the decoder's, whatever the picture's size. The same errors as readImage. Returns the
// file's ImageInfo.
ImageInfo readImageRows(const std::string& path,
                        const std::function<void(const ImageView& rows, int y0)>& rows,
                        const std::string& format = {}, const Progress* progress = nullptr,
                        int subimage = kOnlyImage);
// Every `step`-th column and row of an image, from the first (x, y multiples of step): a
// ceil(width / step) x ceil(height / step) float RGBA frame, read through readImageRows (the
// whole frame never exists). info is the file's (its full size). step 1 is readImage.
LoadedImage readImageSampled(const std::string& path, int step, const std::string& format = {},
                             const Progress* progress = nullptr, int subimage = kOnlyImage);
// Describes subimage `subimage` (kOnlyImage: the first; info.subimages says how many there are).
ImageInfo readImageInfo(const std::string& path, const std::string& format = {},
                        int subimage = kOnlyImage);

// The plausibility rule every image read applies before any codec opens the file, for callers
// that hand an image file to another library (or want to refuse it early): what the header
// declares (size, channels, bit depth, compression, every part, page or layer it lists) against
// lut::limits::kMaxImagePixels and against what the file's bytes can hold for that codec at its
// highest possible compression (the ratios are in docs/robustness.md). Throws lut::LimitError
// "PATH: declares WxH pixels (N bytes as stored) in M bytes of FORMAT data, more than CODEC data
// can hold (at most R:1): truncated or corrupt", or lut::Error for a FIFO, device or folder, or
// a header field whose size runs past the file. Reads the header only (a few KiB). `format`
// names a TGA's format when the path does not (TGA has no magic number).
struct ImageDeclaration {
    std::string format; // "png", "jpeg", "tiff", "openexr", ...; "" = not a format it knows
    int width = 0;      // the first image's
    int height = 0;
    int channels = 0;
    int images = 0;                 // images listed: EXR parts, TIFF pages, PSD merged + layers
    std::uint64_t decoderBytes = 0; // what the format's reader holds at once (ImageInfo's)
};
ImageDeclaration checkImageFile(const std::string& path, const std::string& format = {});

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
// The bytes writeImage would put in a file named `name` (whose extension picks the format, as a
// path's does; options.format otherwise), made in memory through the same codecs and checks
// (lut::memoryOutput): no temporary file. A file of several images (OpenEXR parts, TIFF pages),
// which OpenImageIO 2.4 writes by file name only, is refused here as for standard output; every
// single-image writer lutkit uses (PNG, PNM, OpenEXR, and through OpenImageIO TIFF, DPX, TGA,
// BMP, JPEG ...) writes through its I/O proxy.
std::string writeImageMemory(const std::string& name, const Image& image,
                             const ImageWriteOptions& options);

} // namespace lut::formats
