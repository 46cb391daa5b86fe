// SPDX-License-Identifier: Apache-2.0
// PNG, natively. Reading: the common files (8/16-bit grey, grey + alpha, RGB, RGBA, not
// interlaced, no tRNS) are inflated by ISA-L as their rows are asked for (streamed: reading
// overlaps the rest; as fast as libdeflate's one call over the whole image, twice zlib's speed)
// and unfiltered here (PngUnfilter.h); the others are libpng's, row by row
// (transforms: palette and low-depth grey expanded to 8 bits, tRNS to alpha, 16-bit samples in
// host order; no gamma), and so are the common files the fast path finds anything unusual in. Both
// give the same samples (tests/formats/test_png_read.cpp). Writing is ours, because libpng
// compresses on one core: rows are filtered as libpng's default heuristic does (the filter with the
// smallest sum of absolute values, per row), strips of about a megabyte are deflated in parallel
// (each primed with the previous strip's last 32 KiB, as pigz does, and ended with a sync flush so
// the raw deflate streams concatenate into one zlib stream) and written as IDAT chunks. Metadata:
// every ancillary chunk of a PNG input (iCCP, gAMA, cHRM, sRGB, tEXt/zTXt/iTXt, eXIf, pHYs, tIME
// ...) is copied verbatim to a PNG output, at its place; chunks tied to the palette or to the
// colour type (PLTE, tRNS, hIST, sPLT, and bKGD/sBIT when the colour type or depth changes) and
// unknown unsafe-to-copy chunks are not. From other formats: the ICC profile, EXIF and text. PNG:
// https://www.w3.org/TR/png/ (chunk layout, filters, the zlib stream).
#include "imageio/ByteIO.h"
#include "imageio/ImageCodec.h"

#include "lut/Error.h"

#include "imageio/PngUnfilter.h"

#include <isa-l/crc.h>
#include <isa-l/igzip_lib.h>
#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <future>
#include <vector>

