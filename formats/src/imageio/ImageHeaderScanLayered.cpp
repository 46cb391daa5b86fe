// SPDX-License-Identifier: Apache-2.0
// Header scanners for PSD, DPX and Maya IFF (ImageHeaderScan.h): formats whose headers list
// sections, layers or elements, each with a size OpenImageIO allocates when it opens the file.
#include "imageio/ImageHeaderScan.h"

#include "lut/Error.h"

#include <algorithm>

namespace lut::formats {

namespace {

std::uint64_t ceilDiv(std::uint64_t a, std::uint64_t b) {
    return b == 0 ? 0 : (a + b - 1) / b;
}

[[noreturn]] void pastEnd(const std::string& path, const std::string& what, std::uint64_t bytes,
                          std::uint64_t left) {
    throw Error(path + ": " + what + " declares " + std::to_string(bytes) + " bytes, but only " +
                std::to_string(left) + " follow in the file (truncated or corrupt)");
}

std::pair<double, const char*> psdCodec(std::uint64_t compression) {
    switch (compression) {
    case 0:
        return {1.0, "uncompressed"};
    case 1:
        return {64.0, "PackBits"};
    case 2:
    case 3:
        return {1032.0, "deflate"};
    default:
        return {0.0, "this compression"};
    }
}

} // namespace

// PSD and PSB (Adobe Photoshop File Formats Specification): a 26-byte header (channels, height,
// width, depth), then three sections each led by its length (colour mode data, image resources,
// layers and masks), then the merged image. Every length is checked against the file before
// OpenImageIO reads it: a 62-byte file claiming a 2 GB colour mode block made it allocate 2 GB.
// Layer records give each layer's rectangle and its channels' byte counts, which bound the
// layer like an image (OpenImageIO sizes a table per row of each layer when it opens the file).
DeclaredImage scanPsd(const HeaderBytes& b, const std::string& path) {
    DeclaredImage d;
    d.format = "psd";
    const std::uint64_t version = b.be(4, 2);
    const std::uint64_t channels = b.be(12, 2), h = b.be(14, 4), w = b.be(18, 4);
    const std::uint64_t depth = b.be(22, 2);
    if ((version != 1 && version != 2) || channels < 1 || channels > 56 ||
        (depth != 1 && depth != 8 && depth != 16 && depth != 32))
        return d;
    const bool psb = version == 2;
    const int lengthSize = psb ? 8 : 4;
    const std::uint64_t size = b.size();
    std::uint64_t at = 26;
    auto section = [&](const char* what, int bytes) {
        if (at + static_cast<std::uint64_t>(bytes) > size) {
            if (!b.whole())
                return false;
            throw Error(path + ": PSD file ends before its " + what + " (truncated)");
        }
        const std::uint64_t len = b.be(at, bytes);
        at += static_cast<std::uint64_t>(bytes);
        if (len > size - at) {
            if (!b.whole())
                return false;
            pastEnd(path, std::string("PSD ") + what, len, size - at);
        }
        at += len;
        return true;
    };
    if (!section("colour mode data", 4) || !section("image resources", 4)) {
        d.complete = false;
        return d;
    }
    // Layers and masks: the section's length, the layer info's length, the layer count.
    const std::uint64_t layersAt = at + static_cast<std::uint64_t>(lengthSize);
    if (!section("layer and mask information", lengthSize)) {
        d.complete = false;
        return d;
    }
    const std::uint64_t layersEnd = at;
    if (layersEnd > layersAt + static_cast<std::uint64_t>(lengthSize) + 2) {
        const std::uint64_t infoLength = b.be(layersAt, lengthSize);
        std::uint64_t r = layersAt + static_cast<std::uint64_t>(lengthSize);
        if (infoLength > layersEnd - r)
            pastEnd(path, "PSD layer information", infoLength, layersEnd - r);
        const auto signedCount = static_cast<std::int16_t>(b.be(r, 2));
        const int count = signedCount < 0 ? -signedCount : signedCount;
        r += 2;
        struct Layer {
            std::int64_t w = 0, h = 0;
            std::vector<std::uint64_t> lengths;
        };
        std::vector<Layer> layers;
        for (int i = 0; i < count && infoLength > 0; ++i) {
            if (r + 18 > layersEnd)
                throw Error(path + ": PSD layer record " + std::to_string(i + 1) +
                            " runs past its section (corrupt)");
            Layer l;
            const auto top = static_cast<std::int32_t>(b.be(r, 4));
            const auto left = static_cast<std::int32_t>(b.be(r + 4, 4));
            const auto bottom = static_cast<std::int32_t>(b.be(r + 8, 4));
            const auto right = static_cast<std::int32_t>(b.be(r + 12, 4));
            l.h = static_cast<std::int64_t>(bottom) - top;
            l.w = static_cast<std::int64_t>(right) - left;
            if (l.w < 0 || l.h < 0)
                throw Error(path + ": PSD layer " + std::to_string(i + 1) +
                            " has an inverted rectangle (corrupt)");
            const std::uint64_t nch = b.be(r + 16, 2);
            r += 18;
            for (std::uint64_t c = 0; c < nch; ++c) {
                if (r + 2 + static_cast<std::uint64_t>(lengthSize) > layersEnd)
                    throw Error(path + ": PSD layer record " + std::to_string(i + 1) +
                                " runs past its section (corrupt)");
                l.lengths.push_back(b.be(r + 2, lengthSize));
                r += 2 + static_cast<std::uint64_t>(lengthSize);
            }
            r += 12; // blend mode signature and key, opacity, clipping, flags, filler
            const std::uint64_t extra = b.be(r, 4);
            r += 4;
            if (r > layersEnd || extra > layersEnd - r)
                throw Error(path + ": PSD layer record " + std::to_string(i + 1) +
                            " runs past its section (corrupt)");
            r += extra;
            layers.push_back(std::move(l));
        }
        // Each channel's data: a 2-byte compression, then the pixels.
        for (std::size_t i = 0; i < layers.size(); ++i) {
            DeclaredPart p;
            p.what = "layer " + std::to_string(i + 1);
            p.width = static_cast<std::uint64_t>(layers[i].w);
            p.height = static_cast<std::uint64_t>(layers[i].h);
            p.channels = static_cast<int>(std::min<std::size_t>(layers[i].lengths.size(), 64));
            for (const std::uint64_t len : layers[i].lengths) {
                if (r > layersEnd || len > layersEnd - r)
                    pastEnd(path, "PSD " + p.what + " channel data", len,
                            layersEnd > r ? layersEnd - r : 0);
                const std::uint64_t rowBytes = ceilDiv(p.width * depth, 8);
                const std::uint64_t compression = len >= 2 ? b.be(r, 2) : 0;
                const auto [ratio, codec] = psdCodec(compression);
                // A channel's rows: RLE keeps a byte count per row before them.
                const std::uint64_t counts = compression == 1 ? p.height * (psb ? 4 : 2) : 0;
                if (compression == 1 && counts > len)
                    pastEnd(path, "PSD " + p.what + " row table", counts, len);
                if (p.width > 0 && p.height > 0 && len >= 2) {
                    p.storedBytes += p.height * rowBytes;
                    p.dataBytes += len - 2 - std::min(len - 2, counts);
                    p.maxRatio = std::max(p.maxRatio, ratio);
                    p.codec = codec;
                }
                r += len;
            }
            if (p.storedBytes > 0)
                d.parts.push_back(p);
        }
    }
    // The merged image: every channel, one after the other.
    DeclaredPart merged;
    merged.width = w;
    merged.height = h;
    merged.channels = static_cast<int>(channels);
    merged.storedBytes = channels * h * ceilDiv(w * depth, 8);
    if (layersEnd + 2 <= size) {
        const std::uint64_t compression = b.be(layersEnd, 2);
        const std::uint64_t counts = compression == 1 ? channels * h * (psb ? 4 : 2) : 0;
        const std::uint64_t data = size - layersEnd - 2;
        if (counts > data && b.whole())
            pastEnd(path, "PSD merged image's row table", counts, data);
        merged.dataBytes = data - std::min(data, counts);
        const auto [ratio, codec] = psdCodec(compression);
        merged.maxRatio = ratio;
        merged.codec = codec;
    } else if (!b.whole()) {
        d.complete = false;
    }
    d.parts.insert(d.parts.begin(), merged);
    return d;
}

// DPX (SMPTE 268M): "SDPX" big-endian or "XPDS" little-endian; the generic header gives the size
// of the user data (at byte 2048), the image header (byte 768) the number of image elements
// (OpenImageIO's subimages, at most 8), the pixels per line and lines, and each element (72 bytes
// from byte 780) its descriptor (the components), bit depth, packing, encoding and where its data
// starts. Uncompressed: the data must hold every line (10-bit samples filled three to a 32-bit
// word, 12-bit ones in 16 bits). OpenImageIO allocates the user data whole when it opens the
// file: a 9 KB file whose user data size said 2 GB took 14 GB (found by fuzz_image_apply), one
// saying 4 GB aborted; a 2 KB file claiming 32704x32704 made it ask for 4.3 GB. Run-length
// encoded elements are refused: OpenImageIO 2.4 does not decode them, but sized a row buffer
// from the width first (a 268435456-pixel line: 384 GB asked for).
DeclaredImage scanDpx(const HeaderBytes& b, const std::string& path) {
    DeclaredImage d;
    d.format = "dpx";
    const bool big = b.get(0, 4) == "SDPX";
    auto num = [&](std::uint64_t at, int n) { return big ? b.be(at, n) : b.le(at, n); };
    if (b.size() < 812)
        return d;
    constexpr std::uint64_t kUserDataAt = 2048;
    const std::uint64_t user = num(32, 4);
    if (user != 0 && user != 0xFFFFFFFFu && b.whole() &&
        (b.size() < kUserDataAt || user > b.size() - kUserDataAt))
        pastEnd(path, "DPX user data (its size at byte 32)", user,
                b.size() > kUserDataAt ? b.size() - kUserDataAt : 0);
    const std::uint64_t w = num(772, 4), h = num(776, 4);
    const std::uint64_t declared = num(770, 2);
    if (declared > 8)
        throw Error(path + ": DPX header declares " + std::to_string(declared) +
                    " image elements (at most 8): corrupt");
    const std::uint64_t elements = std::clamp<std::uint64_t>(declared, 1, 8);
    for (std::uint64_t e = 0; e < elements; ++e) {
        const std::uint64_t at = 780 + 72 * e;
        const int descriptor = b.byte(at + 20), bits = b.byte(at + 23);
        const std::uint64_t packing = num(at + 24, 2), encoding = num(at + 26, 2);
        std::uint64_t offset = num(at + 28, 4);
        if (offset == 0 || offset == 0xFFFFFFFFu)
            offset = num(4, 4);
        if (encoding == 1)
            throw Error(path + ": DPX image element " + std::to_string(e + 1) +
                        " is run-length encoded, which OpenImageIO's DPX reader does not decode");
        int comps = 1;
        if (descriptor == 50 || descriptor == 102)
            comps = 3;
        else if (descriptor == 51 || descriptor == 52 || descriptor == 103)
            comps = 4;
        else if (descriptor == 100)
            comps = 2;
        else if (descriptor == 101)
            comps = 3;
        else if (descriptor >= 150 && descriptor <= 156)
            comps = descriptor - 148;
        std::uint64_t rowBytes = 0;
        if (bits == 10 && packing != 0)
            rowBytes = ceilDiv(w * static_cast<std::uint64_t>(comps), 3) * 4;
        else if (bits == 12 && packing != 0)
            rowBytes = w * static_cast<std::uint64_t>(comps) * 2;
        else
            rowBytes = w * static_cast<std::uint64_t>(comps) * static_cast<std::uint64_t>(bits) / 8;
        DeclaredPart p;
        if (elements > 1)
            p.what = "image element " + std::to_string(e + 1);
        p.width = w;
        p.height = h;
        p.channels = comps;
        p.storedBytes = rowBytes * h;
        p.dataBytes = offset < b.size() ? b.size() - offset : 0;
        p.maxRatio = 1.0;
        p.codec = "uncompressed";
        d.parts.push_back(p);
    }
    return d;
}

namespace {

// Maya IFF tiles as OpenImageIO 2.4 decodes them (IffInput::readimg), from `at` (the first chunk
// inside "FOR4" <size> "TBMP"): chunks in order until `tiles` "RGBA" chunks were read, each
// x0, y0, x1, y1 (16 bits) then its data; a tile whose chunk is smaller than its pixels is RLE,
// one stream per channel byte (a count byte: bit 7 a run of the next byte, else that many + 1
// literal bytes). The decoder stops only when a stream has filled the tile, so a run that goes
// past it writes past its buffer, and a stream that ends early reads past the chunk (valgrind:
// a fuzzed 652-byte IFF wrote past a 192-byte tile buffer; under ASan, the heap corruption
// docs/robustness.md tracked). Returns what is wrong with the first such tile, or "".
std::string iffTileDefect(const HeaderBytes& b, std::uint64_t at, std::uint64_t tiles,
                          std::uint64_t width, std::uint64_t height, std::uint64_t bytesPerPixel) {
    for (std::uint64_t t = 0; t < tiles;) {
        if (at + 8 > b.size())
            return ""; // the file ends: the codec says the data is missing
        const std::uint64_t size = b.be(at + 4, 4);
        const std::uint64_t data = at + 8;
        at = data + (size + 3) / 4 * 4;
        if (b.get(data - 8, 4) != "RGBA")
            continue;
        ++t;
        const std::string who = "IFF tile " + std::to_string(t) + " of " + std::to_string(tiles);
        // Its chunk is read whole into a buffer of the declared size (a fuzzed 2 GB).
        if (size > b.size() - data)
            return who + " declares " + std::to_string(size) + " bytes, but only " +
                   std::to_string(b.size() - data) + " follow in the file";
        const std::uint64_t x0 = b.be(data, 2), y0 = b.be(data + 2, 2);
        const std::uint64_t x1 = b.be(data + 4, 2), y1 = b.be(data + 6, 2);
        if (size < 8 || x0 > x1 || y0 > y1 || x1 >= width || y1 >= height)
            return who + " lies outside the image or has no pixels";
        const std::uint64_t pixels = (x1 - x0 + 1) * (y1 - y0 + 1);
        if (pixels * bytesPerPixel + 8 <= size)
            continue; // stored uncompressed
        std::uint64_t in = data + 8;
        const std::uint64_t end = std::min(b.size(), data + size);
        for (std::uint64_t stream = 0; stream < bytesPerPixel; ++stream) {
            std::uint64_t out = 0;
            while (out < pixels) {
                if (in >= end)
                    return who + ": its RLE data ends before the tile is filled";
                const int code = b.byte(in++);
                const std::uint64_t count = static_cast<std::uint64_t>(code & 0x7f) + 1;
                in += (code & 0x80) ? 1 : count;
                out += count;
                if (out > pixels)
                    return who + ": an RLE run goes past the tile's " + std::to_string(pixels) +
                           " pixels";
            }
            if (in > end)
                return who + ": its RLE data ends before the tile is filled";
        }
    }
    return "";
}

} // namespace

// Maya IFF: "FOR4" <size> "CIMG", then chunks; TBHD gives width, height, the channels (flags:
// RGB, alpha), 8 or 16 bits, the tile count and the compression (per-channel runs of at most 128
// in two bytes: bounded at 64:1). OpenImageIO reads every tile of the image at the first row;
// its RLE decoder trusts the runs (iffTileDefect above), so a whole file's tiles are checked.
DeclaredImage scanIff(const HeaderBytes& b, const std::string& path) {
    DeclaredImage d;
    d.format = "iff";
    std::uint64_t at = 12, tiles = 0, bytesPerPixel = 0;
    for (int chunks = 0; chunks < 256 && at + 8 <= b.size(); ++chunks) {
        const std::string id = b.get(at, 4);
        const std::uint64_t len = b.be(at + 4, 4);
        if (id == "FOR4" && b.get(at + 8, 4) == "TBMP") {
            if (!d.parts.empty()) // the tiles
                d.parts.back().corruptBlock = iffTileDefect(b, at + 12, tiles, d.parts.back().width,
                                                            d.parts.back().height, bytesPerPixel);
            return d;
        }
        // OpenImageIO's header reader takes the chunks before the tiles (AUTH, DATE...) whole: a
        // fuzzed DATE of 3.7 GB in a 1.5 KB file was allocated.
        if (b.whole() && len > b.size() - (at + 8))
            pastEnd(path, "IFF chunk '" + id + "' at byte " + std::to_string(at), len,
                    b.size() - (at + 8));
        if (id == "TBHD" && len >= 24 && d.parts.empty()) {
            const std::uint64_t w = b.be(at + 8, 4), h = b.be(at + 12, 4);
            const std::uint64_t flags = b.be(at + 20, 4), bytes = b.be(at + 24, 2);
            const std::uint64_t compression = b.be(at + 28, 4);
            tiles = b.be(at + 26, 2);
            const int channels = ((flags & 1) ? 3 : 0) + ((flags & 2) ? 1 : 0);
            // A depth-only image (flag 4) stores 32-bit floats, "bytes" 0; OpenImageIO asserts
            // that and aborts the process otherwise (a fuzzed header: exit 134, no message).
            if (channels == 0 && (flags & 4) && bytes != 0)
                throw Error(path + ": IFF header (TBHD) declares a depth-only image with " +
                            std::to_string(bytes) +
                            " in its bytes field, where only 0 (32-bit depth) is valid (corrupt)");
            // Colour with the "black" flag (16): asserted the same way.
            if (channels > 0 && (flags & 16))
                throw Error(path + ": IFF header (TBHD) flags colour channels and 'black' (" +
                            std::to_string(flags) + "), which exclude each other (corrupt)");
            // The image's origin: OpenImageIO 2.4 takes it as the data window's and then cuts
            // tiles as if it were 0 (a fuzzed x of 33 in a 16-wide image: memcpy of -51 bytes).
            const std::uint64_t x = len >= 32 ? b.be(at + 32, 4) : 0;
            const std::uint64_t y = len >= 32 ? b.be(at + 36, 4) : 0;
            if (x != 0 || y != 0)
                throw Error(path + ": IFF header (TBHD) places the image at (" + std::to_string(x) +
                            ", " + std::to_string(y) +
                            "); OpenImageIO's reader handles only (0, 0)");
            // No colour channels: no part, but the chunks' sizes are still checked.
            if (channels > 0) {
                bytesPerPixel = static_cast<std::uint64_t>(channels) * (bytes ? 2 : 1);
                DeclaredPart p;
                p.width = w;
                p.height = h;
                p.channels = channels;
                p.storedBytes = w * h * bytesPerPixel;
                p.dataBytes = b.size();
                p.maxRatio = compression == 1 ? 64.0 : compression == 0 ? 1.0 : 0.0;
                p.codec = compression == 1 ? "RLE" : "uncompressed";
                d.parts.push_back(p);
                d.decoderBytes = p.storedBytes;
                if (!b.whole())
                    return d; // a stream: the rest is the codec's to check
            }
        }
        at += 8 + (len + 3) / 4 * 4;
    }
    d.complete = b.whole() || !d.parts.empty();
    return d;
}

} // namespace lut::formats
