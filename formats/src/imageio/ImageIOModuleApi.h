#pragma once
// The seam between the formats library and the OpenImageIO module (lutkit_imageio.so).
//
// Why: linking OpenImageIO pulls in ~250 shared libraries whose loading and static initialisers
// cost 250+ ms at every start of lutkit, before main() runs, even for `lutkit info small.cube`.
// So ImageIO.cpp (the only file that uses OIIO) is built into a module that ImageIOLoader.cpp
// dlopen()s on the first image read or write. Exceptions do not cross the seam: the module
// returns a status and message and the loader rethrows them as the caller's own types.
#include "lut/formats/ImageIO.h"

#include <string>

namespace lut::formats::module {

constexpr int kImageIOApiVersion = 2; // 2: ImageInfo has colorSpace and chromaSubsampling
constexpr const char* kImageIOModuleName = "lutkit_imageio.so";
constexpr const char* kImageIOEntryPoint = "lutkit_imageio_api";

enum Status : int { kOk = 0, kError = 1, kLimitError = 2, kOutOfMemory = 3 };

struct ImageIOApi {
    int version;
    int (*readImage)(const std::string& path, LoadedImage& out, std::string& error);
    int (*readImageInfo)(const std::string& path, ImageInfo& out, std::string& error);
    int (*writeImage)(const std::string& path, const Image& image, const ImageWriteOptions& options,
                      std::string& error);
};

using ImageIOEntryPoint = const ImageIOApi* (*)();

} // namespace lut::formats::module