namespace lut::formats {

namespace {

constexpr unsigned char kSignature[8] = {137, 'P', 'N', 'G', 13, 10, 26, 10};

std::uint32_t be32(const unsigned char* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) |
           std::uint32_t(p[3]);
}

bool isType(const char* t, const char* name) {
    return std::memcmp(t, name, 4) == 0;
}

// The first `max` bytes of a zlib stream, inflated (for iCCP).
std::string inflateAll(const unsigned char* data, std::size_t n, std::size_t max) {
    std::string out(std::min<std::size_t>(max, 1 << 16), '\0');
    z_stream z{};
    if (inflateInit(&z) != Z_OK)
        return {};
    z.next_in = const_cast<unsigned char*>(data);
    z.avail_in = static_cast<uInt>(n);
    std::size_t have = 0;
    int rc = Z_OK;
    while (rc == Z_OK) {
        if (have == out.size()) {
            if (out.size() >= max)
                break;
            out.resize(std::min(max, out.size() * 2));
        }
        z.next_out = reinterpret_cast<unsigned char*>(out.data() + have);
        z.avail_out = static_cast<uInt>(out.size() - have);
        rc = inflate(&z, Z_NO_FLUSH);
        have = out.size() - z.avail_out;
    }
    inflateEnd(&z);
    out.resize(rc == Z_STREAM_END ? have : 0);
    return out;
}

struct PngError {
    std::string message;
};

// libpng's error leaves through an exception, not a longjmp: one way out on every platform (the
// browser edition's WebAssembly exceptions do not mix with setjmp). libpng's C frames are unwound
// without cleanups (its structures are destroyed by png_destroy_read_struct), as they are by a
// longjmp.
struct PngAbort {};

[[noreturn]] void onError(png_structp png, png_const_charp msg) {
    auto* e = static_cast<PngError*>(png_get_error_ptr(png));
    if (e && e->message.empty())
        e->message = msg ? msg : "libpng error";
    throw PngAbort{};
}
void onWarning(png_structp, png_const_charp) {} // libpng's warnings are not ours to print

class PngSource : public ImageSource {
public:
    PngSource(const std::string& path, std::string memory) : m_in(path, std::move(memory)) {
        // The destructor does not run for a constructor that throws (a refused size, a libpng
        // error): the reader's structures go here then.
        try {
            open(path);
        } catch (const PngAbort&) {
            png_destroy_read_struct(&m_png, &m_pngInfo, nullptr);
            fail();
        } catch (...) {
            png_destroy_read_struct(&m_png, &m_pngInfo, nullptr);
            throw;
        }
    }
    ~PngSource() override { png_destroy_read_struct(&m_png, &m_pngInfo, nullptr); }

private:
    void open(const std::string& path) {
        scanChunks();
        m_png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &m_error, onError, onWarning);
        m_pngInfo = m_png ? png_create_info_struct(m_png) : nullptr;
        if (!m_pngInfo)
            throw Error(path + ": out of memory starting the PNG reader");
        png_set_read_fn(m_png, this, [](png_structp png, png_bytep dst, png_size_t n) {
            auto* self = static_cast<PngSource*>(png_get_io_ptr(png));
            std::size_t got = 0;
            try {
                got = self->m_in.read(dst, n);
            } catch (const std::exception& e) {
                self->m_error.message = e.what();
                png_error(png, "read error");
            }
            if (got != n)
                png_error(png, "the file ends early (truncated)");
        });
        // Metadata was collected by scanChunks: libpng need not keep any ancillary chunk.
        png_set_keep_unknown_chunks(m_png, PNG_HANDLE_CHUNK_NEVER, nullptr, 0);
        png_read_info(m_png, m_pngInfo);
        png_uint_32 w = 0, h = 0;
        int depth = 0, colour = 0, interlace = 0;
        png_get_IHDR(m_png, m_pngInfo, &w, &h, &depth, &colour, &interlace, nullptr, nullptr);
        if (colour == PNG_COLOR_TYPE_PALETTE)
            png_set_palette_to_rgb(m_png);
        if (colour == PNG_COLOR_TYPE_GRAY && depth < 8)
            png_set_expand_gray_1_2_4_to_8(m_png);
        if (png_get_valid(m_png, m_pngInfo, PNG_INFO_tRNS))
            png_set_tRNS_to_alpha(m_png);
        if (depth == 16)
            png_set_swap(m_png);
        m_passes = png_set_interlace_handling(m_png);
        png_read_update_info(m_png, m_pngInfo);
        const int ch = png_get_channels(m_png, m_pngInfo);
        checkImageSize(path, static_cast<int>(std::min<png_uint_32>(w, 1u << 30)),
                       static_cast<int>(std::min<png_uint_32>(h, 1u << 30)), ch);
        m_info.width = static_cast<int>(w);
        m_info.height = static_cast<int>(h);
        m_info.channels = ch;
        m_info.format = "png";
        m_info.type = depth == 16 ? PixelType::UInt16 : PixelType::UInt8;
        m_info.bitDepth = m_info.bitsPerSample = depth == 16 ? 16 : 8;
        m_info.compression = "zip";
        m_info.channelNames = ch == 1   ? std::vector<std::string>{"Y"}
                              : ch == 2 ? std::vector<std::string>{"Y", "A"}
                              : ch == 3 ? std::vector<std::string>{"R", "G", "B"}
                                        : std::vector<std::string>{"R", "G", "B", "A"};
        m_info.alphaChannel = (ch == 2 || ch == 4) ? ch - 1 : -1;
        m_meta->pngColourType = colour;
        m_meta->pngBitDepth = depth;
        m_metadata = m_meta;
        const bool plainLayout = colour == PNG_COLOR_TYPE_GRAY || colour == PNG_COLOR_TYPE_RGB ||
                                 colour == PNG_COLOR_TYPE_GRAY_ALPHA ||
                                 colour == PNG_COLOR_TYPE_RGB_ALPHA;
        m_whole = plainLayout && (depth == 8 || depth == 16) && interlace == PNG_INTERLACE_NONE &&
                  !png_get_valid(m_png, m_pngInfo, PNG_INFO_tRNS);
    }

    // The fast path, streamed: the IDAT chunks are read one at a time as rows are asked for (each
    // chunk's CRC checked before its bytes are used) and inflated by ISA-L straight into the rows
    // asked for (its stateful inflate keeps the 32 KiB window itself); every filter byte must be
    // known, and after the last row the zlib stream must end there (its Adler-32 checked), with
    // IEND after the data and no critical chunk between. Anything else (a damaged or unusual
    // file) hands the file to libpng from its first IDAT (nothing was consumed: pread), the rows
    // already given read again and dropped, so libpng's messages and its tolerance of benign
    // faults are unchanged. (It was one libdeflate call over the whole image: a 1080p frame's
    // 20-30 ms before the first row, on the reading thread alone.)
    void startStream() {
        m_inflate.reset(new inflate_state); // ~ 90 KiB, set up by isal_inflate_init
        isal_inflate_init(m_inflate.get());
        m_inflate->crc_flag = ISAL_ZLIB; // the zlib header parsed, the Adler-32 verified
        m_chunkAt = 8;
        m_sawData = false;
        m_rowsDone = 0;
        m_prevRow.assign(rowBytes(m_info), 0);
    }

