// Image file I/O for every format OpenImageIO knows. Integer samples are normalised exactly
// (v/255, v/65535) and written back with lut::toUnorm8/16, so 8- and 16-bit data round-trip
// bit-exactly. No colour-space conversion is ever applied: LUT images store values, not colours.
#include "lut/formats/ImageIO.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/Quantize.h"
#include "lut/io/AtomicFile.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <vector>

namespace lut::formats {

namespace OIIO = OIIO_NAMESPACE;

static ImageInfo infoFromSpec(const OIIO::ImageSpec& spec, const std::string& format) {
    ImageInfo info;
    info.width = spec.width;
    info.height = spec.height;
    info.channels = spec.nchannels;
    info.format = format;
    info.colorSpace = spec.get_string_attribute("oiio:ColorSpace");
    info.chromaSubsampling = spec.get_string_attribute("jpeg:subsampling");
    switch (spec.format.basetype) {
    case OIIO::TypeDesc::UINT8:
        info.bitDepth = 8;
        break;
    case OIIO::TypeDesc::UINT16:
        info.bitDepth = 16;
        break;
    case OIIO::TypeDesc::HALF:
    case OIIO::TypeDesc::FLOAT:
    case OIIO::TypeDesc::DOUBLE:
        info.bitDepth = 32;
        info.isFloat = true;
        break;
    default:
        info.bitDepth = 0;
        break;
    }
    return info;
}

static std::unique_ptr<OIIO::ImageInput> openInput(const std::string& path) {
    // Keep colour values as stored: by default OIIO premultiplies PNG/TIFF colour by an
    // unassociated alpha, which would scale the LUT entries of any pixel whose alpha is not 1.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) {
        std::string err = OIIO::geterror();
        err = err.substr(0, err.find('\n')); // OIIO stacks libpng's lines; errors are one line
        if (err.empty())
            err = "not an image OpenImageIO can read";
        throw Error(path + ": cannot read image: " + err);
    }
    return in;
}

static void checkSize(const std::string& path, const OIIO::ImageSpec& spec) {
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        throw Error(path + ": image has no pixels (" + std::to_string(spec.width) + "x" +
                    std::to_string(spec.height) + ", " + std::to_string(spec.nchannels) +
                    " channels)");
    if (static_cast<std::uint64_t>(spec.width) * static_cast<std::uint64_t>(spec.height) >
            limits::kMaxImagePixels ||
        spec.nchannels > 64)
        throw LimitError(path + ": image is " + std::to_string(spec.width) + "x" +
                         std::to_string(spec.height) + " with " + std::to_string(spec.nchannels) +
                         " channels, over the limit of " + std::to_string(limits::kMaxImagePixels) +
                         " pixels and 64 channels");
}

ImageInfo readImageInfo(const std::string& path) {
    auto in = openInput(path);
    const OIIO::ImageSpec& spec = in->spec();
    checkSize(path, spec);
    return infoFromSpec(spec, in->format_name());
}

LoadedImage readImage(const std::string& path) {
    auto in = openInput(path);
    const OIIO::ImageSpec spec = in->spec();
    checkSize(path, spec);
    LoadedImage out;
    out.info = infoFromSpec(spec, in->format_name());
    const int nch = spec.nchannels;
    std::vector<float> buf(static_cast<std::size_t>(spec.width) * spec.height * nch);
    if (!in->read_image(0, 0, 0, nch, OIIO::TypeDesc::FLOAT, buf.data())) {
        std::string err = in->geterror();
        err = err.substr(0, err.find('\n')); // one line: OIIO appends libpng's own lines
        throw Error(path +
                    ": cannot read image data: " + (err.empty() ? "truncated or corrupt" : err));
    }
    in->close();
    // OIIO converts integers with v * (1/max); recompute from the exact integer so that
    // v/255 and v/65535 are the correctly rounded floats our quantiser inverts.
    const double maxv = out.info.bitDepth == 8 ? 255.0 : out.info.bitDepth == 16 ? 65535.0 : 0.0;
    out.image = Image(spec.width, spec.height);
    float* dst = out.image.data();
    const std::size_t n = static_cast<std::size_t>(spec.width) * spec.height;
    for (std::size_t i = 0; i < n; ++i) {
        const float* s = buf.data() + i * nch;
        float v[4];
        if (nch == 1 || nch == 2) {
            v[0] = v[1] = v[2] = s[0];
            v[3] = nch == 2 ? s[1] : 1.0f;
        } else {
            v[0] = s[0];
            v[1] = s[1];
            v[2] = s[2];
            v[3] = nch >= 4 ? s[3] : 1.0f;
        }
        for (int c = 0; c < 4; ++c) {
            float x = v[c];
            if (maxv > 0.0)
                x = static_cast<float>(std::round(static_cast<double>(x) * maxv) / maxv);
            dst[4 * i + c] = x;
        }
    }
    return out;
}

