// SPDX-License-Identifier: Apache-2.0
// Windows BMP, natively (read only; OpenImageIO writes BMP): "BM" files with an info header of 12
// (OS/2 1.x), 40 (Windows 3), 52, 56, 108 (V4) or 124 bytes (V5); 1-, 4- and 8-bit colour maps,
// RLE8 and RLE4, 16-bit (5-5-5, or the BITFIELDS masks: 5-6-5), 24- and 32-bit, bottom-up or
// top-down (a negative height). Layout: Microsoft's "Bitmap Storage" (BITMAPINFOHEADER,
// BITMAPV5HEADER, "Bitmap Compression"). Samples, channels, their names, ImageInfo and the
// attributes handed to OpenImageIO's writers are OpenImageIO 2.4's (bmpinput.cpp, what lutkit
// read BMP with before), checked against it in tests/formats/test_bmp_tga_read.cpp:
//   - 8-bit RGB always (32-bit: R, G, B, A); an 8-bit file whose colour map is all grey is one
//     channel "Y" (1- and 4-bit grey maps stay RGB); 16-bit files are RGB at the masks' bits
//     (bitsPerSample: the red mask's) widened by repeating them, their alpha mask ignored;
//   - a colour-map index past the map's end takes its last entry; an RLE delta's skipped pixels
//     and rows take entry 0; RLE pixels past a row's end are dropped; a top-down RLE file (which
//     the format forbids) is read bottom-up;
//   - compression "rle8"/"rle4" (else none said), bmp:version, bmp:bitsperpixel (16 bits and
//     less), the resolution in pixels per metre.
// Where OpenImageIO 2.4 reads a file oddly, lutkit reads what the file means:
//   - an RLE stream whose last row ends with an end-of-line before its end-of-bitmap marker
//     (what ImageMagick writes) is read; OpenImageIO refused it ("out-of-bounds pixel");
//   - RLE8 with an all-grey colour map is one grey channel, as the uncompressed file; OpenImageIO
//     said one channel and wrote three bytes a pixel (the first third of each row, and past it);
//   - 32-bit BITFIELDS masks are applied (OpenImageIO assumed B, G, R, A bytes: the same for the
//     usual masks);
//   - a 32-bit file that declares no alpha (no alpha mask: BI_RGB's "unused" byte) and whose
//     fourth bytes are all 0 (a GDI X8R8G8B8 capture) is opaque (alpha 255); OpenImageIO gave
//     alpha 0, a picture that vanishes;
//   - refused, one line naming the field, where OpenImageIO read garbage: other compressions
//     (JPEG, PNG, CMYK ...), RLE8 without 8 bits per pixel or RLE4 without 4, info header sizes
//     it does not know (OS/2 2.x: it read uninitialised fields).
// Where OpenImageIO refuses a file (a colour count over what the bits index, a short colour map,
// RLE commands past the last row, a stream or rows that end early), so does this reader, at open.
// Memory: uncompressed rows are read where they lie (a bottom-up file from its end) in blocks of
// at most 1 MiB; an RLE stream is walked once at open (checked whole) noting where every row (or
// every 256 pixels' worth of rows) starts, and rows are decoded from there when asked: at most 24
// bytes per row besides one row of indices, where OpenImageIO held the whole image.
#include "imageio/ByteIO.h"
#include "imageio/ImageCodec.h"
#include "imageio/OiioAttributes.h"
#include "imageio/RowWindowSource.h"

#include "lut/Error.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cstring>
#include <vector>

