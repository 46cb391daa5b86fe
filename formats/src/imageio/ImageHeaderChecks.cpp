// SPDX-License-Identifier: Apache-2.0
// The pre-open plausibility rule (ImageHeaderChecks.h, ImageHeaderScan.h): the dispatch by first
// bytes, the OpenEXR scanner, the rule itself and the public checkImageFile().
#include "imageio/ImageHeaderChecks.h"
#include "imageio/ImageHeaderScan.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/formats/ImageIO.h"
#include "lut/io/FileNames.h"
#include "lut/io/InputFile.h"
#include "lut/os/Files.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <limits>

namespace lut::formats {

HeaderBytes::HeaderBytes(Reader read, std::uint64_t size, bool whole)
    : m_read(std::move(read)), m_size(size), m_whole(whole) {}

std::string HeaderBytes::get(std::uint64_t offset, std::size_t n) const {
    if (offset >= m_size)
        return {};
    n = static_cast<std::size_t>(std::min<std::uint64_t>(n, m_size - offset));
    if (offset >= m_cacheAt && offset + n <= m_cacheAt + m_cache.size())
        return m_cache.substr(static_cast<std::size_t>(offset - m_cacheAt), n);
    if (n <= 4096) { // small reads go through a 64 KiB window
        m_cacheAt = offset;
        m_cache.resize(static_cast<std::size_t>(std::min<std::uint64_t>(65536, m_size - offset)));
        m_cache.resize(m_read(offset, m_cache.data(), m_cache.size()));
        return m_cache.substr(0, std::min(n, m_cache.size()));
    }
    std::string s(n, '\0');
    s.resize(m_read(offset, s.data(), n));
    return s;
}

std::uint64_t HeaderBytes::le(std::uint64_t offset, int bytes) const {
    const std::string s = get(offset, static_cast<std::size_t>(bytes));
    if (s.size() != static_cast<std::size_t>(bytes))
        return 0;
    std::uint64_t v = 0;
    for (int i = bytes - 1; i >= 0; --i)
        v = v << 8 | static_cast<unsigned char>(s[static_cast<std::size_t>(i)]);
    return v;
}

std::uint64_t HeaderBytes::be(std::uint64_t offset, int bytes) const {
    const std::string s = get(offset, static_cast<std::size_t>(bytes));
    if (s.size() != static_cast<std::size_t>(bytes))
        return 0;
    std::uint64_t v = 0;
    for (char c : s)
        v = v << 8 | static_cast<unsigned char>(c);
    return v;
}

int HeaderBytes::byte(std::uint64_t offset) const {
    const std::string s = get(offset, 1);
    return s.empty() ? -1 : static_cast<unsigned char>(s[0]);
}

// OpenEXR (openexr.com, "OpenEXR File Layout"): magic 76 2f 31 01, a version word (bit 12 =
// multi-part), then headers of attributes "name\0type\0" + int32 size + value, each header ended
// by an empty name (multi-part: the list ended by one more). Every attribute's size must fit in
// the bytes after it (a 330-byte file whose "Software" claimed 1.7 GB made OpenEXR take 1.8 GB
// inside OpenImageIO's open; found by fuzz_image_apply). Each part's data window and channels
// give what it stores; its compression how far its share of the chunks can expand (measured and
// derived in docs/robustness.md; DWAA/DWAB: a DC value and an end-of-block code per 8x8 block,
// deflated).
namespace {

// How many bytes OpenEXR's reader takes for an attribute value of type `kind` whose header says
// `len` (OpenEXR 3.1, Header::readFrom): a known type is read by its own layout, not by `len`,
// and the next attribute is read from wherever that ends. A file where the two differ is
// corrupt, and OpenEXR would go on reading attribute names and sizes from inside values (a
// fuzzed channel list without its terminator made it allocate 486 MB for an "attribute" it
// found in the data that followed). Unknown types are kept as opaque bytes: exactly `len`.
std::uint64_t exrValueBytes(const HeaderBytes& b, const std::string& kind, std::uint64_t value,
                            std::uint64_t len) {
    // clang-format off
    static const std::pair<const char*, std::uint64_t> kFixed[] = {
        {"box2i", 16}, {"box2f", 16}, {"compression", 1}, {"deepImageState", 1}, {"double", 8},
        {"envmap", 1}, {"float", 4}, {"int", 4}, {"keycode", 28}, {"lineOrder", 1}, {"m33f", 36},
        {"m33d", 72}, {"m44f", 64}, {"m44d", 128}, {"rational", 8}, {"tiledesc", 9},
        {"timecode", 8}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12}, {"v3f", 12},
        {"v3d", 24}, {"chromaticities", 32}};
    // clang-format on
    for (const auto& [name, bytes] : kFixed)
        if (kind == name)
            return bytes;
    const std::uint64_t end = std::min(b.size(), value + len + 1);
    if (kind == "chlist") { // names and 16 bytes each, up to an empty name
        std::uint64_t c = value;
        while (c < end && b.byte(c) != 0) {
            const std::string name = b.get(c, 256);
            const auto nul = name.find('\0');
            if (nul == std::string::npos)
                return len + 1; // no end within the value: not what the header says
            c += nul + 1 + 16;
        }
        return c + 1 - value;
    }
    if (kind == "stringvector") { // int32 size + characters, until `len` is reached
        std::uint64_t c = value;
        while (c < value + len) {
            const auto n = static_cast<std::int32_t>(b.le(c, 4));
            if (n < 0)
                return len + 1;
            c += 4 + static_cast<std::uint64_t>(n);
        }
        return c - value;
    }
    if (kind == "preview") { // width, height, then 4 bytes per pixel
        const std::uint64_t w = b.le(value, 4), h = b.le(value + 4, 4);
        return len < 8 || w > len || h > len ? len + 1 : 8 + 4 * w * h;
    }
    return len;
}

} // namespace