// 4x4 Bayer matrix, thresholds in (-0.5, 0.5) of one quantisation step.
static float bayer(int x, int y) {
    static const int m[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
    return (static_cast<float>(m[y & 3][x & 3]) + 0.5f) / 16.0f - 0.5f;
}

void writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options) {
    if (image.empty())
        throw Error(path + ": cannot write an empty image");
    const int bits = options.bitDepth;
    if (bits != 8 && bits != 16 && bits != 32)
        throw Error(path + ": unsupported bit depth " + std::to_string(bits) +
                    " (expected 8, 16 or 32)");
    AtomicFile file(path);
    auto out = OIIO::ImageOutput::create(file.tempPath());
    if (!out)
        throw Error(path + ": no image writer for this extension: " + OIIO::geterror());
    const int nch = options.alpha ? 4 : 3;
    const OIIO::TypeDesc type = bits == 8    ? OIIO::TypeDesc::UINT8
                                : bits == 16 ? OIIO::TypeDesc::UINT16
                                             : OIIO::TypeDesc::FLOAT;
    if (bits == 32 && !out->supports("floatpixels") && std::string(out->format_name()) == "png")
        throw Error(path + ": PNG stores 8 or 16 bits per channel, not float (use .exr or .tif)");
    OIIO::ImageSpec spec(image.width(), image.height(), nch, type);
    // Our pixels are unassociated (colour not multiplied by alpha): without this OIIO divides
    // colour by alpha when writing PNG/TIFF, changing every pixel whose alpha is below 1.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (bits == 16 && std::string(out->format_name()) == "jpeg")
        throw Error(path + ": JPEG stores 8 bits per channel only");
    if (!out->open(file.tempPath(), spec))
        throw Error(path + ": cannot write image: " + out->geterror());
    const std::size_t n = static_cast<std::size_t>(image.width()) * image.height();
    bool ok = false;
    const float* src = image.data();
    const float step = bits == 8 ? 1.0f / 255.0f : 1.0f / 65535.0f;
    auto dith = [&](std::size_t i) {
        if (!options.dither)
            return 0.0f;
        const int x = static_cast<int>(i % static_cast<std::size_t>(image.width()));
        const int y = static_cast<int>(i / static_cast<std::size_t>(image.width()));
        return bayer(x, y) * step;
    };
    if (bits == 8) {
        std::vector<std::uint8_t> buf(n * nch);
        for (std::size_t i = 0; i < n; ++i) {
            const float d = dith(i);
            for (int c = 0; c < nch; ++c)
                buf[i * nch + c] = toUnorm8(src[4 * i + c] + (c < 3 ? d : 0.0f));
        }
        ok = out->write_image(type, buf.data());
    } else if (bits == 16) {
        std::vector<std::uint16_t> buf(n * nch);
        for (std::size_t i = 0; i < n; ++i) {
            const float d = dith(i);
            for (int c = 0; c < nch; ++c)
                buf[i * nch + c] = toUnorm16(src[4 * i + c] + (c < 3 ? d : 0.0f));
        }
        ok = out->write_image(type, buf.data());
    } else {
        std::vector<float> buf(n * nch);
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < nch; ++c)
                buf[i * nch + c] = src[4 * i + c];
        ok = out->write_image(type, buf.data());
    }
    if (!ok)
        throw Error(path + ": cannot write image: " + out->geterror());
    if (!out->close())
        throw Error(path + ": cannot write image: " + out->geterror());
    out.reset();
    file.commit();
}

} // namespace lut::formats