    enum class Feed { Data, End, Bad };
    // The next IDAT's data as the inflater's input (Data); End at IEND; Bad for a damaged chunk,
    // a critical chunk after the data, or a file that ends without IEND.
    Feed nextIdat() {
        unsigned char hdr[8];
        while (m_chunkAt + 8 <= m_in.size() && m_in.pread(hdr, 8, m_chunkAt) == 8) {
            const std::uint32_t len = be32(hdr);
            const char* type = reinterpret_cast<const char*>(hdr + 4);
            if (len > 0x7fffffffu || m_chunkAt + 12 + static_cast<std::uint64_t>(len) > m_in.size())
                return Feed::Bad; // the chunk runs past the end of the file
            if (isType(type, "IEND"))
                return Feed::End;
            if (isType(type, "IDAT")) {
                m_idat.resize(static_cast<std::size_t>(len) + 4);
                if (m_in.pread(m_idat.data(), len + 4, m_chunkAt + 8) != len + 4)
                    return Feed::Bad;
                const std::uint32_t crc = static_cast<std::uint32_t>(
                    crc32_gzip_refl(crc32_gzip_refl(0, hdr + 4, 4), m_idat.data(), len));
                if (crc != be32(m_idat.data() + len))
                    return Feed::Bad;
                m_chunkAt += 12 + static_cast<std::uint64_t>(len);
                m_sawData = true;
                if (len == 0)
                    continue;
                m_inflate->next_in = m_idat.data();
                m_inflate->avail_in = len;
                return Feed::Data;
            }
            if (m_sawData && (type[0] & 0x20) == 0)
                return Feed::Bad; // a critical chunk after the data
            m_chunkAt += 12 + static_cast<std::uint64_t>(len);
        }
        return Feed::Bad;
    }

    // Exactly n inflated bytes into out; false if the stream is damaged or ends first.
    bool inflateTo(unsigned char* out, std::size_t n) {
        inflate_state* s = m_inflate.get();
        s->next_out = out;
        s->avail_out = static_cast<std::uint32_t>(n);
        while (s->avail_out > 0) {
            const std::uint32_t outBefore = s->avail_out, inBefore = s->avail_in;
            if (isal_inflate(s) != ISAL_DECOMP_OK)
                return false;
            if (s->avail_out == 0)
                break;
            if (s->block_state == ISAL_BLOCK_FINISH)
                return false; // the stream ended before the rows did
            if (s->avail_out != outBefore || s->avail_in != inBefore)
                continue;
            if (s->avail_in > 0 || nextIdat() != Feed::Data)
                return false; // stuck, or the data ends before the rows do
        }
        return true;
    }

    // After the last row: the stream ends (Adler-32 checked by the inflater), nothing follows it
    // in the data, and IEND comes with no critical chunk before it.
    bool endOfStream() {
        inflate_state* s = m_inflate.get();
        unsigned char extra = 0;
        while (s->block_state != ISAL_BLOCK_FINISH) {
            s->next_out = &extra;
            s->avail_out = 1;
            const std::uint32_t inBefore = s->avail_in;
            if (isal_inflate(s) != ISAL_DECOMP_OK || s->avail_out == 0)
                return false; // damaged, or more data than the rows
            if (s->block_state == ISAL_BLOCK_FINISH)
                break;
            if (s->avail_in == inBefore && (s->avail_in > 0 || nextIdat() != Feed::Data))
                return false;
        }
        if (s->avail_in != 0)
            return false; // bytes after the zlib stream
        for (;;) {
            const Feed f = nextIdat();
            if (f != Feed::Data)
                return f == Feed::End;
            if (m_inflate->avail_in > 0)
                return false; // more data after the stream's end
        }
    }