DeclaredImage scanExr(const HeaderBytes& b, const std::string& path) {
    DeclaredImage d;
    d.format = "openexr";
    d.sharedData = true;
    const bool multiPart = (b.le(4, 4) & 0x1000u) != 0;
    std::uint64_t at = 8;
    const std::uint64_t size = b.size();
    auto cString = [&](std::uint64_t& pos, std::string& out) {
        out = b.get(pos, 256);
        const auto nul = out.find('\0');
        if (nul == std::string::npos)
            return false;
        out.resize(nul);
        pos += nul + 1;
        return true;
    };
    for (int header = 0; header < 1024; ++header) {
        if (at >= size || b.byte(at) == 0) // an empty header name: the end of the headers
            break;
        DeclaredPart p;
        std::int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;
        double bytesPerPixel = 0.0;
        int channels = 0, compression = 0;
        std::string type, name;
        for (;;) {
            if (at >= size) {
                d.complete = false;
                return d;
            }
            if (b.byte(at) == 0) { // the end of this header
                ++at;
                break;
            }
            std::string attr, kind;
            if (!cString(at, attr) || !cString(at, kind) || at + 4 > size) {
                d.complete = false;
                return d; // the codec says what is wrong
            }
            const auto len = static_cast<std::int32_t>(b.le(at, 4));
            at += 4;
            const std::uint64_t left = size - at;
            if (len < 0 || static_cast<std::uint64_t>(len) > left) {
                if (!b.whole()) {
                    d.complete = false;
                    return d;
                }
                throw Error(path + ": OpenEXR header attribute '" + attr + "' declares " +
                            std::to_string(len) + " bytes, but only " + std::to_string(left) +
                            " bytes follow in the file (truncated or corrupt)");
            }
            const std::uint64_t value = at;
            at += static_cast<std::uint64_t>(len);
            const std::uint64_t reads =
                exrValueBytes(b, kind, value, static_cast<std::uint64_t>(len));
            if (reads != static_cast<std::uint64_t>(len))
                throw Error(path + ": OpenEXR header attribute '" + attr + "' (" + kind +
                            ") declares " + std::to_string(len) + " bytes, but its value is " +
                            (reads > static_cast<std::uint64_t>(len) ? "longer" : "shorter") +
                            " (" + std::to_string(reads) + " bytes; corrupt)");
            if (kind == "box2i" && attr == "dataWindow" && len == 16) {
                x0 = static_cast<std::int32_t>(b.le(value, 4));
                y0 = static_cast<std::int32_t>(b.le(value + 4, 4));
                x1 = static_cast<std::int32_t>(b.le(value + 8, 4));
                y1 = static_cast<std::int32_t>(b.le(value + 12, 4));
            } else if (kind == "tiledesc" && len == 9) {
                // OpenEXR allocates a whole tile per compressor whatever the data window (a
                // fuzzed 16x12 image with 8x2293768 tiles: 293 MB); the TIFF limit applies.
                checkTileSize(path, "OpenEXR", b.le(value, 4), b.le(value + 4, 4));
            } else if (kind == "compression" && len == 1) {
                compression = b.byte(value);
            } else if (kind == "string" && attr == "type") {
                type = b.get(value, static_cast<std::size_t>(std::min(len, 64)));
            } else if (kind == "string" && attr == "name") {
                name = b.get(value, static_cast<std::size_t>(std::min(len, 255)));
            } else if (kind == "chlist") {
                std::uint64_t c = value;
                std::string channel;
                while (c < at && b.byte(c) != 0 && cString(c, channel) && c + 16 <= at) {
                    const std::uint64_t pixelType = b.le(c, 4);
                    const std::uint64_t xs = std::max<std::uint64_t>(1, b.le(c + 8, 4) & 0xffff);
                    const std::uint64_t ys = std::max<std::uint64_t>(1, b.le(c + 12, 4) & 0xffff);
                    bytesPerPixel += (pixelType == 1 ? 2.0 : 4.0) / static_cast<double>(xs * ys);
                    ++channels;
                    c += 16;
                }
            }
        }
        if (x1 >= x0 && y1 >= y0 && channels > 0 && type.rfind("deep", 0) != 0) {
            p.what = multiPart ? "part " + std::to_string(header + 1) +
                                     (name.empty() ? "" : " ('" + name + "')")
                               : "";
            p.width = static_cast<std::uint64_t>(x1 - x0 + 1);
            p.height = static_cast<std::uint64_t>(y1 - y0 + 1);
            p.channels = channels;
            // In double (a 2^31 x 2^31 window overflows 64 bits); converting a double past 2^64
            // is undefined (UBSan, image_oiio), so it saturates.
            const double stored =
                static_cast<double>(p.width) * static_cast<double>(p.height) * bytesPerPixel;
            p.storedBytes = stored >= 1.8e19 ? std::numeric_limits<std::uint64_t>::max()
                                             : static_cast<std::uint64_t>(stored);
            // clang-format off
            static const std::pair<double, const char*> kCodecs[] = {
                {1.0, "uncompressed"}, {64.0, "RLE"}, {1032.0, "ZIPS"}, {1032.0, "ZIP"},
                {512.0, "PIZ"}, {1376.0, "PXR24"}, {2.3, "B44"}, {10.7, "B44A"},
                {66048.0, "DWAA"}, {66048.0, "DWAB"}};
            // clang-format on
            if (compression >= 0 && compression < 10) {
                p.maxRatio = kCodecs[compression].first;
                p.codec = kCodecs[compression].second;
            } else {
                p.codec = "this compression";
            }
            d.parts.push_back(p);
        }
        if (!multiPart)
            break;
    }
    for (auto& p : d.parts)
        p.dataBytes = size > at ? size - at : 0;
    return d;
}

