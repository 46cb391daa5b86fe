// SPDX-License-Identifier: Apache-2.0
#pragma once
// What lutkit knows about image files by their name, and the one policy for what a written image
// holds: used by `lutkit apply`, `lutkit preview` and the editor's "save preview", so they cannot
// drift apart.
#include "lut/Error.h"
#include "lut/formats/ImageIO.h"

#include <string>
#include <vector>

namespace lut::formats {

// Whether path's extension is an image format lutkit reads and writes (.png .jpg .jpeg .tif .tiff
// .exr .bmp .tga .hdr .webp .dpx .psd .gif .ppm .pgm .pnm, any case).
bool isImageExtension(const std::string& path);

// Whether an image file of this extension (or format name) can store an alpha channel (JPEG, BMP,
// HDR and PNM cannot; GIF's transparency is not written by OpenImageIO 2.4's GIF writer).
bool canHoldAlpha(const std::string& pathOrFormat);

// The bit depth (8, 16, 32 = float) and alpha to write a rendered display-encoded image with,
// for an input described by `input`: an integer input keeps its depth (16 becomes 8 where the
// format has only 8); a float input gets float for .exr/.hdr/.pfm, 16 for .png/.tif, else 8.
// Alpha is written when the input had one and the output can hold it. requestedBitDepth (8, 16,
// 32) overrides the depth.
ImageWriteOptions renderedImageWriteOptions(const ImageInfo& input, const std::string& outPath,
                                            int requestedBitDepth = 0);

// What `apply` writes for an input: the input's data type, channels and compression, as far as
// the output format holds them (what it cannot, and a linear float input written to an 8-bit
// display format, come back as diagnostics).
struct RenderedLayout {
    PixelType type = PixelType::UInt8;
    int bitsPerSample = 0;                 // 10/12 for DPX kept as DPX; 0 = the type's
    std::vector<std::string> channelNames; // R G B [A] [the input's other channels]
    std::string keepCompression;           // the input's, when the output format has it
    Diagnostics diagnostics;
};
// requestedBitDepth: 0 = the input's; 8, 16 (half for OpenEXR), 32 (float). Throws lut::Error
// for a depth the format cannot store ("PNG stores 8 or 16 bits per channel").
RenderedLayout appliedImageLayout(const ImageInfo& input, const std::string& outPathOrFormat,
                                  int requestedBitDepth = 0);

// Whether writing through `apply`'s layout (appliedImageLayout, the streamed applyToImage) gives
// the very file content renderedImageWriteOptions asks for: an 8/16-bit input of R, G, B only (a
// single image), written at its own depth to PNG or PNM (formats without a compression of the
// input's to keep). `lutkit preview` then streams the picture instead of holding a float frame.
bool appliedLayoutIsRendered(const ImageInfo& input, const std::string& outPath,
                             int requestedBitDepth = 0);

} // namespace lut::formats
