// SPDX-License-Identifier: Apache-2.0
// The image formats only OpenImageIO or OpenEXR read and write, in the portable editions
// (docs/portable.md): PNG, JPEG and PNM are read and written by lutkit's own codecs; anything
// else (TIFF, OpenEXR, ...) is refused with one line naming the edition, and a PNG or JPEG that
// is not one with the Linux build's message. BMP and TGA are read natively too (BmpCodec.cpp,
// TgaCodec.cpp).
#include "imageio/ImageCodec.h"

#include "lut/Error.h"
#include "lut/formats/Edition.h"
#include "lut/io/OutputPolicy.h"
#include "lut/os/Files.h"

#include <cstdio>

namespace lut::formats {

namespace {

std::string shown(const std::string& path) {
    return path == "-" ? std::string("standard input") : path;
}

// "reading WHAT needs ...": "OpenEXR images", "tiff images", "images of this format".
std::string imagesOf(const std::string& format) {
    std::string f = canonicalImageFormat(format);
    return f.empty() ? std::string("images of this format")
                     : (f == "openexr" ? "OpenEXR" : f) + std::string(" images");
}

// The first two bytes of the picture (memory, or the file), for the JPEG message.
unsigned firstTwoBytes(const std::string& path, const std::string& memory) {
    std::string head = memory.substr(0, 2);
    if (head.empty() && !isStdStream(path))
        if (std::FILE* f = os::openStream(path, "rb")) {
            char buf[2];
            head.assign(buf, std::fread(buf, 1, sizeof buf, f));
            std::fclose(f);
        }
    unsigned v = 0;
    for (const char c : head)
        v = v * 256 + static_cast<unsigned char>(c);
    return v;
}

} // namespace

std::unique_ptr<ImageSource> openOiioSource(const std::string& path, std::string memory,
                                            const std::string& format) {
    // A PNG or JPEG comes here only when its bytes are not what its name says (the native codecs
    // took it otherwise): the Linux build's words for that, OpenImageIO's own.
    const std::string f = canonicalImageFormat(format.empty() ? path : format);
    if (f == "png")
        throw Error(shown(path) + ": cannot read image: Not a PNG file");
    if (f == "jpeg") {
        char magic[16];
        std::snprintf(magic, sizeof magic, "0x%x", firstTwoBytes(path, memory));
        throw Error(shown(path) + ": cannot read image: \"" + shown(path) +
                    "\" is not a JPEG file, magic number doesn't match (was " + magic + ")");
    }
    throw Error(shown(path) + ": " +
                notInEdition("reading " + imagesOf(format.empty() ? path : format), "OpenImageIO",
                             "this edition reads PNG, JPEG, BMP, TGA and PNM (PPM/PGM)"));
}

std::unique_ptr<ImageSink> createOiioSink(const OutputTarget& target,
                                          const std::vector<SinkSpec>& parts) {
    const std::string format = parts.empty() ? std::string() : parts.front().format;
    throw Error(target.path + ": " +
                notInEdition("writing " + imagesOf(format.empty() ? target.path : format),
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
