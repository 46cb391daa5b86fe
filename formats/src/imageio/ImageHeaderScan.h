// SPDX-License-Identifier: Apache-2.0
#pragma once
// What image headers declare, read field by field without decoding anything (no OpenImageIO:
// this runs before the image module opens a file). One scanner per format, in
// ImageHeaderScanRaster.cpp (PNG, JPEG, GIF, BMP, TGA, HDR, WebP), ImageHeaderScanTiff.cpp
// (TIFF), ImageHeaderScanLayered.cpp (PSD, DPX, IFF) and ImageHeaderChecks.cpp (OpenEXR, the
// dispatch and the rule). Each one throws lut::Error naming the field when a size the header
// gives runs past the file (OpenImageIO would allocate it), and otherwise returns the images the
// header declares with what the codec can at most expand its bytes to; the rule
// (checkDeclaredImage) then compares them.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace lut::formats {

// Random access to a file's bytes (a file through pread, or standard input's bytes in memory),
// with a small cache for the scanners that walk a file's blocks one byte at a time (GIF).
class HeaderBytes {
public:
    using Reader = std::function<std::size_t(std::uint64_t offset, void* dst, std::size_t n)>;
    // `size`: the file's size; for a stream read so far, whole = false.
    HeaderBytes(Reader read, std::uint64_t size, bool whole = true);
    std::uint64_t size() const { return m_size; }
    bool whole() const { return m_whole; }
    // Up to n bytes at offset (fewer at the end of the file).
    std::string get(std::uint64_t offset, std::size_t n) const;
    // Numbers at offset; 0 past the end (scanners check sizes before trusting them).
    std::uint64_t le(std::uint64_t offset, int bytes) const;
    std::uint64_t be(std::uint64_t offset, int bytes) const;
    int byte(std::uint64_t offset) const; // -1 past the end

private:
    Reader m_read;
    std::uint64_t m_size;
    bool m_whole;
    mutable std::string m_cache;
    mutable std::uint64_t m_cacheAt = 0;
};

// One image the header declares (an OpenEXR part, a TIFF page, a GIF frame, a PSD layer).
struct DeclaredPart {
    std::string what;        // "", or "page 2", "part 'beauty'", "layer 3": for messages
    std::uint64_t width = 0; // pixels
    std::uint64_t height = 0;
    int channels = 0;              // as decoded (a palette image: 3 or 4)
    std::uint64_t storedBytes = 0; // the pixels at the file's bit depth, uncompressed
    std::uint64_t dataBytes = 0;   // the bytes of the file that hold them
    double maxRatio = 0.0; // the codec's most stored bytes per data byte (0: no bound but the
                           // pixel limit)
    std::string codec;     // "uncompressed", "deflate", "PackBits", ...: for messages
    // Set when a block of the part's data is one its decoder would read or write past (a TIFF
    // strip or tile past the end of the file, an IFF tile whose runs overrun it): which block and
    // how, for the message. OpenImageIO's decoders trust these (docs/robustness.md), so the file
    // is refused before decoding.
    std::string corruptBlock;
};

struct DeclaredImage {
    std::string format; // "png", "jpeg", "tiff", ...; "" = not recognised
    std::vector<DeclaredPart> parts;
    // Parts sharing one pool of data bytes (OpenEXR parts): their stored bytes over their
    // ratios must fit in it together.
    bool sharedData = false;
    // What the format's reader holds at once besides the caller's rows (whole-image decoders).
    std::uint64_t decoderBytes = 0;
    // For a stream: the header ended within the bytes read (the declaration is complete).
    bool complete = true;
};

DeclaredImage scanPng(const HeaderBytes& b, const std::string& path);
DeclaredImage scanJpeg(const HeaderBytes& b, const std::string& path);
DeclaredImage scanGif(const HeaderBytes& b, const std::string& path);
DeclaredImage scanBmp(const HeaderBytes& b, const std::string& path);
DeclaredImage scanTga(const HeaderBytes& b, const std::string& path);
DeclaredImage scanHdr(const HeaderBytes& b, const std::string& path);
DeclaredImage scanWebp(const HeaderBytes& b, const std::string& path);
DeclaredImage scanPnm(const HeaderBytes& b, const std::string& path);
DeclaredImage scanTiff(const HeaderBytes& b, const std::string& path);
DeclaredImage scanPsd(const HeaderBytes& b, const std::string& path);
DeclaredImage scanDpx(const HeaderBytes& b, const std::string& path);
DeclaredImage scanIff(const HeaderBytes& b, const std::string& path);
DeclaredImage scanExr(const HeaderBytes& b, const std::string& path);

// The format a file's first bytes (and, for TGA, which has no magic number, its name or the
// named format) say it is: "png", "jpeg", ..., "" when none.
std::string sniffImageFormat(const HeaderBytes& b, const std::string& nameOrFormat);
// The scanner for a sniffed format (an unknown one: an empty declaration).
DeclaredImage scanImageHeader(const HeaderBytes& b, const std::string& format,
                              const std::string& path);
// The rule: every part within lut::limits::kMaxImagePixels and 64 channels, and holding no more
// stored bytes than its data bytes can expand to. Throws LimitError naming the file (and part).
void checkDeclaredImage(const std::string& path, const DeclaredImage& image);

// Tiled formats (TIFF, OpenEXR): their decoders allocate a whole tile whatever the image's size,
// so a tile over 2^24 pixels (either side, or its area) is refused as over the limit, naming it.
void checkTileSize(const std::string& path, const std::string& format, std::uint64_t width,
                   std::uint64_t height);

// The most bytes a complete file of this declaration can take (for standard input, read before
// it is whole): the data the parts' pixels need at worst (incompressible data expands them a
// little) plus room for metadata; 0 when the header does not say enough to bound it.
std::uint64_t plausibleFileBytes(const DeclaredImage& image);

} // namespace lut::formats