namespace lut::formats {

namespace {

constexpr int kRle8 = 1, kRle4 = 2, kBitfields = 3;

std::uint32_t le32(const unsigned char* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
           std::uint32_t(p[3]) << 24;
}
std::uint32_t le16(const unsigned char* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8;
}

// One channel of a 16- or 32-bit pixel: OpenImageIO's calc_shifts (the mask's lowest set bit and
// the run of set bits from there) and bit_range_convert to 8 bits (the bits repeated to fill 8,
// or the top 8 of more).
struct MaskField {
    std::uint32_t mask = 0, shift = 0;
    int bits = 0;
    MaskField() = default;
    explicit MaskField(std::uint32_t m) : mask(m) {
        for (; m != 0 && !(m & 1u); m >>= 1)
            ++shift;
        for (; m & 1u; m >>= 1)
            ++bits;
    }
    unsigned char operator()(std::uint32_t pixel) const {
        if (bits == 0)
            return 0;
        const std::uint32_t v = (pixel & mask) >> shift;
        std::uint32_t out = 0;
        int s = 8 - bits;
        for (; s > 0; s -= bits)
            out |= v << s;
        out |= v >> -s;
        return static_cast<unsigned char>(out);
    }
};

class BmpSource : public RowWindowSource {
public:
    BmpSource(const std::string& path, std::string memory)
        : RowWindowSource(path, std::move(memory), "BMP") {
        readHeader();
    }

private:
    void readPackedRows(std::int64_t a, std::int64_t b, const RowPlace& place) override {
        decodeRle(a, b,
                  [&](std::int64_t r, const unsigned char* idx) { paletteRow(idx, place(r)); });
    }

