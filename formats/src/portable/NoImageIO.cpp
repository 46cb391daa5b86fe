// SPDX-License-Identifier: Apache-2.0
// The image formats only OpenImageIO or OpenEXR read and write, in the portable editions
// (docs/portable.md): PNG, JPEG and PNM are read and written by lutkit's own codecs; anything
// else (TIFF, OpenEXR, ...) is refused with one line naming the edition. BMP and TGA are read
// natively too (BmpCodec.cpp, TgaCodec.cpp).
#include "imageio/ImageCodec.h"

#include "lut/Error.h"
#include "lut/formats/Edition.h"

namespace lut::formats {

namespace {

std::string shown(const std::string& path) {
    return path == "-" ? std::string("standard input") : path;
}

std::string formatWord(const std::string& format) {
    std::string f = canonicalImageFormat(format);
    return f.empty() ? std::string("this image format") : f == "openexr" ? "OpenEXR" : f;
}

} // namespace

std::unique_ptr<ImageSource> openOiioSource(const std::string& path, std::string,
                                            const std::string& format) {
    throw Error(shown(path) + ": " +
                notInEdition("reading " + formatWord(format.empty() ? path : format) + " images",
                             "OpenImageIO",
                             "this edition reads PNG, JPEG, BMP, TGA and PNM (PPM/PGM)"));
}

std::unique_ptr<ImageSink> createOiioSink(const OutputTarget& target,
                                          const std::vector<SinkSpec>& parts) {
    const std::string format = parts.empty() ? std::string() : parts.front().format;
    throw Error(
        target.path + ": " +
        notInEdition("writing " + formatWord(format.empty() ? target.path : format) + " images",
                     "OpenImageIO", "this edition writes PNG and PNM (PPM/PGM)"));
}

std::unique_ptr<ImageSource> openExrSource(const std::string&, std::string) {
    return nullptr; // then openOiioSource, which says what this edition reads
}

std::unique_ptr<ImageSink> createExrSink(const OutputTarget&, const SinkSpec&) {
    return nullptr; // then createOiioSink, which says what this edition writes
}

bool exrIsNative(const std::string&, const std::string&) {
    return false;
}

} // namespace lut::formats
