// SPDX-License-Identifier: Apache-2.0
// Which codec reads or writes a file: told from the first bytes for reading (never from the
// name, which may lie), from the output's extension or the named format for writing. Files,
// standard input and bytes in memory take the same checks and codecs.
#include "imageio/ImageCodec.h"
#include "imageio/ImageHeaderChecks.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/io/FileNames.h"
#include "lut/io/InputFile.h"
#include "lut/io/StdStreams.h"
#include "lut/os/Files.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>

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

// Standard input, bounded by what its header declares: a stream that is no image stops after
// its first MiB, one that is stops at what its pixels can take (plausibleFileBytes).
// A stream whose header is wrong is refused as soon as its head has arrived, not buffered to
// the limit (issue 41: a PNG signature then zeros took 4 GB, `--in-format png < /dev/zero` 2 GB).
std::string readImageStream(const std::string& named) {
    return readStandardInput(
        static_cast<std::size_t>(limits::kMaxLutFileBytes), [&](const std::string& head) {
            // A stream shorter than the head is refused with its reason once it is whole, as a
            // file is. A longer one: the header scanners read its head as a head (a field past
            // it is not an error), and what they refuse in it is refused at once.
            const bool longer = head.size() >= kStreamHeadBytes;
            DeclaredImage d;
            try {
                d = checkImageBytes("-", head, named, false);
            } catch (const Error&) {
                if (!longer)
                    return StreamBound{};
                throw;
            }
            if (d.format.empty() && named.empty())
                throw Error("-: standard input is not an image lutkit reads (no PNG, JPEG, TIFF, "
                            "OpenEXR, DPX, PSD, GIF, BMP, HDR, WebP, IFF or PNM header; name the "
                            "format of a TGA or another one with --in-format)");
            // A format named with --in-format whose files start with a signature: a stream
            // without it is not one.
            static const char* const kSigned[] = {"png", "jpeg", "gif", "tiff", "openexr",
                                                  "psd", "dpx",  "hdr", "webp", "iff",
                                                  "bmp", "pnm",  "dds", "fits"};
            if (longer && d.format.empty() &&
                std::find(std::begin(kSigned), std::end(kSigned), named) != std::end(kSigned))
                throw Error("-: standard input does not start as a " + named +
                            " file does (--in-format " + named +
                            "): no such signature in its first bytes");
            // A PNG's IHDR is its first chunk, at byte 8: a stream whose first MiB declares no
            // image there is no PNG (a signature then zeros was buffered to the limit).
            if (longer && d.format == "png" && d.parts.empty())
                throw Error("-: standard input starts with a PNG signature but no valid IHDR "
                            "chunk follows it: truncated or corrupt");
            const std::uint64_t most = plausibleFileBytes(d);
            if (most == 0)
                return StreamBound{};
            return StreamBound{most, "that its " + d.format + " header's " +
                                         std::to_string(d.parts.front().width) + "x" +
                                         std::to_string(d.parts.front().height) +
                                         " pixels can take"};
        });
}