    // Rows [y0, y1) by the fast path into out; false if anything is not as expected.
    bool streamRows(int y0, int y1, unsigned char* out) {
        if (y0 != m_rowsDone)
            return false;
        const std::size_t rb = rowBytes(m_info);
        const std::size_t bpp =
            static_cast<std::size_t>(m_info.channels * bytesPerSample(m_info.type));
        const std::size_t rows = static_cast<std::size_t>(y1 - y0);
        m_filtered.resize((rb + 1) * rows);
        if (!inflateTo(m_filtered.data(), m_filtered.size()))
            return false;
        for (std::size_t r = 0; r < rows; ++r)
            if (m_filtered[(rb + 1) * r] > 4)
                return false; // an unknown filter
        const bool wide = m_info.type == PixelType::UInt16;
        if (wide)
            m_row.resize(rb);
        for (std::size_t r = 0; r < rows; ++r) {
            const unsigned char* f = m_filtered.data() + (rb + 1) * r;
            unsigned char* o = wide ? m_row.data() : out + rb * r;
            unfilterRow(f[0], f + 1, m_prevRow.data(), o, rb, bpp);
            std::memcpy(m_prevRow.data(), o, rb);
            if (wide) { // big-endian samples to host order, as png_set_swap does
                unsigned char* w = out + rb * r;
                for (std::size_t i = 0; i < rb; i += 2) {
                    w[i] = o[i + 1];
                    w[i + 1] = o[i];
                }
            }
        }
        if (y1 == m_info.height && !endOfStream())
            return false;
        m_rowsDone = y1;
        if (y1 == m_info.height)
            releaseStream();
        return true;
    }

    void releaseStream() {
        m_inflate.reset();
        UninitBytes().swap(m_idat);
        UninitBytes().swap(m_filtered);
    }

    // The fast path gives up at row `rows`: libpng reads the file from its first IDAT, and the
    // rows already given are read again and dropped (libpng says what is wrong, or reads on).
    void handToLibpng(int rows) {
        m_whole = false;
        releaseStream();
        if (rows <= 0)
            return;
        m_skip.resize(rowBytes(m_info));
        m_skipped = 0;
        try {
            for (; m_skipped < rows; ++m_skipped)
                png_read_row(m_png, m_skip.data(), nullptr);
        } catch (const PngAbort&) {
            fail();
        }
    }

public:
    void readRows(int y0, int y1, void* dst) override {
        if (y0 == 0) // before decoding: more pixels than the deflated data can hold is refused
            checkImageSize(m_in.path(), m_info.width, m_info.height, m_info.channels, m_in.size(),
                           1032.0);
        const std::size_t rb = rowBytes(m_info);
        if (m_whole && y0 == 0 && !m_inflate)
            startStream();
        if (m_whole) {
            if (streamRows(y0, y1, static_cast<unsigned char*>(dst)))
                return;
            handToLibpng(y0);
        }
        readRowsAt(y0, y1, static_cast<png_bytep>(dst), rb);
    }

    void readRowsAt(int y0, int y1, png_bytep out, std::size_t rb) {
        if (m_passes > 1) { // interlaced: the whole image once, then rows from it
            if (m_frame.empty()) {
                m_frame.resize(rb * static_cast<std::size_t>(m_info.height));
                std::vector<png_bytep> rows(static_cast<std::size_t>(m_info.height));
                for (int y = 0; y < m_info.height; ++y)
                    rows[static_cast<std::size_t>(y)] =
                        m_frame.data() + rb * static_cast<std::size_t>(y);
                try {
                    png_read_image(m_png, rows.data());
                } catch (const PngAbort&) {
                    fail();
                }
            }
            std::memcpy(out, m_frame.data() + rb * static_cast<std::size_t>(y0),
                        rb * static_cast<std::size_t>(y1 - y0));
            return;
        }
        m_next = out;
        m_rowBytes = rb;
        try {
            for (int y = y0; y < y1; ++y, m_next += m_rowBytes)
                png_read_row(m_png, m_next, nullptr);
        } catch (const PngAbort&) {
            fail();
        }
    }

    void finish() override {
        if (m_whole) // the data and IEND were checked by endOfStream
            return;
        try {
            png_read_end(m_png, nullptr); // through IEND: a truncated file is an error here
        } catch (const PngAbort&) {
            fail();
        }
    }

private:
    [[noreturn]] void fail() {
        std::string msg = m_error.message.empty() ? "corrupt PNG" : m_error.message;
        if (msg.rfind(m_in.path() + ":", 0) == 0)
            throw Error(msg);
        throw Error(m_in.path() + ": cannot read PNG: " + msg);
    }

