// SPDX-License-Identifier: Apache-2.0
#pragma once
// Saving a round-trip screenshot the way an image editor would (8-bit PNG, 16-bit TIFF, quality-90
// JPEG with 4:2:0 or 4:4:4 chroma) and reading it back through lutkit's reader.
#include "lut/Image.h"
#include "lut/formats/ImageIO.h"

#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace lut::rt {

enum class Storage { Png8, Tiff16, Jpeg420, Jpeg444 };

inline const char* storageName(Storage s) {
    switch (s) {
    case Storage::Png8:
        return "png-8";
    case Storage::Tiff16:
        return "tiff-16";
    case Storage::Jpeg420:
        return "jpeg-q90-420";
    case Storage::Jpeg444:
        return "jpeg-q90-444";
    }
    return "?";
}
inline int storageBits(Storage s) {
    return s == Storage::Tiff16 ? 16 : 8;
}

// Writes the RGB of `img` (values in [0,1], already quantised for PNG and TIFF) with OpenImageIO
// and returns the path.
inline std::string writeAs(const Image& img, Storage storage, const std::string& dir,
                           const std::string& stem) {
    const bool jpeg = storage == Storage::Jpeg420 || storage == Storage::Jpeg444;
    const std::string path = dir + "/" + stem + "-" + storageName(storage) +
                             (jpeg                         ? ".jpg"
                              : storage == Storage::Tiff16 ? ".tif"
                                                           : ".png");
    OIIO::ImageSpec spec(img.width(), img.height(), 3,
                         storage == Storage::Tiff16 ? OIIO::TypeDesc::UINT16
                                                    : OIIO::TypeDesc::UINT8);
    if (jpeg) {
        spec.attribute("Compression", "jpeg:90");
        spec.attribute("jpeg:subsampling", storage == Storage::Jpeg420 ? "4:2:0" : "4:4:4");
    }
    std::vector<float> rgb(static_cast<std::size_t>(img.width()) * img.height() * 3);
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            for (int c = 0; c < 3; ++c)
                rgb[(static_cast<std::size_t>(y) * img.width() + x) * 3 + c] = img.pixel(x, y)[c];
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out && out->open(path, spec)) << path;
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, rgb.data())) << path;
    out->close();
    return path;
}

inline Image savedAs(const Image& img, Storage storage, const std::string& dir,
                     const std::string& stem) {
    return formats::readImage(writeAs(img, storage, dir, stem)).image;
}

} // namespace lut::rt