    void readHeader() {
        const std::string head = m_in.head(14 + 124 + 16);
        const auto* p = reinterpret_cast<const unsigned char*>(head.data());
        if (head.size() < 18 || p[0] != 'B' || p[1] != 'M')
            fail("not a BMP file (no \"BM\" signature and header)");
        m_dataStart = le32(p + 10);
        const std::uint32_t infoSize = le32(p + 14);
        if (infoSize != 12 && infoSize != 40 && infoSize != 52 && infoSize != 56 &&
            infoSize != 108 && infoSize != 124)
            fail("BMP info header of " + std::to_string(infoSize) +
                 " bytes (at byte 14) is not one lutkit reads (12, 40, 52, 56, 108 or 124: " +
                 "Windows and OS/2 1.x bitmaps)");
        if (head.size() < 14 + infoSize)
            fail("BMP info header is cut short (" + std::to_string(head.size()) +
                 " bytes, it needs " + std::to_string(14 + infoSize) + ")");
        std::int64_t w = 0, h = 0;
        std::int32_t colours = 0, hres = 0, vres = 0;
        std::uint32_t masks[4] = {0, 0, 0, 0};
        if (infoSize == 12) { // OS/2 1.x: 16-bit unsigned sizes, no compression, 3-byte entries
            w = le16(p + 18);
            h = le16(p + 20);
            m_bpp = static_cast<int>(le16(p + 24));
        } else {
            w = static_cast<std::int32_t>(le32(p + 18));
            h = static_cast<std::int32_t>(le32(p + 22));
            m_bpp = static_cast<int>(le16(p + 28));
            m_compression = static_cast<std::int32_t>(le32(p + 30));
            hres = static_cast<std::int32_t>(le32(p + 38));
            vres = static_cast<std::int32_t>(le32(p + 42));
            colours = static_cast<std::int32_t>(le32(p + 46));
            // Windows 3's BITFIELDS masks follow its header; later headers hold them.
            const bool v3Masks =
                infoSize == 40 && m_compression == kBitfields && (m_bpp == 16 || m_bpp == 32);
            if (v3Masks && head.size() < 14 + 40 + 12)
                fail("BMP colour masks are cut short (truncated)");
            const int nMasks = v3Masks || infoSize == 52 ? 3 : infoSize >= 56 ? 4 : 0;
            for (int i = 0; i < nMasks; ++i)
                masks[i] = le32(p + 54 + 4 * i);
        }
        if (m_bpp != 1 && m_bpp != 4 && m_bpp != 8 && m_bpp != 16 && m_bpp != 24 && m_bpp != 32)
            fail("BMP of " + std::to_string(m_bpp) +
                 " bits per pixel (header byte 28) is not read (1, 4, 8, 16, 24 or 32)");
        if (m_compression != 0 && m_compression != kRle8 && m_compression != kRle4 &&
            m_compression != kBitfields)
            fail("BMP compression " + std::to_string(m_compression) +
                 " (header byte 30) is not read (0 none, 1 RLE8, 2 RLE4, 3 BITFIELDS)");
        if ((m_compression == kRle8 && m_bpp != 8) || (m_compression == kRle4 && m_bpp != 4))
            fail(std::string("BMP compression ") + (m_compression == kRle8 ? "RLE8" : "RLE4") +
                 " needs " + (m_compression == kRle8 ? "8" : "4") + " bits per pixel, not " +
                 std::to_string(m_bpp));
        m_packed = m_compression == kRle8 || m_compression == kRle4;
        m_topDown = h < 0 && !m_packed; // a top-down RLE file is read bottom-up
        h = h < 0 ? -h : h;
        if (m_bpp <= 8)
            readColourMap(14 + infoSize, colours, infoSize == 12 ? 3 : 4);
        const int channels = m_bpp == 32 ? 4 : m_grey ? 1 : 3;
        checkImageSize(m_in.path(), static_cast<int>(w),
                       static_cast<int>(std::min<std::int64_t>(h, INT_MAX)), channels);
        m_info.width = static_cast<int>(w);
        m_info.height = static_cast<int>(h);
        m_info.channels = channels;
        m_info.format = "bmp";
        m_info.type = PixelType::UInt8;
        m_info.bitDepth = 8;
        m_info.bitsPerSample = 8;
        m_info.channelNames = channels == 1   ? std::vector<std::string>{"Y"}
                              : channels == 3 ? std::vector<std::string>{"R", "G", "B"}
                                              : std::vector<std::string>{"R", "G", "B", "A"};
        m_info.alphaChannel = channels == 4 ? 3 : -1;
        m_info.compression = m_compression == kRle8 ? "rle8" : m_compression == kRle4 ? "rle4" : "";
        if (m_bpp == 16) {
            // The masks where the header has them (OpenImageIO's rule: BITFIELDS in a Windows 3
            // header, always in later ones), 5-5-5 unless all three are set.
            if (masks[0] == 0 || masks[1] == 0 || masks[2] == 0) {
                masks[0] = 0x7c00;
                masks[1] = 0x03e0;
                masks[2] = 0x001f;
            }
            m_bitsPerSample16 = MaskField(masks[0]).bits;
            m_info.bitsPerSample = m_bitsPerSample16;
        }
        if (m_bpp == 16 || m_bpp == 32) {
            const bool useMasks = m_bpp == 16 || (m_compression == kBitfields && masks[0] != 0 &&
                                                  masks[1] != 0 && masks[2] != 0);
            m_r = MaskField(useMasks ? masks[0] : 0x00ff0000u);
            m_g = MaskField(useMasks ? masks[1] : 0x0000ff00u);
            m_b = MaskField(useMasks ? masks[2] : 0x000000ffu);
            m_a = MaskField(useMasks && masks[3] != 0 ? masks[3] : 0xff000000u);
        }
        m_stride = static_cast<std::size_t>(
            (static_cast<std::uint64_t>(m_info.width) * static_cast<std::uint64_t>(m_bpp) + 31) /
            32 * 4);
        if (m_packed) {
            indexRle();
        } else {
            const std::uint64_t need = m_dataStart + m_stride * static_cast<std::uint64_t>(h);
            if (m_in.size() < need)
                fail("BMP pixel data ends early: " + std::to_string(w) + "x" + std::to_string(h) +
                     " pixels at " + std::to_string(m_bpp) + " bits need " +
                     std::to_string(need - m_dataStart) + " bytes from byte " +
                     std::to_string(m_dataStart) + ", the file has " + std::to_string(m_in.size()) +
                     " (truncated)");
            // BI_RGB's fourth byte is "unused": all 0 there is no alpha, not a transparent image.
            m_opaque = m_bpp == 32 && masks[3] == 0 && !anyAlpha();
        }
        m_info.decoderBytes = m_marks.capacity() * sizeof(Mark) + (std::size_t(1) << 16) +
                              std::max<std::size_t>(m_stride, std::size_t(1) << 20);

        OiioAttributes a;
        if (hres > 0 && vres > 0) {
            a.addInt("XResolution", hres);
            a.addInt("YResolution", vres);
            a.addString("ResolutionUnit", "m");
        }
        if (m_bpp == 16)
            a.addUInt("oiio:BitsPerSample", static_cast<unsigned>(m_bitsPerSample16));
        if (m_bpp <= 16)
            a.addInt("bmp:bitsperpixel", m_bpp);
        const int version = infoSize == 12    ? 1
                            : infoSize == 40  ? 3
                            : infoSize == 108 ? 4
                            : infoSize == 124 ? 5
                                              : 0;
        if (version > 0)
            a.addInt("bmp:version", version);
        if (m_packed)
            a.addString("compression", m_info.compression);
        auto meta = std::make_shared<ImageMetadata>();
        meta->format = "bmp";
        meta->oiioAttributes = a.bytes();
        m_metadata = meta;
    }