    // The ancillary chunks, by walking the chunk headers (IDAT data is skipped, not read).
    void scanChunks() {
        const std::string sig = m_in.head(8);
        if (sig.size() < 8 || std::memcmp(sig.data(), kSignature, 8) != 0)
            throw Error(m_in.path() + ": not a PNG file");
        m_meta = std::make_shared<ImageMetadata>();
        m_meta->format = "png";
        std::uint64_t at = 8;
        int place = 0;
        unsigned char hdr[8];
        while (at + 8 <= m_in.size() && m_in.pread(hdr, 8, at) == 8) {
            const std::uint32_t len = be32(hdr);
            const char* type = reinterpret_cast<const char*>(hdr + 4);
            if (isType(type, "IEND") || len > (1u << 30))
                break;
            if (isType(type, "PLTE"))
                place = std::max(place, 1);
            else if (isType(type, "IDAT"))
                place = 2;
            const bool critical = (type[0] & 0x20) == 0;
            const bool skip =
                critical || isType(type, "tRNS") || isType(type, "hIST") || isType(type, "sPLT");
            if (!skip && len <= (16u << 20) && at + 12 + len <= m_in.size()) {
                ImageMetadata::PngChunk c;
                std::memcpy(c.type, type, 4);
                c.data.resize(len);
                m_in.pread(c.data.data(), len, at + 8);
                c.place = place == 2 ? 2 : place;
                collectCommon(c);
                m_meta->pngChunks.push_back(std::move(c));
            }
            at += 12 + static_cast<std::uint64_t>(len);
        }
    }

    void collectCommon(const ImageMetadata::PngChunk& c) {
        const std::string& d = c.data;
        if (isType(c.type, "iCCP")) {
            const std::size_t nul = d.find('\0');
            if (nul != std::string::npos && nul + 2 <= d.size())
                m_meta->icc = inflateAll(reinterpret_cast<const unsigned char*>(d.data()) + nul + 2,
                                         d.size() - nul - 2, 16u << 20);
        } else if (isType(c.type, "sRGB")) {
            m_info.colorSpace = "sRGB";
            m_meta->srgb = true;
        } else if (isType(c.type, "gAMA") && d.size() == 4 && m_info.colorSpace.empty()) {
            const unsigned char* g = reinterpret_cast<const unsigned char*>(d.data());
            const std::uint32_t gamma = (std::uint32_t(g[0]) << 24) | (std::uint32_t(g[1]) << 16) |
                                        (std::uint32_t(g[2]) << 8) | g[3];
            if (gamma == 100000) // stored values are linear light
                m_info.colorSpace = "Linear";
        } else if (isType(c.type, "eXIf")) {
            m_meta->exif = d;
        } else if (isType(c.type, "tEXt")) {
            const std::size_t nul = d.find('\0');
            if (nul != std::string::npos) {
                // PNG's "Description" is what TIFF and OpenImageIO call ImageDescription.
                std::string key = d.substr(0, nul);
                if (key == "Description")
                    key = "ImageDescription";
                m_meta->text.emplace_back(std::move(key), d.substr(nul + 1));
            }
        }
    }

    ByteReader m_in;
    png_structp m_png = nullptr;
    png_infop m_pngInfo = nullptr;
    PngError m_error;
    int m_passes = 1;
    bool m_whole = false;                     // the fast path (streamRows)
    std::unique_ptr<inflate_state> m_inflate; // ISA-L's inflater, once rows are asked for
    UninitBytes m_idat;                       // the IDAT chunk being inflated (and its CRC)
    std::uint64_t m_chunkAt = 8;              // the next chunk's header
    bool m_sawData = false;
    int m_rowsDone = 0;                   // rows given by the fast path
    UninitBytes m_filtered;               // the rows being unfiltered, with filter bytes
    std::vector<unsigned char> m_skip;    // a row libpng reads again and drops
    int m_skipped = 0;                    // how many of the rows given again were dropped
    std::vector<unsigned char> m_prevRow; // the last row unfiltered (the next one's "up")
    std::vector<unsigned char> m_row;     // a 16-bit row before its bytes are swapped
    png_bytep m_next = nullptr;           // where the next row goes
    std::size_t m_rowBytes = 0;
    std::vector<unsigned char> m_frame;
    std::shared_ptr<ImageMetadata> m_meta;
};

} // namespace

std::unique_ptr<ImageSource> openPngSource(const std::string& path, std::string memory) {
    return std::make_unique<PngSource>(path, std::move(memory));
}

} // namespace lut::formats
