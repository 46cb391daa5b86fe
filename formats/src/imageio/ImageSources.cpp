// Which codec reads or writes a file: told from the first bytes for reading (never from the
// name, which may lie), from the output's extension or the named format for writing.
#include "imageio/ImageCodec.h"
#include "imageio/ImageHeaderChecks.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/io/FileNames.h"
#include "lut/io/InputFile.h"
#include "lut/io/StdStreams.h"

#include <cstring>

namespace lut::formats {

ImageSource::~ImageSource() = default;
ImageSink::~ImageSink() = default;

void checkImageSize(const std::string& path, int width, int height, int channels,
                    std::uint64_t fileBytes, double maxRatio) {
    if (width <= 0 || height <= 0 || channels <= 0)
        throw Error(path + ": image has no pixels (" + std::to_string(width) + "x" +
                    std::to_string(height) + ", " + std::to_string(channels) + " channels)");
    const std::uint64_t pixels =
        static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
    if (pixels > limits::kMaxImagePixels || channels > 64)
        throw LimitError(path + ": image is " + std::to_string(width) + "x" +
                         std::to_string(height) + " with " + std::to_string(channels) +
                         " channels, over the limit of " + std::to_string(limits::kMaxImagePixels) +
                         " pixels and 64 channels");
    // The most a compressed stream can expand (deflate: 258 bytes from 2 bits, 1032:1): more
    // pixels declared than the file can hold is a truncated or hostile file, refused before
    // anything is allocated or decoded.
    const double decoded = static_cast<double>(pixels) * channels;
    if (maxRatio > 0.0 && fileBytes > 0 && decoded > maxRatio * static_cast<double>(fileBytes))
        throw LimitError(path + ": declares " + std::to_string(width) + "x" +
                         std::to_string(height) + " pixels, more than its " +
                         std::to_string(fileBytes) + " bytes can hold (truncated or corrupt)");
}

std::string canonicalImageFormat(const std::string& formatOrPath) {
    std::string e = formatOrPath.find('.') == std::string::npos ? "." + formatOrPath
                                                                : extensionOf(formatOrPath);
    for (auto& c : e)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (e == ".png")
        return "png";
    if (e == ".exr" || e == ".openexr")
        return "openexr";
    if (e == ".ppm" || e == ".pgm" || e == ".pnm" || e == ".pbm")
        return "pnm";
    if (e == ".jpg" || e == ".jpeg" || e == ".jpe")
        return "jpeg";
    if (e == ".tif" || e == ".tiff")
        return "tiff";
    return e.size() > 1 ? e.substr(1) : e;
}

namespace {

std::unique_ptr<ImageSource> openAnySource(const std::string& path, const std::string& format) {
    std::string memory;
    std::string head;
    if (isStdStream(path)) {
        memory = readStandardInput(static_cast<std::size_t>(limits::kMaxLutFileBytes));
        head = memory.substr(0, 16);
    } else {
        checkRegularInput(path); // a FIFO or device is refused before it is opened
        std::FILE* f = std::fopen(path.c_str(), "rb");
        if (!f)
            throw Error(path + ": cannot open: " + std::strerror(errno));
        char buf[16];
        head.assign(buf, std::fread(buf, 1, sizeof buf, f));
        std::fclose(f);
        if (head.empty())
            throw Error(path + ": is empty");
        checkImageHeader(path); // declared sizes against the file, before a codec believes them
    }
    const std::string named = format.empty() ? "" : canonicalImageFormat(format);
    const auto starts = [&](const char* magic, std::size_t n) {
        return head.size() >= n && std::memcmp(head.data(), magic, n) == 0;
    };
    if (named == "png" || (named.empty() && starts("\x89PNG\r\n\x1a\n", 8)))
        return openPngSource(path, std::move(memory));
    if (named == "pnm" || (named.empty() && (starts("P5", 2) || starts("P6", 2))))
        if (head.size() >= 2 && (head[1] == '5' || head[1] == '6'))
            return openPnmSource(path, std::move(memory));
    if (named == "openexr" || (named.empty() && starts("\x76\x2f\x31\x01", 4))) {
        std::string copy = memory; // kept for OpenImageIO if the file is not a scanline one
        if (auto src = openExrSource(path, std::move(copy)))
            return src;
    }
    if (named == "jpeg" || (named.empty() && starts("\xff\xd8\xff", 3))) {
        // libjpeg fills a truncated file with grey and only warns: a JPEG must end with its
        // end-of-image marker (after which some writers leave padding).
        std::string tail;
        if (!memory.empty()) {
            tail = memory.substr(memory.size() > 4096 ? memory.size() - 4096 : 0);
        } else if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
            std::fseek(f, 0, SEEK_END);
            const long size = std::ftell(f);
            std::fseek(f, size > 4096 ? size - 4096 : 0, SEEK_SET);
            char buf[4096];
            tail.assign(buf, std::fread(buf, 1, sizeof buf, f));
            std::fclose(f);
        }
        if (tail.find("\xff\xd9") == std::string::npos)
            throw Error(path + ": JPEG file ends before its end-of-image marker (truncated)");
    }
    return openOiioSource(path, std::move(memory), named.empty() ? format : named);
}

} // namespace

std::unique_ptr<ImageSource> openImageSource(const std::string& path, const std::string& format) {
    auto src = openAnySource(path, format);
    // A header may declare no pixels at all (a DPX of width 0 was read without a word: found by
    // fuzz_image_apply); nothing downstream can use that.
    const ImageInfo& info = src->info();
    if (info.width <= 0 || info.height <= 0 || info.channels <= 0)
        throw Error((isStdStream(path) ? std::string("standard input") : path) +
                    ": the image has no pixels (" + std::to_string(info.width) + "x" +
                    std::to_string(info.height) + ", " + std::to_string(info.channels) +
                    " channels)");
    return src;
}

std::unique_ptr<ImageSink> createImageSink(const OutputTarget& target, const SinkSpec& spec) {
    const std::string fmt = canonicalImageFormat(
        !spec.format.empty() && (target.inPlace() || extensionOf(target.path).empty())
            ? spec.format
            : target.path);
    if (fmt == "png")
        return createPngSink(target, spec);
    if (fmt == "pnm")
        return createPnmSink(target, spec);
    if (fmt == "openexr")
        if (auto sink = createExrSink(target, spec))
            return sink;
    SinkSpec s = spec;
    s.format = fmt;
    return createOiioSink(target, s);
}

} // namespace lut::formats