// A file (path), standard input ("-") or bytes in memory (`bytes`, with path the name that
// stands for them): standard input is read whole and then takes the memory path, so bytes are
// checked and decoded exactly as a file's are, only without a file.
std::unique_ptr<ImageSource> openAnySource(const std::string& path, const std::string& format,
                                           DeclaredImage& declared,
                                           std::optional<std::string> bytes) {
    std::string memory;
    std::string head;
    const std::string named = format.empty() ? "" : canonicalImageFormat(format);
    if (bytes || isStdStream(path)) {
        if (bytes) {
            // Codecs read empty memory as "no memory": the name must never be opened as a file.
            if (bytes->empty())
                throw Error(path + ": is empty");
            memory = std::move(*bytes);
        } else {
            memory = readImageStream(named);
        }
        // As for a file, a TGA (no magic number) is told by its name's extension.
        declared = checkImageBytes(isStdStream(path) ? "-" : path, memory,
                                   named.empty() && bytes ? path : named, true);
        head = memory.substr(0, 16);
    } else {
        checkRegularInput(path); // a FIFO or device is refused before it is opened
        std::FILE* f = os::openStream(path, "rb");
        if (!f)
            throw IoError(path + ": cannot open: " + std::strerror(errno));
        char buf[16];
        head.assign(buf, std::fread(buf, 1, sizeof buf, f));
        std::fclose(f);
        if (head.empty())
            throw Error(path + ": is empty");
        // Declared sizes against the file, before a codec believes them.
        declared = checkImageHeader(path, named.empty() ? path : named);
    }
    const auto starts = [&](const char* magic, std::size_t n) {
        return head.size() >= n && std::memcmp(head.data(), magic, n) == 0;
    };
    if (named == "png" || (named.empty() && starts("\x89PNG\r\n\x1a\n", 8)))
        return openPngSource(path, std::move(memory));
    if (named == "pnm" || (named.empty() && (starts("P5", 2) || starts("P6", 2))))
        if (head.size() >= 2 && (head[1] == '5' || head[1] == '6'))
            return openPnmSource(path, std::move(memory));
    // BMP by its "BM"; TGA, which has no magic number, as the header check took it (the name's
    // extension, the named format or the TGA 2.0 footer).
    if (named == "bmp" || (named.empty() && starts("BM", 2)))
        return openBmpSource(path, std::move(memory));
    if (named == "targa" || named == "tga" || (named.empty() && declared.format == "targa"))
        return openTgaSource(path, std::move(memory));
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
        } else if (std::FILE* f = os::openStream(path, "rb")) {
            std::fseek(f, 0, SEEK_END);
            const long size = std::ftell(f);
            std::fseek(f, size > 4096 ? size - 4096 : 0, SEEK_SET);
            char buf[4096];
            tail.assign(buf, std::fread(buf, 1, sizeof buf, f));
            std::fclose(f);
        }
        if (tail.find("\xff\xd9") == std::string::npos)
            throw Error(path + ": JPEG file ends before its end-of-image marker (truncated)");
        return openJpegSource(path, std::move(memory));
    }
    // OpenImageIO reads memory through the reader it is told (a file's it would find from the
    // bytes when the extension's reader refuses them): the format the bytes declare, else the
    // name's extension.
    if (named.empty() && !memory.empty() && !declared.format.empty())
        return openOiioSource(path, std::move(memory), declared.format);
    return openOiioSource(path, std::move(memory), named.empty() ? format : named);
}

// A file as it is when its read begins, compared with it after the read (the content check):
// any write to the file in between moves its change time (ctime, set by the kernel on every
// write, whatever the writer does to the modification time), its modification time or its size.
// A rewrite in place at the same size (`dd conv=notrunc` while an uncompressed TIFF was read)
// gave rows of neither picture, exit 0 (issue 41).
struct FileState {
    bool known = false;
    os::FileInfo info;
};

FileState fileState(const std::string& path) {
    FileState f;
    if (isStdStream(path) || os::fileInfo(path, f.info) != 0 ||
        f.info.type != os::FileType::Regular)
        return f;
    f.known = true;
    return f;
}

// Throws "PATH: the file changed while being read (...)" when it did. A file replaced by another
// (renamed over it: another inode) was read whole as it was: that is no change to what was read.
void checkUnchanged(const std::string& path, const FileState& before) {
    if (!before.known)
        return;
    const FileState after = fileState(path);
    const os::FileInfo &a = after.info, &b = before.info;
    if (!after.known || a.device != b.device || a.inode != b.inode)
        return;
    if (a.size != b.size)
        throw Error(path + ": the file changed while being read (" + std::to_string(b.size) +
                    " bytes when opened, " + std::to_string(a.size) + " bytes now)");
    if (a.changedNs != b.changedNs || a.modifiedNs != b.modifiedNs)
        throw Error(path + ": the file changed while being read (written to by another " +
                    "program: its change time moved); read it again once it is written");
}

// Every part of a source within the pixel limit, whatever codec reads it; the header's
// declaration bounds what the codec's own decoder holds. A file's state is checked after the
// read (checkUnchanged).
class CheckedSource : public ImageSource {
public:
    CheckedSource(std::string path, std::unique_ptr<ImageSource> inner, std::uint64_t decoder,
                  FileState before = {})
        : m_path(std::move(path)), m_inner(std::move(inner)), m_decoder(decoder), m_before(before) {
        describe();
    }
    int rowGranularity() const override { return m_inner->rowGranularity(); }
    void readRows(int y0, int y1, void* dst) override { m_inner->readRows(y0, y1, dst); }
    void finish() override {
        m_inner->finish();
        checkUnchanged(m_path, m_before);
    }
    int parts() const override { return m_inner->parts(); }
    void selectPart(int index) override {
        m_inner->selectPart(index);
        describe();
    }

private:
    void describe() {
        m_info = m_inner->info();
        m_metadata = m_inner->metadata();
        const std::string name = isStdStream(m_path) ? std::string("-") : m_path;
        // A header may declare no pixels at all (a DPX of width 0 was read without a word:
        // found by fuzz_image_apply); nothing downstream can use that.
        if (m_info.width <= 0 || m_info.height <= 0 || m_info.channels <= 0)
            throw Error((isStdStream(m_path) ? std::string("standard input") : m_path) +
                        ": the image has no pixels (" + std::to_string(m_info.width) + "x" +
                        std::to_string(m_info.height) + ", " + std::to_string(m_info.channels) +
                        " channels)");
        checkImageSize(name, m_info.width, m_info.height, m_info.channels);
        m_info.decoderBytes = std::max(m_info.decoderBytes, m_decoder);
        if (m_info.tileWidth > 0) // a row of tiles, read and converted
            m_info.decoderBytes +=
                2 * rowBytes(m_info) * static_cast<std::uint64_t>(m_info.tileHeight);
    }

