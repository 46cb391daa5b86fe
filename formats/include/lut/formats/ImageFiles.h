#pragma once
// What lutkit knows about image files by their name: which extensions are images, which can hold
// an alpha channel, and the one policy for the bit depth and alpha of a rendered image (used by
// `lutkit apply`, `lutkit preview` and the editor's "save preview", so they cannot drift apart).
#include "lut/formats/ImageIO.h"

#include <string>

namespace lut::formats {

// Whether path's extension is an image format lutkit reads and writes through OpenImageIO
// (.png .jpg .jpeg .tif .tiff .exr .bmp .tga .hdr .webp .dpx .psd .gif, any case).
bool isImageExtension(const std::string& path);

// Whether an image file of this extension can store an alpha channel (JPEG, BMP, HDR cannot).
bool canHoldAlpha(const std::string& path);

// The bit depth (8, 16, 32 = float) and alpha to write a rendered display-encoded image with,
// for an input described by `input`: an integer input keeps its depth (16 becomes 8 where the
// format has only 8); a float input gets float for .exr/.hdr/.pfm, 16 for .png/.tif, else 8.
// Alpha is written when the input had one and the output can hold it. requestedBitDepth (8, 16,
// 32) overrides the depth.
ImageWriteOptions renderedImageWriteOptions(const ImageInfo& input, const std::string& outPath,
                                            int requestedBitDepth = 0);

} // namespace lut::formats