std::string sniffImageFormat(const HeaderBytes& b, const std::string& nameOrFormat) {
    const std::string h = b.get(0, 16);
    auto starts = [&](const char* magic, std::size_t n) {
        return h.size() >= n && std::memcmp(h.data(), magic, n) == 0;
    };
    if (starts("\x89PNG\r\n\x1a\n", 8))
        return "png";
    if (starts("\xff\xd8\xff", 3))
        return "jpeg";
    if (starts("GIF", 3)) // giflib checks these three bytes only, not the version after them
        return "gif";
    if (starts("II*\0", 4) || starts("MM\0*", 4) || starts("II+\0", 4) || starts("MM\0+", 4))
        return "tiff";
    if (starts("\x76\x2f\x31\x01", 4))
        return "openexr";
    if (starts("8BPS", 4))
        return "psd";
    if (starts("SDPX", 4) || starts("XPDS", 4))
        return "dpx";
    if (starts("#?", 2))
        return "hdr";
    if (starts("RIFF", 4) && h.size() >= 12 && h.compare(8, 4, "WEBP") == 0)
        return "webp";
    if (starts("FOR4", 4) && h.size() >= 12 && h.compare(8, 4, "CIMG") == 0)
        return "iff";
    if (starts("BM", 2))
        return "bmp";
    if (h.size() >= 3 && h[0] == 'P' && h[1] >= '1' && h[1] <= '7' &&
        std::isspace(static_cast<unsigned char>(h[2])))
        return "pnm";
    // Formats OpenImageIO reads that have no scanner here: known by their magic numbers (so
    // standard input may be one, and OpenImageIO, which finds no reader for memory by content,
    // is told which), held to the pixel limit once OpenImageIO has read the header.
    if (starts("\x01\xda", 2))
        return "sgi";
    if (starts("\x80\x2a\x5f\xd7", 4) || starts("\xd7\x5f\x2a\x80", 4))
        return "cineon";
    if (starts("DDS ", 4))
        return "dds";
    if (starts("\x53\x80\xf6\x34", 4))
        return "softimage";
    if (starts("SIMPLE  =", 9))
        return "fits";
    if (starts("\xff\x4f\xff\x51", 4) || starts("\0\0\0\x0cjP  ", 8))
        return "jpeg2000";
    if (starts("\x2f\x08\x67\xab", 4) || starts("\xab\x67\x08\x2f", 4))
        return "zfile";
    if (h.size() >= 12 && h.compare(4, 4, "ftyp") == 0)
        return "heif";
    // TGA has no magic number: its name, the named format, or the TGA 2.0 footer.
    std::string ext = nameOrFormat.find('.') == std::string::npos ? "." + nameOrFormat
                                                                  : extensionOf(nameOrFormat);
    for (auto& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".tga" || ext == ".targa" || ext == ".tpic" ||
        (b.whole() && b.size() >= 26 && b.get(b.size() - 18, 16) == "TRUEVISION-XFILE"))
        return "targa";
    return {};
}