    std::string m_path;
    std::unique_ptr<ImageSource> m_inner;
    std::uint64_t m_decoder = 0;
    FileState m_before;
};

} // namespace

MultiImageError::MultiImageError(const std::string& path, int count, const std::string& kind)
    : Error(path + ": holds " + std::to_string(count) + " images (" + kind +
            ") and one is read here: extract the one you mean first (oiiotool " + path +
            " --subimage N -o ONE" + extensionOf(path) + ")"),
      m_count(count), m_kind(kind) {}

std::string subimageKind(const std::string& format) {
    if (format == "openexr")
        return "OpenEXR parts";
    if (format == "tiff")
        return "TIFF pages";
    if (format == "gif")
        return "GIF frames";
    return format + " subimages";
}

std::vector<int> selectSubimage(ImageSource& src, const std::string& path, int subimage) {
    const ImageInfo first = src.info();
    const std::string name = isStdStream(path) ? std::string("-") : path;
    if (subimage == kOnlyImage && first.subimages > 1)
        throw MultiImageError(name, first.subimages, subimageKind(first.format));
    const int want = std::max(0, subimage);
    if (want >= first.subimages)
        throw Error(name + ": holds " + std::to_string(first.subimages) +
                    (first.subimages == 1 ? " image" : " images") + ", no image " +
                    std::to_string(want) + " (they count from 0)");
    std::vector<int> parts;
    for (int i = 0; i < src.parts(); ++i) {
        if (i > 0 || src.info().subimage != 0)
            src.selectPart(i);
        if (src.info().subimage == want)
            parts.push_back(i);
        else if (src.info().subimage > want)
            break;
    }
    src.selectPart(parts.front());
    return parts;
}

void ImageSource::selectPart(int index) {
    if (index != 0)
        throw Error("image part " + std::to_string(index) + " does not exist");
}

void ImageSink::nextPart() {
    throw Error("this image writer holds one image");
}

std::unique_ptr<ImageSource> openImageSource(const std::string& path, const std::string& format) {
    if (isStdinName(path) && !isStdStream(path))
        return openImageSource("-", format); // /dev/stdin is standard input
    DeclaredImage declared;
    const FileState before = fileState(path); // before the header is read
    auto src = openAnySource(path, format, declared, std::nullopt);
    return std::make_unique<CheckedSource>(path, std::move(src), declared.decoderBytes, before);
}

std::unique_ptr<ImageSource> openImageMemory(const std::string& name, std::string bytes,
                                             const std::string& format) {
    DeclaredImage declared;
    auto src = openAnySource(name, format, declared, std::move(bytes));
    return std::make_unique<CheckedSource>(name, std::move(src), declared.decoderBytes);
}

bool formatHoldsParts(const std::string& canonicalFormat) {
    return canonicalFormat == "openexr" || canonicalFormat == "tiff" || canonicalFormat == "gif";
}

std::unique_ptr<ImageSink> createImageSink(const OutputTarget& target,
                                           const std::vector<SinkSpec>& parts) {
    if (parts.size() == 1)
        return createImageSink(target, parts.front());
    std::vector<SinkSpec> specs = parts;
    const SinkSpec& spec = parts.front();
    const std::string fmt = canonicalImageFormat(
        !spec.format.empty() && (target.inPlace() || extensionOf(target.path).empty())
            ? spec.format
            : target.path);
    for (auto& s : specs)
        s.format = fmt;
    return createOiioSink(target, specs);
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
    return createOiioSink(target, {s});
}

} // namespace lut::formats
