// SPDX-License-Identifier: Apache-2.0
#pragma once
// The streaming seam every image codec implements: an ImageSource hands out rows in the file's
// own sample type, an ImageSink takes rows in the output's type, both in chunks of whole rows, in
// order. Native codecs (PNG, OpenEXR scanline files, PNM; readers for BMP and TGA) are compiled
// into lutkit_formats; every other format goes through OpenImageIO in the module
// (ImageIOLoader.cpp loads it and forwards to it; OiioImage.cpp inside it).
#include "lut/formats/ImageIO.h"
#include "lut/io/OutputFile.h"

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lut::formats {

// What a file carries besides its pixels, as read, for writers to copy.
class ImageMetadata {
public:
    std::string format; // the format it was read from ("png", "openexr", OIIO's names)
    // Same-format copies, verbatim:
    struct PngChunk {
        char type[5] = {};
        std::string data;
        int place = 0; // 0 = before PLTE, 1 = before IDAT, 2 = after IDAT
    };
    std::vector<PngChunk> pngChunks;
    int pngColourType = -1; // the PNG input's IHDR colour type and depth (sBIT/bKGD follow them)
    int pngBitDepth = 0;
    std::shared_ptr<const void> exrHeader; // an Imf::Header (ExrCodec.cpp)
    std::string oiioAttributes;            // OpenImageIO's ParamValueList, serialised
    // Across formats:
    std::string icc;            // ICC profile
    std::string exif;           // TIFF-structured EXIF block
    std::string xmp;            // XMP packet (a JPEG's APP1)
    std::string iptc;           // IPTC block (a JPEG's APP13, 8BIM)
    bool iptcBeforeXmp = false; // the order they came in (decoding the second may add to the first)
    std::string jpegSubsampling;                           // "4:2:0", ... (a JPEG read natively)
    double xResolution = 0, yResolution = 0;               // pixels per resolutionUnit, 0 = none
    std::string resolutionUnit;                            // "in", "cm"
    std::vector<std::pair<std::string, std::string>> text; // key, value
    // Tagged sRGB (a PNG's sRGB chunk, Exif ColorSpace 1, OpenImageIO's oiio:ColorSpace "sRGB",
    // which its JPEG reader gives every JPEG): writers of another format tag their file so (PNG's
    // sRGB chunk where no ICC profile is written, Exif ColorSpace 1 in TIFF and JPEG).
    bool srgb = false;
    // OpenImageIO's files: the data window's origin and the display window, kept by writers of
    // the same format.
    bool hasWindows = false;
    int x = 0, y = 0;
    int fullX = 0, fullY = 0, fullWidth = 0, fullHeight = 0;
};

// Row bytes of a chunk of `rows` rows.
inline std::size_t rowBytes(const ImageInfo& info) {
    return static_cast<std::size_t>(info.width) * static_cast<std::size_t>(info.channels) *
           static_cast<std::size_t>(bytesPerSample(info.type));
}

class ImageSource {
public:
    virtual ~ImageSource();
    const ImageInfo& info() const { return m_info; }
    std::shared_ptr<const ImageMetadata> metadata() const { return m_metadata; }
    // Rows a read naturally covers (a tile row, an EXR line block): chunks are multiples of it.
    virtual int rowGranularity() const { return 1; }
    // Rows [y0, y1) of every channel, interleaved, in info().type, to dst (rowBytes apart).
    // Called with consecutive ranges from 0. Throws lut::Error naming the file.
    virtual void readRows(int y0, int y1, void* dst) = 0;
    // After the last row: checks the end of the file (a PNG's IEND: truncation is an error).
    virtual void finish() {}
    // The images the file holds, in order (OpenEXR parts, TIFF pages, GIF frames, and each one's
    // MIP levels): info().subimages and mipLevels say what they are. selectPart(i) makes part i
    // the one info(), metadata() and readRows() (again from row 0) are about.
    virtual int parts() const { return 1; }
    virtual void selectPart(int index);

protected:
    ImageInfo m_info;
    std::shared_ptr<const ImageMetadata> m_metadata;
};

// What a sink writes.
struct SinkSpec {
    std::string format; // "png", "openexr", "pnm", or an OIIO format / extension
    int width = 0;
    int height = 0;
    std::vector<std::string> channelNames; // "R","G","B"[,"A"] or the input's names
    int alphaChannel = -1;
    PixelType type = PixelType::UInt8;
    int bitsPerSample = 0;   // 0 = the type's; 10/12 for DPX
    std::string compression; // "" = the format's default
    int tileWidth = 0, tileHeight = 0;
    int mipLevel = 0; // > 0: a MIP level of the part written before (createImageSink's list)
    std::shared_ptr<const ImageMetadata> metadata; // copied where it fits
    int threads = 1;                               // encoder threads (PNG deflate)
};

class ImageSink {
public:
    virtual ~ImageSink();
    virtual int rowGranularity() const { return 1; }
    // Rows [y0, y1) interleaved in the spec's type and channels. Consecutive from 0.
    virtual void writeRows(int y0, int y1, const void* src) = 0;
    // Ends the file, checks it and commits it (the rename); throws lut::Error naming the
    // output. Without finish() the output is left as it was.
    virtual void finish() = 0;
    // Several parts (createImageSink with a list): ends the current one, starts the next; its
    // rows again from 0.
    virtual void nextPart();
};

// The codec for a file, told from its first bytes ("-" = standard input; `format` names its
// format, else sniffed). Throws lut::Error naming the file; FIFOs and devices are refused first.
std::unique_ptr<ImageSource> openImageSource(const std::string& path,
                                             const std::string& format = {});
// The same on bytes in memory: `name` stands for them in every message (as a path would, and
// its extension is what OpenImageIO is told, as a file's); the same plausibility rule
// (checkImageBytes) and codecs as a file, no file touched. Empty bytes are refused.
std::unique_ptr<ImageSource> openImageMemory(const std::string& name, std::string bytes,
                                             const std::string& format = {});
// Reads the selected subimage of an open source into a float RGBA frame (readImage's work;
// name stands for the source in messages).
LoadedImage readFrame(ImageSource& src, const std::string& name, const Progress* progress,
                      int subimage);
// Writes a frame to an output (writeImage's work once the output rule was applied).
void writeFrame(const OutputTarget& target, const Image& image, const ImageWriteOptions& options);
// Selects subimage `subimage` (its first MIP level) of src; kOnlyImage keeps part 0 and refuses
// a file holding several subimages (MultiImageError). Throws lut::Error naming path when there
// is no such subimage. Returns the parts (MIP levels) of that subimage, in order.
std::vector<int> selectSubimage(ImageSource& src, const std::string& path, int subimage);
// Whether a native codec writes this format (else OpenImageIO does).
std::string canonicalImageFormat(const std::string& formatOrPath);
// Sinks write to any OutputTarget: a file, standard output, a device or memory (memoryOutput).
std::unique_ptr<ImageSink> createImageSink(const OutputTarget& target, const SinkSpec& spec);
// A file of several parts (subimages, MIP levels), written one after the other: OpenEXR and TIFF
// (formatHoldsParts), through OpenImageIO.
std::unique_ptr<ImageSink> createImageSink(const OutputTarget& target,
                                           const std::vector<SinkSpec>& parts);
bool formatHoldsParts(const std::string& canonicalFormat);

// Native codecs (each in its own file).
std::unique_ptr<ImageSource> openPngSource(const std::string& path, std::string memory);
std::unique_ptr<ImageSink> createPngSink(const OutputTarget& target, const SinkSpec& spec);
std::unique_ptr<ImageSource> openExrSource(const std::string& path, std::string memory);
std::unique_ptr<ImageSink> createExrSink(const OutputTarget& target, const SinkSpec& spec);
bool exrIsNative(const std::string& path, const std::string& memory); // single-part scanline
std::unique_ptr<ImageSource> openPnmSource(const std::string& path, std::string memory);
std::unique_ptr<ImageSource> openJpegSource(const std::string& path, std::string memory);
std::unique_ptr<ImageSink> createPnmSink(const OutputTarget& target, const SinkSpec& spec);
// Readers only (OpenImageIO writes these formats).
std::unique_ptr<ImageSource> openBmpSource(const std::string& path, std::string memory);
std::unique_ptr<ImageSource> openTgaSource(const std::string& path, std::string memory);
// OpenImageIO through the module.
std::unique_ptr<ImageSource> openOiioSource(const std::string& path, std::string memory,
                                            const std::string& format);
std::unique_ptr<ImageSink> createOiioSink(const OutputTarget& target,
                                          const std::vector<SinkSpec>& parts);

// The limit checks every codec makes before allocating for an image: no pixels, over
// lut::limits::kMaxImagePixels, or more decoded bytes than `fileBytes` can hold at `maxRatio`
// (0 = no such bound; deflate: 1032).
void checkImageSize(const std::string& path, int width, int height, int channels,
                    std::uint64_t fileBytes = 0, double maxRatio = 0.0);

} // namespace lut::formats