DeclaredImage scanImageHeader(const HeaderBytes& b, const std::string& format,
                              const std::string& path) {
    if (format == "png")
        return scanPng(b, path);
    if (format == "jpeg")
        return scanJpeg(b, path);
    if (format == "gif")
        return scanGif(b, path);
    if (format == "tiff")
        return scanTiff(b, path);
    if (format == "openexr")
        return scanExr(b, path);
    if (format == "psd")
        return scanPsd(b, path);
    if (format == "dpx")
        return scanDpx(b, path);
    if (format == "hdr")
        return scanHdr(b, path);
    if (format == "webp")
        return scanWebp(b, path);
    if (format == "iff")
        return scanIff(b, path);
    if (format == "bmp")
        return scanBmp(b, path);
    if (format == "pnm")
        return scanPnm(b, path);
    if (format == "sgi" || format == "cineon" || format == "dds" || format == "softimage" ||
        format == "fits" || format == "jpeg2000" || format == "zfile" || format == "heif") {
        DeclaredImage d; // no scanner: the pixel limit once OpenImageIO has read the header
        d.format = format;
        return d;
    }
    if (format == "targa")
        return scanTga(b, path);
    return {};
}

namespace {

std::string formatName(const std::string& f) {
    if (f == "openexr")
        return "OpenEXR";
    if (f == "targa")
        return "TGA";
    std::string s = f;
    for (auto& c : s)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

std::string ratioText(double r) {
    char buf[32];
    std::snprintf(buf, sizeof buf, r < 10 ? "%.3g" : "%.0f", r);
    return buf;
}

} // namespace

void checkTileSize(const std::string& path, const std::string& format, std::uint64_t width,
                   std::uint64_t height) {
    constexpr std::uint64_t kMaxTilePixels = std::uint64_t(1) << 24;
    if (width > kMaxTilePixels || height > kMaxTilePixels || width * height > kMaxTilePixels)
        throw LimitError(path + ": " + format + " tiles of " + std::to_string(width) + "x" +
                         std::to_string(height) + " pixels, over the limit of " +
                         std::to_string(kMaxTilePixels) + " pixels per tile");
}

void checkDeclaredImage(const std::string& path, const DeclaredImage& image) {
    const std::string name = formatName(image.format);
    double shared = 0.0;
    std::uint64_t sharedData = 0;
    for (const DeclaredPart& p : image.parts) {
        const std::string who = path + (p.what.empty() ? "" : " (" + p.what + ")");
        if (p.width == 0 || p.height == 0)
            throw Error(who + ": the image has no pixels (" + std::to_string(p.width) + "x" +
                        std::to_string(p.height) + ")");
        if (p.width * p.height > limits::kMaxImagePixels || p.channels > 64 ||
            p.width > (1u << 30) || p.height > (1u << 30))
            throw LimitError(who + ": image is " + std::to_string(p.width) + "x" +
                             std::to_string(p.height) + " with " + std::to_string(p.channels) +
                             " channels, over the limit of " +
                             std::to_string(limits::kMaxImagePixels) + " pixels and 64 channels");
        if (p.maxRatio <= 0.0)
            continue;
        const double can = p.maxRatio * static_cast<double>(p.dataBytes);
        if (image.sharedData) {
            shared += static_cast<double>(p.storedBytes) / p.maxRatio;
            sharedData = p.dataBytes;
        }
        if (static_cast<double>(p.storedBytes) > can)
            throw LimitError(who + ": declares " + std::to_string(p.width) + "x" +
                             std::to_string(p.height) + " pixels (" +
                             std::to_string(p.storedBytes) + " bytes as stored) in " +
                             std::to_string(p.dataBytes) + " bytes of " + name + " data, more " +
                             "than " + p.codec + " data can hold (at most " +
                             ratioText(p.maxRatio) + ":1): truncated or corrupt");
    }
    if (image.sharedData && image.parts.size() > 1 && shared > static_cast<double>(sharedData))
        throw LimitError(path + ": declares " + std::to_string(image.parts.size()) +
                         " parts whose pixels need more than the file's " +
                         std::to_string(sharedData) + " bytes of " + name +
                         " data can hold: truncated or corrupt");
    // Plausible sizes, but a block of data its decoder would read or write past.
    for (const DeclaredPart& p : image.parts)
        if (!p.corruptBlock.empty())
            throw Error(path + (p.what.empty() ? "" : " (" + p.what + ")") + ": " + p.corruptBlock +
                        ": truncated or corrupt");
}

std::uint64_t plausibleFileBytes(const DeclaredImage& image) {
    if (image.format.empty() || !image.complete || image.parts.empty())
        return 0;
    // Incompressible pixels grow a little (deflate: 5 bytes per 64 KiB block; a JPEG at quality
    // 100 of noise: about 1.2 times); metadata (ICC profiles, EXIF, XMP) rarely passes 16 MiB.
    std::uint64_t stored = 0;
    for (const DeclaredPart& p : image.parts)
        stored += p.storedBytes;
    if (image.format == "psd" || image.format == "tiff")
        return 0; // layers or pages the first header does not list
    return 2 * stored + (std::uint64_t(64) << 20);
}

DeclaredImage checkImageHeader(const std::string& path, const std::string& nameOrFormat) {
    const int fd = os::openFile(path, os::OpenFor::Read);
    if (fd < 0)
        return {}; // the reader says why it cannot open it
    os::FileInfo st;
    if (os::openFileInfo(fd, st) != 0 || st.type != os::FileType::Regular) {
        os::closeFile(fd);
        return {};
    }
    const HeaderBytes bytes(
        [fd](std::uint64_t offset, void* dst, std::size_t n) {
            std::size_t got = 0;
            while (got < n) {
                const std::ptrdiff_t r =
                    os::readBytesAt(fd, static_cast<char*>(dst) + got, n - got, offset + got);
                if (r < 0 && errno == EINTR)
                    continue;
                if (r <= 0)
                    break;
                got += static_cast<std::size_t>(r);
            }
            return got;
        },
        st.size);
    DeclaredImage d;
    try {
        d = scanImageHeader(bytes, sniffImageFormat(bytes, nameOrFormat), path);
        checkDeclaredImage(path, d);
    } catch (...) {
        os::closeFile(fd);
        throw;
    }
    os::closeFile(fd);
    return d;
}

DeclaredImage checkImageBytes(const std::string& name, const std::string& bytes,
                              const std::string& format, bool whole) {
    const HeaderBytes b(
        [&bytes](std::uint64_t offset, void* dst, std::size_t n) {
            if (offset >= bytes.size())
                return std::size_t(0);
            const std::size_t got =
                std::min<std::size_t>(n, bytes.size() - static_cast<std::size_t>(offset));
            std::memcpy(dst, bytes.data() + offset, got);
            return got;
        },
        bytes.size(), whole);
    DeclaredImage d = scanImageHeader(b, sniffImageFormat(b, format), name);
    if (whole)
        checkDeclaredImage(name, d);
    return d;
}

std::uint64_t imageStreamBytes(std::string_view head, const std::string& format) {
    DeclaredImage d;
    try {
        d = checkImageBytes("-", std::string(head), format, false);
    } catch (const Error&) {
        return limits::kMaxLutFileBytes; // refused with its reason once it is whole
    }
    if (d.format.empty())
        return 0;
    const std::uint64_t most = plausibleFileBytes(d);
    return most > 0 ? std::min<std::uint64_t>(most, limits::kMaxLutFileBytes)
                    : limits::kMaxLutFileBytes;
}

ImageDeclaration checkImageFile(const std::string& path, const std::string& format) {
    checkRegularInput(path);
    const DeclaredImage d = checkImageHeader(path, format.empty() ? path : format);
    ImageDeclaration out;
    out.format = d.format;
    out.decoderBytes = d.decoderBytes;
    out.images = static_cast<int>(d.parts.size());
    if (!d.parts.empty()) {
        out.width = static_cast<int>(d.parts.front().width);
        out.height = static_cast<int>(d.parts.front().height);
        out.channels = d.parts.front().channels;
    }
    return out;
}

} // namespace lut::formats
