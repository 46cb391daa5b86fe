// SPDX-License-Identifier: Apache-2.0
// Header scanners for the single-image raster formats (ImageHeaderScan.h): PNG, JPEG, GIF, BMP,
// TGA, Radiance HDR and WebP. Each reads the fields its format's specification puts first and
// says how far the codec can expand its bytes; docs/robustness.md gives each bound's reasoning
// and the ratios measured on the most compressible files the usual encoders write.
#include "imageio/ImageHeaderScan.h"

#include "lut/Error.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>

namespace lut::formats {

namespace {

std::uint64_t ceilDiv(std::uint64_t a, std::uint64_t b) {
    return (a + b - 1) / b;
}

DeclaredPart part(std::uint64_t w, std::uint64_t h, int channels, std::uint64_t stored,
                  std::uint64_t data, double ratio, const char* codec) {
    DeclaredPart p;
    p.width = w;
    p.height = h;
    p.channels = channels;
    p.storedBytes = stored;
    p.dataBytes = data;
    p.maxRatio = ratio;
    p.codec = codec;
    return p;
}

} // namespace

// PNG (ISO/IEC 15948): IHDR, then the chunks; the pixels are the IDAT chunks' bytes, deflated
// (at most 1032:1: a 258-byte match in two 1-bit codes). Counting IDAT, not the file, is what
// catches a file padded with a private chunk.
DeclaredImage scanPng(const HeaderBytes& b, const std::string& path) {
    (void)path;
    DeclaredImage d;
    d.format = "png";
    if (b.get(12, 4) != "IHDR")
        return d;
    const std::uint64_t w = b.be(16, 4), h = b.be(20, 4);
    const int depth = b.byte(24), colour = b.byte(25), interlace = b.byte(28);
    const int samples = colour == 0   ? 1
                        : colour == 2 ? 3
                        : colour == 3 ? 1
                        : colour == 4 ? 2
                        : colour == 6 ? 4
                                      : 0;
    if (samples == 0 || (depth != 1 && depth != 2 && depth != 4 && depth != 8 && depth != 16))
        return d;
    std::uint64_t idat = 0;
    std::uint64_t at = 8;
    for (int chunks = 0; at + 8 <= b.size() && chunks < 1000000; ++chunks) {
        const std::uint64_t len = b.be(at, 4);
        const std::string type = b.get(at + 4, 4);
        if (type == "IDAT")
            idat += std::min<std::uint64_t>(len, b.size() - at - 8);
        if (type == "IEND" || len > (std::uint64_t(1) << 31))
            break;
        at += 12 + len;
    }
    const std::uint64_t rowBytes = ceilDiv(w * static_cast<std::uint64_t>(samples * depth), 8);
    // Interlaced: the seven passes' rows have their own filter bytes; the pixels alone are a
    // lower bound of what is stored.
    const std::uint64_t stored = h * (rowBytes + (interlace ? 0 : 1));
    const int channels = colour == 3 ? 3 : samples;
    d.parts.push_back(part(w, h, channels, stored, idat, 1032.0, "deflate"));
    if (interlace) // decoded whole, then handed out row by row
        d.decoderBytes = w * h * static_cast<std::uint64_t>(channels) * (depth == 16 ? 2 : 1);
    return d;
}

// JPEG (ITU T.81): markers up to the first scan; the frame header (SOFn) gives the size, the
// components and their sampling. Huffman-coded data spends at least one bit per 8x8 block of
// each component (the DC code of a progressive file's first scan; two in a sequential one), so
// an MCU's blocks bound how many pixels a byte can hold. Arithmetic coding (SOF9-15) has no such
// bound: it gets 64 times Huffman's (policy, docs/robustness.md).
DeclaredImage scanJpeg(const HeaderBytes& b, const std::string& path) {
    (void)path;
    DeclaredImage d;
    d.format = "jpeg";
    d.complete = false;
    std::uint64_t at = 2, dataStart = 0;
    int sof = -1;
    std::uint64_t w = 0, h = 0;
    int precision = 8, comps = 0, hMax = 1, vMax = 1, blocksPerMcu = 0;
    for (int markers = 0; markers < 100000 && at + 4 <= b.size(); ++markers) {
        if (b.byte(at) != 0xFF)
            break;
        const int m = b.byte(at + 1);
        if (m == 0xFF) { // fill byte
            ++at;
            continue;
        }
        if (m == 0xD8 || m == 0x01 || (m >= 0xD0 && m <= 0xD7)) {
            at += 2;
            continue;
        }
        if (m == 0xD9)
            break;
        const std::uint64_t len = b.be(at + 2, 2);
        if (len < 2)
            break;
        const bool isSof = m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC;
        if (isSof && sof < 0) {
            sof = m;
            precision = b.byte(at + 4);
            h = b.be(at + 5, 2);
            w = b.be(at + 7, 2);
            comps = std::max(0, b.byte(at + 9));
            blocksPerMcu = 0;
            for (int c = 0; c < comps; ++c) {
                const int hv = std::max(0, b.byte(at + 11 + 3 * static_cast<std::uint64_t>(c)));
                const int hs = std::max(1, hv >> 4), vs = std::max(1, hv & 15);
                hMax = std::max(hMax, hs);
                vMax = std::max(vMax, vs);
                blocksPerMcu += hs * vs;
            }
        }
        if (m == 0xDA) {
            dataStart = at + 2 + len;
            d.complete = true;
            break;
        }
        at += 2 + len;
    }
    if (sof < 0 || w == 0 || h == 0 || comps <= 0 || blocksPerMcu <= 0)
        return d; // the codec says what is wrong (a height of 0 needs a DNL marker: refused)
    d.complete = true;
    const int bps = precision > 8 ? 2 : 1;
    const bool arithmetic = sof >= 0xC9;
    const double perMcu = 64.0 * hMax * vMax * comps * bps;
    const double ratio = perMcu * 8.0 / blocksPerMcu * (arithmetic ? 64.0 : 1.0);
    const std::uint64_t data = dataStart > 0 && dataStart < b.size() ? b.size() - dataStart : 0;
    d.parts.push_back(part(w, h, comps == 4 ? 3 : comps,
                           w * h * static_cast<std::uint64_t>(comps * bps), data, ratio,
                           arithmetic ? "arithmetic-coded JPEG" : "Huffman-coded JPEG"));
    // Progressive (and arithmetic-coded progressive) files: libjpeg keeps every block's
    // coefficients (64 of 2 bytes each) until the last scan.
    if (sof == 0xC2 || sof == 0xC6 || sof == 0xCA || sof == 0xCE)
        d.decoderBytes = ceilDiv(w, 8 * static_cast<std::uint64_t>(hMax)) *
                         ceilDiv(h, 8 * static_cast<std::uint64_t>(vMax)) *
                         static_cast<std::uint64_t>(blocksPerMcu) * 128;
    return d;
}

// GIF (89a): the logical screen (OpenImageIO composes every frame on an RGBA canvas of that
// size), then image descriptors, each followed by its LZW data in sub-blocks. LZW with 12-bit
// codes emits at most 4096 indices per code: bounded at 4096 stored bytes per data byte.
// The screen is what the reader allocates and what lutkit writes, but the file stores only its
// frames (the rest is background): a 962-byte file whose 56610x3862 screen held small frames
// took an 874 MB canvas. A screen over kGifFreeScreenPixels (a 64 MiB canvas) counts as stored
// pixels, so the file's LZW data must be able to cover it.
constexpr std::uint64_t kGifFreeScreenPixels = std::uint64_t(1) << 24;
DeclaredImage scanGif(const HeaderBytes& b, const std::string& path) {
    (void)path;
    DeclaredImage d;
    d.format = "gif";
    const std::uint64_t sw = b.le(6, 2), sh = b.le(8, 2);
    const int flags = b.byte(10);
    std::uint64_t at = 13 + ((flags & 0x80) ? 3 * (std::uint64_t(2) << (flags & 7)) : 0);
    std::uint64_t stored = 0, data = 0, frames = 0, widest = 0;
    DeclaredPart largest;
    auto skipBlocks = [&] {
        for (int n; at < b.size() && (n = b.byte(at)) > 0;) {
            data += static_cast<std::uint64_t>(n);
            at += static_cast<std::uint64_t>(n) + 1;
        }
        ++at;
    };
    d.complete = false;
    while (at < b.size() && frames < 100000) {
        const int c = b.byte(at);
        if (c == 0x2C) {
            const std::uint64_t fw = b.le(at + 5, 2), fh = b.le(at + 7, 2);
            const int fflags = b.byte(at + 9);
            at += 10 + ((fflags & 0x80) ? 3 * (std::uint64_t(2) << (fflags & 7)) : 0) + 1;
            stored += fw * fh;
            widest = std::max(widest, fw);
            if (fw * fh > largest.width * largest.height)
                largest = part(fw, fh, 4, 0, 0, 0.0, "LZW");
            ++frames;
            skipBlocks();
        } else if (c == 0x21) {
            at += 2;
            const std::uint64_t before = data;
            skipBlocks();
            data = before; // extension bytes hold no pixels
        } else {
            d.complete = c == 0x3B;
            break;
        }
    }
    d.complete = d.complete || b.whole();
    DeclaredPart screen =
        part(sw, sh, 4, sw * sh > kGifFreeScreenPixels ? std::max(stored, sw * sh) : stored, data,
             4096.0, "LZW");
    screen.what = frames > 1 ? std::to_string(frames) + " frames" : "";
    d.parts.push_back(screen);
    if (largest.width * largest.height > sw * sh) {
        largest.what = "a frame";
        d.parts.push_back(largest); // the pixel limit for a frame larger than the screen
    }
    d.decoderBytes = sw * sh * 4 + widest;
    return d;
}

// BMP (Windows DIB): the file header's pixel offset, the info header's size, bit count and
// compression. Rows are padded to 4 bytes and stored whole; RLE8/RLE4 code at most 255 pixels in
// two bytes (bounded at 128 stored bytes per data byte, the declared size against the file's:
// deltas may skip more, but a file holding less than 1/128 of its pixels is refused). The
// native reader (BmpCodec.cpp) streams rows and says what it holds itself (ImageInfo).
DeclaredImage scanBmp(const HeaderBytes& b, const std::string& path) {
    (void)path;
    DeclaredImage d;
    d.format = "bmp";
    const std::uint64_t offBits = b.le(10, 4);
    const std::uint64_t infoSize = b.le(14, 4);
    std::uint64_t w = 0, h = 0;
    int bpp = 0;
    std::uint64_t compression = 0;
    if (infoSize == 12) {
        w = b.le(18, 2);
        h = b.le(20, 2);
        bpp = static_cast<int>(b.le(24, 2));
    } else if (infoSize >= 40) {
        const auto sw = static_cast<std::int32_t>(b.le(18, 4));
        const auto sh = static_cast<std::int32_t>(b.le(22, 4));
        w = static_cast<std::uint64_t>(sw < 0 ? -static_cast<std::int64_t>(sw) : sw);
        h = static_cast<std::uint64_t>(sh < 0 ? -static_cast<std::int64_t>(sh) : sh);
        bpp = static_cast<int>(b.le(28, 2));
        compression = b.le(30, 4);
    } else {
        return d;
    }
    if (bpp != 1 && bpp != 4 && bpp != 8 && bpp != 16 && bpp != 24 && bpp != 32)
        return d;
    const std::uint64_t data = offBits < b.size() ? b.size() - offBits : 0;
    const int channels = bpp == 32 ? 4 : 3;
    if (compression == 1 || compression == 2) {
        d.parts.push_back(part(w, h, channels, h * ceilDiv(w * static_cast<std::uint64_t>(bpp), 8),
                               data, 128.0, "RLE"));
    } else if (compression == 0 || compression == 3 || compression == 6) {
        const std::uint64_t stride = ceilDiv(w * static_cast<std::uint64_t>(bpp), 32) * 4;
        d.parts.push_back(part(w, h, channels, stride * h, data, 1.0, "uncompressed"));
    }
    return d;
}

// TGA (Truevision 2.0): an 18-byte header and no magic number (told by the file's name, the
// named format or the 2.0 footer). Raw or RLE packets of at most 128 pixels after a 1-byte
// header (bounded at 128:1). The native reader (TgaCodec.cpp) streams rows and says what it
// holds itself (ImageInfo).
DeclaredImage scanTga(const HeaderBytes& b, const std::string& path) {
    DeclaredImage d;
    d.format = "targa";
    const int idLength = b.byte(0), cmapType = b.byte(1), type = b.byte(2);
    const std::uint64_t cmapLength = b.le(5, 2);
    const int cmapBits = b.byte(7);
    const std::uint64_t w = b.le(12, 2), h = b.le(14, 2);
    const int bpp = b.byte(16);
    const bool rle = type >= 9;
    if (b.size() < 18 || (cmapType != 0 && cmapType != 1) ||
        (type != 1 && type != 2 && type != 3 && type != 9 && type != 10 && type != 11) ||
        (bpp != 8 && bpp != 15 && bpp != 16 && bpp != 24 && bpp != 32))
        return d;
    const std::uint64_t offset = 18 + static_cast<std::uint64_t>(idLength) +
                                 (cmapType ? cmapLength * ceilDiv(std::max(cmapBits, 0), 8) : 0);
    if (b.whole() && offset > b.size())
        throw Error(path + ": TGA colour map of " + std::to_string(cmapLength) +
                    " entries runs past the end of the file (truncated or corrupt)");
    const bool grey = type == 3 || type == 11;
    const int channels = grey ? (bpp == 16 ? 2 : 1) : bpp == 32 ? 4 : 3;
    const std::uint64_t stored = w * h * ceilDiv(static_cast<std::uint64_t>(bpp), 8);
    const std::uint64_t data = offset < b.size() ? b.size() - offset : 0;
    d.parts.push_back(
        part(w, h, channels, stored, data, rle ? 128.0 : 1.0, rle ? "RLE" : "uncompressed"));
    return d;
}

// Radiance RGBE: text header lines up to a blank line, then the resolution ("-Y H +X W").
// Scanlines 8..32767 pixels wide may be run-length coded per component (runs of up to 127 in two
// bytes: bounded at 64:1); any other width is stored flat, 4 bytes a pixel.
DeclaredImage scanHdr(const HeaderBytes& b, const std::string& path) {
    (void)path;
    DeclaredImage d;
    d.format = "hdr";
    const std::string head = b.get(0, 65536);
    const auto blank = head.find("\n\n");
    if (blank == std::string::npos) {
        d.complete = b.whole();
        return d;
    }
    const auto eol = head.find('\n', blank + 2);
    if (eol == std::string::npos) {
        d.complete = b.whole();
        return d;
    }
    char a1 = 0, a2 = 0, s1 = 0, s2 = 0;
    unsigned long long n1 = 0, n2 = 0;
    const std::string res = head.substr(blank + 2, eol - blank - 2);
    if (std::sscanf(res.c_str(), "%c%c %llu %c%c %llu", &s1, &a1, &n1, &s2, &a2, &n2) != 6 ||
        (s1 != '-' && s1 != '+') || (s2 != '-' && s2 != '+') || a1 == a2 ||
        (a1 != 'X' && a1 != 'Y') || (a2 != 'X' && a2 != 'Y'))
        return d;
    const std::uint64_t h = a1 == 'Y' ? n1 : n2, w = a1 == 'Y' ? n2 : n1;
    const bool rle = w >= 8 && w <= 0x7fff;
    const std::uint64_t data = b.size() > eol + 1 ? b.size() - eol - 1 : 0;
    d.parts.push_back(
        part(w, h, 3, w * h * 4, data, rle ? 64.0 : 1.0, rle ? "RLE" : "uncompressed"));
    return d;
}

// WebP (RIFF): the first chunk gives the size: VP8 (lossy: 14-bit width and height after the
// start code), VP8L (lossless: 14-bit fields after the signature byte) or VP8X (extended: a
// 24-bit canvas). Both coders can spend almost nothing on a flat area; the bound is the ratio
// measured on flat images times 8 (docs/robustness.md). OpenImageIO decodes the whole image.
DeclaredImage scanWebp(const HeaderBytes& b, const std::string& path) {
    (void)path;
    DeclaredImage d;
    d.format = "webp";
    const std::string chunk = b.get(12, 4);
    std::uint64_t w = 0, h = 0;
    bool lossless = false;
    if (chunk == "VP8 " && b.get(23, 3) == "\x9d\x01\x2a") {
        w = b.le(26, 2) & 0x3fff;
        h = b.le(28, 2) & 0x3fff;
    } else if (chunk == "VP8L" && b.byte(20) == 0x2f) {
        const std::uint64_t bits = b.le(21, 4);
        w = (bits & 0x3fff) + 1;
        h = ((bits >> 14) & 0x3fff) + 1;
        lossless = true;
    } else if (chunk == "VP8X") {
        w = b.le(24, 3) + 1;
        h = b.le(27, 3) + 1;
    } else {
        return d;
    }
    d.parts.push_back(part(w, h, 4, w * h * 4, b.size(), lossless ? 65536.0 : 32768.0,
                           lossless ? "lossless WebP" : "WebP"));
    d.decoderBytes = w * h * 4;
    return d;
}

// PNM (Netpbm): "P5"/"P6" (binary grey, RGB; also the ASCII P1-P3 and P4, P7 OpenImageIO
// reads), then width, height and, but for bitmaps, maxval as text. Binary samples are stored
// flat (one or two bytes, P4 one bit); the native codec then wants exactly that many bytes.
DeclaredImage scanPnm(const HeaderBytes& b, const std::string& path) {
    (void)path;
    DeclaredImage d;
    d.format = "pnm";
    const int kind = b.byte(1) - '0';
    const std::string head = b.get(0, 4096);
    std::uint64_t v[3] = {0, 0, 1};
    std::size_t i = 2;
    const int fields = kind == 1 || kind == 4 ? 2 : 3;
    for (int k = 0; k < fields; ++k) {
        for (;;) { // blanks and comments
            while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i])))
                ++i;
            if (i < head.size() && head[i] == '#') {
                while (i < head.size() && head[i] != '\n')
                    ++i;
                continue;
            }
            break;
        }
        if (i >= head.size() || !std::isdigit(static_cast<unsigned char>(head[i])))
            return d; // the codec says what is wrong (P7's header is not numbers)
        v[k] = 0;
        while (i < head.size() && std::isdigit(static_cast<unsigned char>(head[i])) &&
               v[k] < (std::uint64_t(1) << 32))
            v[k] = v[k] * 10 + static_cast<std::uint64_t>(head[i++] - '0');
    }
    const std::uint64_t w = v[0], h = v[1], bytes = v[2] > 255 ? 2 : 1;
    const int channels = kind == 3 || kind == 6 ? 3 : 1;
    const std::uint64_t data = b.size() > i + 1 ? b.size() - i - 1 : 0;
    if (kind == 5 || kind == 6)
        d.parts.push_back(part(w, h, channels, w * h * static_cast<std::uint64_t>(channels) * bytes,
                               data, 1.0, "uncompressed"));
    else if (kind == 4)
        d.parts.push_back(part(w, h, 1, h * ceilDiv(w, 8), data, 1.0, "uncompressed"));
    else // ASCII: a sample takes a digit and a blank at least (a P1 bit: one character)
        d.parts.push_back(part(w, h, channels,
                               w * h * static_cast<std::uint64_t>(channels) * (kind == 1 ? 1 : 2),
                               data, 1.0, "ASCII"));
    return d;
}

} // namespace lut::formats