    // The colour map after the info header: `colours` entries (0: as many as the bits index),
    // B, G, R (and an unused byte but in OS/2 1.x files).
    void readColourMap(std::uint64_t at, std::int32_t colours, int entryBytes) {
        if (colours < 0 || colours > (1 << m_bpp))
            fail("BMP colour count " + std::to_string(colours) + " (header byte 46) is more than " +
                 std::to_string(m_bpp) + "-bit pixels index (at most " +
                 std::to_string(1 << m_bpp) + ")");
        const int n = colours > 0 ? colours : 1 << m_bpp;
        std::vector<unsigned char> raw(static_cast<std::size_t>(n) * entryBytes);
        if (m_in.pread(raw.data(), raw.size(), at) != raw.size())
            fail("BMP colour map of " + std::to_string(n) + " entries at byte " +
                 std::to_string(at) + " runs past the end of the file (truncated)");
        m_palette.resize(static_cast<std::size_t>(n));
        m_grey = m_bpp == 8;
        for (int i = 0; i < n; ++i) {
            const unsigned char* e = raw.data() + static_cast<std::size_t>(i) * entryBytes;
            m_palette[static_cast<std::size_t>(i)] = {e[2], e[1], e[0]};
            m_grey = m_grey && e[0] == e[1] && e[1] == e[2];
        }
    }

    // Whether any 32-bit pixel's fourth byte is set (read until one is).
    bool anyAlpha() const {
        const std::uint64_t total = m_stride * static_cast<std::uint64_t>(m_info.height);
        std::vector<unsigned char> buf(std::size_t(1) << 20);
        for (std::uint64_t at = 0; at < total;) {
            const std::size_t n =
                static_cast<std::size_t>(std::min<std::uint64_t>(buf.size(), total - at));
            if (m_in.pread(buf.data(), n, m_dataStart + at) != n)
                fail("BMP pixel data ends early (truncated)");
            for (std::size_t i = 3; i < n; i += 4)
                if (buf[i] != 0)
                    return true;
            at += n;
        }
        return false;
    }

    void paletteRow(const unsigned char* idx, unsigned char* out) const {
        const std::size_t last = m_palette.size() - 1;
        const int w = m_info.width;
        if (m_grey) {
            for (int x = 0; x < w; ++x)
                out[x] = m_palette[std::min<std::size_t>(idx[x], last)][0];
            return;
        }
        for (int x = 0; x < w; ++x, out += 3)
            std::memcpy(out, m_palette[std::min<std::size_t>(idx[x], last)].data(), 3);
    }

