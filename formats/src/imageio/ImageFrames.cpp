// SPDX-License-Identifier: Apache-2.0
// Whole frames as float RGBA (lut/formats/ImageIO.h), read and written chunk by chunk through
// the codecs, from and to files or bytes in memory alike: the file's samples are converted straight
// into (out of) the frame's rows, so no second frame-sized buffer of the file's type exists.
#include "imageio/ImageCodec.h"
#include "imageio/PixelConvert.h"

#include "lut/Error.h"
#include "lut/formats/ImageIO.h"
#include "lut/io/FileNames.h"
#include "lut/io/InputFile.h"

#include <algorithm>
#include <vector>

namespace lut::formats {

namespace {

// Rows per chunk: about 256K samples, a multiple of the codec's own block of rows.
int chunkRows(int width, int channels, int granularity) {
    const int byWidth = std::max(1, (1 << 18) / std::max(1, width * channels));
    const int g = std::max(1, granularity);
    return std::max(g, byWidth / g * g);
}

} // namespace

ImageInfo readImageInfo(const std::string& path, const std::string& format, int subimage) {
    auto src = openImageSource(path, format);
    if (subimage > 0)
        selectSubimage(*src, path, subimage);
    return src->info();
}

LoadedImage readImage(const std::string& path, const std::string& format, const Progress* progress,
                      int subimage) {
    checkCancelled(progress, path);
    auto src = openImageSource(path, format);
    return readFrame(*src, path, progress, subimage);
}

LoadedImage readImageMemory(std::string_view bytes, const std::string& name,
                            const std::string& format, const Progress* progress, int subimage) {
    checkCancelled(progress, name);
    auto src = openImageMemory(name, std::string(bytes), format);
    return readFrame(*src, name, progress, subimage);
}

LoadedImage readFrame(ImageSource& source, const std::string& path, const Progress* progress,
                      int subimage) {
    selectSubimage(source, path, subimage);
    LoadedImage out;
    out.info = source.info();
    out.metadata = source.metadata();
    const ImageInfo& info = out.info;
    const RgbaMap map = rgbaMapOf(info);
    const std::uint64_t frameBytes =
        static_cast<std::uint64_t>(info.width) * static_cast<std::uint64_t>(info.height) * 16u;
    allocating(path,
               "a " + std::to_string(info.width) + "x" + std::to_string(info.height) +
                   " float RGBA frame",
               frameBytes, [&] { out.image = Image(info.width, info.height); });
    const int rows = chunkRows(info.width, info.channels, source.rowGranularity());
    const std::size_t rb = rowBytes(info);
    std::vector<unsigned char> chunk(rb * static_cast<std::size_t>(rows));
    for (int y0 = 0; y0 < info.height; y0 += rows) {
        checkCancelled(progress, path);
        const int y1 = std::min(info.height, y0 + rows);
        source.readRows(y0, y1, chunk.data());
        toRgba(chunk.data(), info.type, info.channels, map,
               static_cast<std::size_t>(info.width) * static_cast<std::size_t>(y1 - y0),
               out.image.pixel(0, y0));
        reportProgress(progress, static_cast<double>(y1) / info.height);
    }
    source.finish();
    return out;
}

ImageInfo readImageRows(const std::string& path,
                        const std::function<void(const ImageView& rows, int y0)>& fn,
                        const std::string& format, const Progress* progress, int subimage) {
    checkCancelled(progress, path);
    auto src = openImageSource(path, format);
    selectSubimage(*src, path, subimage);
    const ImageInfo info = src->info();
    const RgbaMap map = rgbaMapOf(info);
    const int rows = chunkRows(info.width, info.channels, src->rowGranularity());
    const std::size_t rb = rowBytes(info);
    std::vector<unsigned char> chunk(rb * static_cast<std::size_t>(rows));
    Image rgba(info.width, rows);
    for (int y0 = 0; y0 < info.height; y0 += rows) {
        checkCancelled(progress, path);
        const int y1 = std::min(info.height, y0 + rows);
        src->readRows(y0, y1, chunk.data());
        toRgba(chunk.data(), info.type, info.channels, map,
               static_cast<std::size_t>(info.width) * static_cast<std::size_t>(y1 - y0),
               rgba.pixel(0, 0));
        ImageView view = rgba.view();
        view.height = y1 - y0;
        fn(view, y0);
        reportProgress(progress, static_cast<double>(y1) / info.height);
    }
    src->finish();
    return info;
}

LoadedImage readImageSampled(const std::string& path, int step, const std::string& format,
                             const Progress* progress, int subimage) {
    if (step <= 1)
        return readImage(path, format, progress, subimage);
    LoadedImage out;
    checkCancelled(progress, path);
    auto src = openImageSource(path, format);
    selectSubimage(*src, path, subimage);
    out.info = src->info();
    out.metadata = src->metadata();
    const ImageInfo& info = out.info;
    const int w = (info.width + step - 1) / step, h = (info.height + step - 1) / step;
    allocating(path,
               "a " + std::to_string(w) + "x" + std::to_string(h) + " float RGBA frame (every " +
                   std::to_string(step) + "th pixel)",
               static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h) * 16u,
               [&] { out.image = Image(w, h); });
    const RgbaMap map = rgbaMapOf(info);
    const int rows = chunkRows(info.width, info.channels, src->rowGranularity());
    const std::size_t rb = rowBytes(info);
    std::vector<unsigned char> chunk(rb * static_cast<std::size_t>(rows));
    std::vector<float> row(static_cast<std::size_t>(info.width) * 4u);
    for (int y0 = 0; y0 < info.height; y0 += rows) {
        checkCancelled(progress, path);
        const int y1 = std::min(info.height, y0 + rows);
        src->readRows(y0, y1, chunk.data());
        for (int y = (y0 + step - 1) / step * step; y < y1; y += step) {
            toRgba(chunk.data() + rb * static_cast<std::size_t>(y - y0), info.type, info.channels,
                   map, static_cast<std::size_t>(info.width), row.data());
            float* dst = out.image.pixel(0, y / step);
            for (int x = 0; x < info.width; x += step)
                std::copy_n(&row[4 * static_cast<std::size_t>(x)], 4,
                            dst + 4 * static_cast<std::size_t>(x / step));
        }
        reportProgress(progress, static_cast<double>(y1) / info.height);
    }
    src->finish();
    return out;
}

void writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options) {
    if (image.empty())
        throw Error(path + ": cannot write an empty image");
    writeFrame(checkOutput(path, ExistingOutput::Replace), image, options);
}

std::string writeImageMemory(const std::string& name, const Image& image,
                             const ImageWriteOptions& options) {
    if (image.empty())
        throw Error(name + ": cannot write an empty image");
    std::string bytes;
    writeFrame(memoryOutput(name, bytes), image, options);
    return bytes;
}

void writeFrame(const OutputTarget& target, const Image& image, const ImageWriteOptions& options) {
    const std::string& path = target.path;
    const int bits = options.bitDepth;
    if (bits != 8 && bits != 16 && bits != 32)
        throw Error(path + ": unsupported bit depth " + std::to_string(bits) +
                    " (expected 8, 16 or 32)");
    SinkSpec spec;
    spec.format = options.format;
    const std::string fmt = canonicalImageFormat(
        !options.format.empty() && (target.inPlace() || extensionOf(path).empty()) ? options.format
                                                                                   : path);
    spec.width = image.width();
    spec.height = image.height();
    spec.channelNames = options.alpha ? std::vector<std::string>{"R", "G", "B", "A"}
                                      : std::vector<std::string>{"R", "G", "B"};
    spec.alphaChannel = options.alpha ? 3 : -1;
    spec.type = bits == 8    ? PixelType::UInt8
                : bits == 16 ? (fmt == "openexr" ? PixelType::Half : PixelType::UInt16)
                             : PixelType::Float;
    if (fmt == "jpeg" && bits != 8)
        throw Error(path + ": JPEG stores 8 bits per channel only");
    spec.metadata = options.metadata;
    spec.compression = options.compression;
    spec.threads = 2;
    auto sink = createImageSink(target, spec);
    ImageInfo out;
    out.width = spec.width;
    out.height = spec.height;
    out.channels = static_cast<int>(spec.channelNames.size());
    out.type = spec.type;
    out.channelNames = spec.channelNames;
    out.alphaChannel = spec.alphaChannel;
    const RgbaMap map = rgbaMapOf(out);
    const int rows = chunkRows(spec.width, out.channels, sink->rowGranularity());
    const std::size_t rb = rowBytes(out);
    std::vector<unsigned char> chunk(rb * static_cast<std::size_t>(rows));
    for (int y0 = 0; y0 < spec.height; y0 += rows) {
        checkCancelled(options.progress, path);
        const int y1 = std::min(spec.height, y0 + rows);
        DitherPos dp;
        dp.on = options.dither && spec.type != PixelType::Float && spec.type != PixelType::Half;
        dp.width = spec.width;
        dp.start = static_cast<std::size_t>(y0) * static_cast<std::size_t>(spec.width);
        fromRgba(image.pixel(0, y0),
                 static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(y1 - y0),
                 chunk.data(), spec.type, out.channels, map, dp);
        sink->writeRows(y0, y1, chunk.data());
        reportProgress(options.progress, static_cast<double>(y1) / spec.height);
    }
    checkCancelled(options.progress, path);
    sink->finish();
}

} // namespace lut::formats
