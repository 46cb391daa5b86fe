// SPDX-License-Identifier: Apache-2.0
#pragma once
// Fuzz target for image reading into apply and preview: the bytes are an image file that goes
// through the read path apply and preview use (lut::formats::readImage, OpenImageIO behind the
// image module), then one LUT applied with each interpolation (what apply does) and the smash
// preview pipeline on a crop of at most 48x48 pixels (what preview does).
//   byte 0: the file's extension, modulo the list below (OpenImageIO picks its reader by it)
//   rest:   the file
// Images over 1 megapixel are only looked at (readImageInfo), not decoded: how much memory a
// declared size may take is the image reader's own limit (--max-memory), not this target's.
// Contract: lut::Error or a result; the LUT and the preview leave finite values.
#include "FuzzTargets.h"

#include "lut/formats/ImageIO.h"
#include "lut/interp/Sampler.h"
#include "lut/pipeline/Pipeline.h"
#include "lut/pipeline/PreviewPlan.h"

#include <algorithm>
#include <memory>

namespace lut::fuzz {

// A small LUT that is not neutral (so apply changes values): a slight S-curve with a channel
// swap, values inside [0,1].
inline const Lut3D& fuzzGradingLut() {
    static const Lut3D lut = [] {
        Lut3D l = Lut3D::identity(5);
        for (auto& v : l.entries()) {
            const glm::vec3 c = v;
            v = glm::vec3(c.g, c.b * 0.9f + 0.05f, c.r * c.r);
        }
        return l;
    }();
    return lut;
}

inline void checkFinite(const Image& image, const char* what) {
    for (float v : image.pixels())
        invariant(std::isfinite(v), what);
}

inline Outcome runImageApply(const std::uint8_t* data, std::size_t size) {
    if (size < 2)
        return Outcome::Refused;
    // clang-format off
    static const char* const kExtensions[] = {
        ".png", ".jpg", ".tif", ".exr", ".bmp", ".tga", ".hdr", ".webp", ".dpx", ".gif", ".psd"};
    // clang-format on
    constexpr std::size_t kCount = sizeof(kExtensions) / sizeof(kExtensions[0]);
    const std::string path =
        writeScratch(std::string("image") + kExtensions[data[0] % kCount], data + 1, size - 1);
    formats::LoadedImage img;
    try {
        const formats::ImageInfo info = formats::readImageInfo(path);
        invariant(info.width > 0 && info.height > 0 && info.channels > 0,
                  "readImageInfo accepted an image without pixels");
        if (static_cast<std::uint64_t>(info.width) * info.height > (1u << 20))
            return Outcome::Accepted;
        img = formats::readImage(path);
    } catch (const lut::Error&) {
        return Outcome::Refused;
    }
    invariant(img.image.width() == img.info.width && img.image.height() == img.info.height,
              "readImage's pixels differ from its info");

    // apply: each interpolation on a copy. Non-finite pixels stay what they are (NaN in, NaN
    // out is allowed), so finiteness is checked on finite inputs only.
    bool finiteIn = true;
    for (float v : img.image.pixels())
        finiteIn = finiteIn && std::isfinite(v);
    for (Interpolation m :
         {Interpolation::Nearest, Interpolation::Trilinear, Interpolation::Tetrahedral}) {
        Image copy = img.image;
        makeSampler(fuzzGradingLut(), m)->apply(copy.view(), 1);
        if (finiteIn)
            checkFinite(copy, "apply made a finite pixel non-finite");
    }

    // preview: the stored values as a screenshot or a linear scene, then the smash chain.
    const int w = std::min(img.image.width(), 48), h = std::min(img.image.height(), 48);
    Image frame(w, h);
    for (int y = 0; y < h; ++y)
        std::copy(img.image.pixel(0, y), img.image.pixel(0, y) + 4 * w, frame.pixel(0, y));
    PreviewPlan scene; // a float file is a linear scene, an integer one is sRGB-decoded
    scene.decode = !img.info.isFloat;
    (void)preparePreviewFrame(scene, frame.view(), nullptr, false, 1);
    PipelineSettings settings;
    settings.lut = std::make_shared<const Lut3D>(fuzzGradingLut());
    Pipeline pipeline(settings);
    RunOptions run;
    run.nthreads = 1;
    (void)pipeline.run(frame.view(), run);
    checkFinite(frame, "the preview pipeline left a non-finite value");
    return Outcome::Accepted;
}

} // namespace lut::fuzz