    void convertRow(const unsigned char* s, unsigned char* out, std::int64_t) override {
        const int w = m_info.width;
        switch (m_bpp) {
        case 24:
            for (int x = 0; x < w; ++x, s += 3, out += 3) {
                out[0] = s[2];
                out[1] = s[1];
                out[2] = s[0];
            }
            return;
        case 32:
            for (int x = 0; x < w; ++x, s += 4, out += 4) {
                const std::uint32_t v = le32(s);
                out[0] = m_r(v);
                out[1] = m_g(v);
                out[2] = m_b(v);
                out[3] = m_opaque ? 255 : m_a(v);
            }
            return;
        case 16:
            for (int x = 0; x < w; ++x, s += 2, out += 3) {
                const std::uint32_t v = le16(s);
                out[0] = m_r(v);
                out[1] = m_g(v);
                out[2] = m_b(v);
            }
            return;
        default: { // colour-mapped: the indices, high bits first, then their colours
            m_indices.resize(static_cast<std::size_t>(w));
            const int perByte = 8 / m_bpp, mask = (1 << m_bpp) - 1;
            for (int x = 0; x < w; ++x) {
                const int shift = 8 - m_bpp * (x % perByte + 1);
                m_indices[static_cast<std::size_t>(x)] =
                    static_cast<unsigned char>((s[x / perByte] >> shift) & mask);
            }
            paletteRow(m_indices.data(), out);
        }
        }
    }

    // RLE8/RLE4 (Microsoft's "Bitmap Compression"): pairs (n, v): a run of n pixels of v (RLE4: its
    // two nibbles in turn); (0, 0) end of line, (0, 1) end of bitmap, (0, 2) a delta (dx, dy), (0,
    // n > 2) n indices as they are, padded to a 16-bit boundary. Rows bottom-up.
    struct Mark {
        std::uint64_t offset; // the next command
        std::int64_t x, y;    // where it draws
    };

    // Walks the whole stream once: every command read and checked, and a mark where each
    // m_markEvery-th row's commands start (the first position at or past it).
    void indexRle() {
        const std::int64_t h = m_info.height;
        m_markEvery = std::max(1, 256 / m_info.width);
        m_marks.reserve(static_cast<std::size_t>(h / m_markEvery + 1));
        m_window.seek(m_dataStart);
        std::int64_t x = 0, y = 0;
        auto markUpTo = [&](std::int64_t row) {
            while (static_cast<std::int64_t>(m_marks.size()) * m_markEvery <= row &&
                   static_cast<std::int64_t>(m_marks.size()) * m_markEvery < h)
                m_marks.push_back({m_window.tell(), x, y});
        };
        for (;;) {
            markUpTo(y);
            const std::uint64_t at = m_window.tell();
            const Command c = next(y);
            if (c.kind == Command::End) {
                m_window.seek(at); // the rows after it decode from the end marker: index 0
                markUpTo(h - 1);
                break;
            }
            if (y >= h)
                fail("BMP RLE data runs past the last row (a command at byte " +
                     std::to_string(at) + " draws row " + std::to_string(y + 1) + " of " +
                     std::to_string(h) + ")");
            if (c.kind == Command::Line) {
                x = 0;
                ++y;
            } else if (c.kind == Command::Delta) {
                x += c.dx;
                y += c.dy;
            } else {
                x += c.n;
            }
        }
    }

    struct Command {
        enum Kind { Run, Literal, Line, End, Delta } kind;
        int n = 0;                           // pixels (Run, Literal)
        int value = 0;                       // Run: the byte
        const unsigned char* data = nullptr; // Literal: its bytes
        int dx = 0, dy = 0;
    };

