// SPDX-License-Identifier: Apache-2.0
// Header scanner for TIFF (ImageHeaderScan.h): TIFF 6.0 and BigTIFF, every page (IFD) of the
// chain. What a page stores is its strips' or tiles' byte counts, each within the file; how far
// they can expand depends on the compression tag (docs/robustness.md).
#include "imageio/ImageHeaderScan.h"

#include "lut/Error.h"

#include <algorithm>
#include <set>
#include <vector>

namespace lut::formats {

namespace {

std::uint64_t ceilDiv(std::uint64_t a, std::uint64_t b) {
    return b == 0 ? 0 : (a + b - 1) / b;
}

int typeSize(std::uint64_t type) {
    switch (type) {
    case 1: // BYTE
    case 2: // ASCII
    case 6: // SBYTE
    case 7: // UNDEFINED
        return 1;
    case 3: // SHORT
    case 8: // SSHORT
        return 2;
    case 4:  // LONG
    case 9:  // SLONG
    case 11: // FLOAT
    case 13: // IFD
        return 4;
    case 5:  // RATIONAL
    case 10: // SRATIONAL
    case 12: // DOUBLE
    case 16: // LONG8
    case 17: // SLONG8
    case 18: // IFD8
        return 8;
    default:
        return 0;
    }
}

// The most stored bytes one byte of a TIFF compression can become, and its name.
std::pair<double, const char*> tiffCodec(std::uint64_t compression, std::uint64_t width) {
    switch (compression) {
    case 1:
        return {1.0, "uncompressed"};
    case 2:     // CCITT modified Huffman
    case 3:     // CCITT T.4
    case 4:     // CCITT T.6
    case 32771: // CCITT RLE, word-aligned
        // Bilevel: every row costs at least one bit, a row stores width/8 bytes.
        return {static_cast<double>(std::max<std::uint64_t>(1, width)), "CCITT fax"};
    case 5:
        return {4096.0, "LZW"};
    case 6:
    case 7:
        return {8192.0, "JPEG"};
    case 8:
    case 32946:
        return {1032.0, "deflate"};
    case 32773:
        return {64.0, "PackBits"};
    case 50000:
        return {32768.0, "Zstandard"};
    default:
        return {0.0, "this compression"};
    }
}

} // namespace

DeclaredImage scanTiff(const HeaderBytes& b, const std::string& path) {
    DeclaredImage d;
    d.format = "tiff";
    const bool little = b.get(0, 2) == "II";
    auto num = [&](std::uint64_t at, int n) { return little ? b.le(at, n) : b.be(at, n); };
    const std::uint64_t version = num(2, 2);
    if (version != 42 && version != 43)
        return d;
    const bool big = version == 43;
    const int countSize = big ? 8 : 2, entrySize = big ? 20 : 12, offsetSize = big ? 8 : 4;
    std::uint64_t ifd = num(big ? 8 : 4, offsetSize);
    std::set<std::uint64_t> seen;
    for (int page = 0; ifd != 0 && page < 1024; ++page) {
        const std::string where =
            "TIFF directory " + std::to_string(page + 1) + " (at byte " + std::to_string(ifd) + ")";
        if (!seen.insert(ifd).second)
            throw Error(path + ": " + where + " is listed twice: the directories form a loop");
        if (ifd > b.size() || b.size() - ifd < static_cast<std::uint64_t>(countSize)) {
            if (!b.whole()) {
                d.complete = false;
                return d;
            }
            throw Error(path + ": " + where + " is past the end of the file (truncated)");
        }
        const std::uint64_t n = num(ifd, countSize);
        const std::uint64_t entriesAt = ifd + static_cast<std::uint64_t>(countSize);
        const std::uint64_t end = entriesAt + n * static_cast<std::uint64_t>(entrySize) +
                                  static_cast<std::uint64_t>(offsetSize);
        if (n > 65535 || end > b.size()) {
            if (!b.whole()) {
                d.complete = false;
                return d;
            }
            throw Error(path + ": " + where + " lists " + std::to_string(n) +
                        " fields, past the end of the file (truncated or corrupt)");
        }
        const std::string entries = b.get(entriesAt, static_cast<std::size_t>(n) * entrySize);
        auto field = [&](std::size_t i, int at, int bytes) {
            std::uint64_t v = 0;
            for (int k = 0; k < bytes; ++k) {
                const auto byte = static_cast<unsigned char>(entries[i * entrySize + at + k]);
                v |= little ? static_cast<std::uint64_t>(byte) << (8 * k)
                            : static_cast<std::uint64_t>(byte) << (8 * (bytes - 1 - k));
            }
            return v;
        };
        std::uint64_t w = 0, h = 0, spp = 1, bps = 1, compression = 1, tw = 0, th = 0;
        std::uint64_t photometric = 2, data = 0;
        // Where a field's values are: its type, count, the offset (or the values, inline).
        struct Values {
            std::uint64_t type = 0, count = 0, at = 0;
            bool inline_ = false;
            std::size_t entry = 0;
        } offsets, counts;
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint64_t tag = field(i, 0, 2), type = field(i, 2, 2);
            const std::uint64_t count = field(i, 4, big ? 8 : 4);
            const int size = typeSize(type);
            const int valueAt = big ? 12 : 8;
            // Division, not count * size: a BigTIFF count is 64 bits, and 2^62 LONGs multiply
            // to 0 (a fuzzed file went on to loop over 2^62 strip counts).
            const bool inline_ =
                size > 0 && count > 0 && count <= static_cast<std::uint64_t>(offsetSize / size);
            auto value = [&](std::uint64_t k) -> std::uint64_t {
                if (size <= 0 || k >= count) // no such value (a count of 0 has none inline)
                    return 0;
                if (inline_)
                    return field(i, valueAt + static_cast<int>(k) * size, std::min(size, 8));
                const std::uint64_t at =
                    field(i, valueAt, offsetSize) + k * static_cast<std::uint64_t>(size);
                return num(at, std::min(size, 8));
            };
            if (size > 0 && count > b.size() / static_cast<std::uint64_t>(size))
                throw Error(path + ": " + where + ": field " + std::to_string(tag) + " lists " +
                            std::to_string(count) + " values, more than the file's " +
                            std::to_string(b.size()) + " bytes hold (corrupt)");
            switch (tag) {
            case 256:
                w = value(0);
                break;
            case 257:
                h = value(0);
                break;
            case 258:
                bps = value(0);
                break;
            case 259:
                compression = value(0);
                break;
            case 262:
                photometric = value(0);
                break;
            case 277:
                spp = value(0);
                break;
            case 322:
                tw = value(0);
                break;
            case 323:
                th = value(0);
                break;
            // Offsets and counts of a type without a size are not read: their count is not
            // bounded by the file (a fuzzed type 55556 with 3.6e9 counts looped over them all).
            case 273: // StripOffsets
            case 324: // TileOffsets
                if (size > 0)
                    offsets = {type, count, field(i, valueAt, offsetSize), inline_, i};
                break;
            case 279: // StripByteCounts
            case 325: // TileByteCounts
                if (size > 0)
                    counts = {type, count, field(i, valueAt, offsetSize), inline_, i};
                break;
            default:
                break;
            }
        }
        // The bytes the strips (or tiles) have in the file: each one's count, as far as the file
        // holds it from its offset (a file cut short holds less than its counts say).
        auto valuesOf = [&](const Values& v, std::uint64_t first, std::uint64_t n,
                            std::vector<std::uint64_t>& out) {
            const int size = typeSize(v.type);
            out.assign(static_cast<std::size_t>(n), 0);
            if (size <= 0)
                return;
            if (v.inline_) {
                for (std::uint64_t k = 0; k < n; ++k)
                    out[static_cast<std::size_t>(k)] =
                        field(v.entry, (big ? 12 : 8) + static_cast<int>(first + k) * size,
                              std::min(size, 8));
                return;
            }
            const std::string block = b.get(v.at + first * static_cast<std::uint64_t>(size),
                                            static_cast<std::size_t>(n) * size);
            for (std::uint64_t k = 0; k < n && (k + 1) * size <= block.size(); ++k) {
                std::uint64_t x = 0;
                for (int q = 0; q < size && q < 8; ++q) {
                    const auto byte =
                        static_cast<unsigned char>(block[static_cast<std::size_t>(k) * size + q]);
                    x |= little ? static_cast<std::uint64_t>(byte) << (8 * q)
                                : static_cast<std::uint64_t>(byte) << (8 * (size - 1 - q));
                }
                out[static_cast<std::size_t>(k)] = x;
            }
        };
        std::string cutShort;
        if (counts.count == 0) {
            data = b.size();
        } else {
            const bool withOffsets = offsets.count == counts.count;
            std::vector<std::uint64_t> at, len;
            for (std::uint64_t k = 0; k < counts.count; k += 8192) {
                const std::uint64_t take = std::min<std::uint64_t>(counts.count - k, 8192);
                valuesOf(counts, k, take, len);
                if (withOffsets)
                    valuesOf(offsets, k, take, at);
                for (std::uint64_t j = 0; j < take; ++j) {
                    const std::uint64_t o = withOffsets ? at[static_cast<std::size_t>(j)] : 0;
                    const std::uint64_t c = len[static_cast<std::size_t>(j)];
                    data += o >= b.size() ? 0 : std::min(c, b.size() - o);
                    if (withOffsets && cutShort.empty() && b.whole() && c > 0 &&
                        (o >= b.size() || c > b.size() - o))
                        cutShort = std::string(tw > 0 && th > 0 ? "TIFF tile " : "TIFF strip ") +
                                   std::to_string(k + j + 1) + " of " +
                                   std::to_string(counts.count) + " (bytes " + std::to_string(o) +
                                   " to " + std::to_string(o + c) +
                                   ") runs past the end of the file (" + std::to_string(b.size()) +
                                   " bytes)";
                }
            }
        }
        ifd = num(entriesAt + n * static_cast<std::uint64_t>(entrySize), offsetSize);
        if (w == 0 || h == 0 || spp == 0 || spp > 65535 || bps == 0 || bps > 64)
            continue; // the codec says what is wrong with the page
        const std::uint64_t bits = spp * bps;
        DeclaredPart p;
        p.what = page > 0 ? "page " + std::to_string(page + 1) : "";
        p.width = w;
        p.height = h;
        p.channels = photometric == 3 ? 3 : static_cast<int>(spp);
        if (tw > 0 && th > 0) {
            checkTileSize(path, "TIFF", tw, th);
            p.storedBytes = ceilDiv(w, tw) * ceilDiv(h, th) * th * ceilDiv(tw * bits, 8);
        } else {
            p.storedBytes = h * ceilDiv(w * bits, 8);
        }
        p.dataBytes = data;
        p.corruptBlock = cutShort;
        const auto [ratio, codec] = tiffCodec(compression, w);
        p.maxRatio = ratio;
        p.codec = codec;
        d.parts.push_back(p);
    }
    return d;
}

} // namespace lut::formats