    // The next command from the window; row y is for the message when the stream ends.
    Command next(std::int64_t y) {
        const unsigned char* p = m_window.take(2);
        if (!p)
            fail("BMP RLE data ends at row " + std::to_string(y + 1) + " of " +
                 std::to_string(m_info.height) + " before its end-of-bitmap marker (truncated)");
        Command c{Command::Run};
        if (p[0] != 0) {
            c.n = p[0];
            c.value = p[1];
            return c;
        }
        if (p[1] == 0) {
            c.kind = Command::Line;
        } else if (p[1] == 1) {
            c.kind = Command::End;
        } else if (p[1] == 2) {
            const unsigned char* d = m_window.take(2);
            if (!d)
                fail("BMP RLE delta is cut short (truncated)");
            c.kind = Command::Delta;
            c.dx = d[0];
            c.dy = d[1];
        } else {
            c.kind = Command::Literal;
            c.n = p[1];
            const int bytes = m_compression == kRle4 ? ((c.n + 1) / 2 + 1) & ~1 : (c.n + 1) & ~1;
            c.data = m_window.take(static_cast<std::size_t>(bytes));
            if (!c.data)
                fail("BMP RLE data ends inside a run of " + std::to_string(c.n) +
                     " pixels (truncated)");
        }
        return c;
    }

    // Decodes file rows [a, b) (bottom-up numbering), handing each to emit(row, indices).
    template <class Emit> void decodeRle(std::int64_t a, std::int64_t b, Emit&& emit) {
        const int w = m_info.width;
        const Mark& m = m_marks[static_cast<std::size_t>(a / m_markEvery)];
        m_window.seek(m.offset);
        std::int64_t x = m.x, y = m.y, pending = a;
        m_indices.assign(static_cast<std::size_t>(w), 0);
        m_zeros.assign(static_cast<std::size_t>(w), 0);
        // Rows before `row` are complete: hands out those of [a, b) not yet given.
        auto emitUntil = [&](std::int64_t row) {
            for (const std::int64_t end = std::min(row, b); pending < end; ++pending)
                emit(pending, pending == y ? m_indices.data() : m_zeros.data());
        };
        auto put = [&](int v) {
            if (x >= 0 && x < w)
                m_indices[static_cast<std::size_t>(x)] = static_cast<unsigned char>(v);
            ++x;
        };
        emitUntil(y);
        const bool four = m_compression == kRle4;
        while (y < b) {
            const Command c = next(y);
            switch (c.kind) {
            case Command::End:
                emitUntil(b);
                return;
            case Command::Line:
            case Command::Delta: {
                const std::int64_t to = c.kind == Command::Line ? y + 1 : y + c.dy;
                if (to != y) {
                    emitUntil(y + 1);
                    std::fill(m_indices.begin(), m_indices.end(), 0);
                    y = to;
                    emitUntil(y);
                }
                x = c.kind == Command::Line ? 0 : x + c.dx;
                break;
            }
            case Command::Run:
                if (x >= w) { // past the row's end: nothing drawn
                    x += c.n;
                    break;
                }
                for (int i = 0; i < c.n; ++i)
                    put(four ? (i & 1 ? c.value & 15 : c.value >> 4) : c.value);
                break;
            case Command::Literal:
                for (int i = 0; i < c.n; ++i)
                    put(four ? (i & 1 ? c.data[i / 2] & 15 : c.data[i / 2] >> 4) : c.data[i]);
                break;
            }
        }
    }

    int m_bpp = 0;
    int m_compression = 0;
    bool m_grey = false;
    bool m_opaque = false;
    int m_bitsPerSample16 = 5;
    std::vector<std::array<unsigned char, 3>> m_palette; // R, G, B
    MaskField m_r, m_g, m_b, m_a;
    std::vector<Mark> m_marks;
    int m_markEvery = 1;
    std::vector<unsigned char> m_indices, m_zeros;
};

} // namespace

std::unique_ptr<ImageSource> openBmpSource(const std::string& path, std::string memory) {
    return std::make_unique<BmpSource>(path, std::move(memory));
}

} // namespace lut::formats
