// SPDX-License-Identifier: Apache-2.0
// The PNG writer (PngCodec.cpp's summary says why it is ours): filtered rows, deflated in strips
// on several threads into one zlib stream, chunks written through lut::OutputFile with checked
// writes, the finished file read back (header and end) before it replaces the output. Levels 1-3
// (a preview's and apply's defaults) deflate with ISA-L's igzip (its portable C, the same bytes on
// every platform: Igzip.h), levels 0 and 4-9 with zlib.
#include "imageio/Igzip.h" // first: it names the igzip lutkit compiles

#include "imageio/ByteIO.h"
#include "imageio/ImageCodec.h"

#include "lut/Error.h"
#include "lut/Parallel.h"

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <future>
#include <memory>
#include <vector>

namespace lut::formats {

namespace {

constexpr unsigned char kSignature[8] = {137, 'P', 'N', 'G', 13, 10, 26, 10};
constexpr std::size_t kStripBytes = std::size_t(1) << 20; // deflated as one job
constexpr std::size_t kWindow = 32768;
constexpr int kDefaultLevel = 3;
// lutkit_isal_level_state_bytes(1) and (2) on x86-64 (third_party/isal/lutkit_isal_level.c).
constexpr std::size_t kIsalLevel1State64 = 21096;
constexpr std::size_t kIsalLevel2State64 = 70248;

void putBe32(unsigned char* p, std::uint32_t v) {
    p[0] = static_cast<unsigned char>(v >> 24);
    p[1] = static_cast<unsigned char>(v >> 16);
    p[2] = static_cast<unsigned char>(v >> 8);
    p[3] = static_cast<unsigned char>(v);
}

// A strip's deflate bytes. The buffer is sized for the worst case and not zero-filled
// (UninitBytes): the compressor writes only its first part (a 1 MiB strip's bound was 1 MiB of
// fresh pages cleared for nothing, each strip on a new thread).
struct Strip {
    UninitBytes deflated;
    std::uint32_t adler = 1;
    std::size_t rawBytes = 0;
};

// One strip as raw deflate data, primed with `dict`, ended with a sync flush (or the final block),
// by zlib (levels 0 and 4-9: the same bytes as before ISA-L was used).
Strip deflateStripZlib(const std::vector<unsigned char>& data,
                       const std::vector<unsigned char>& dict, bool last, int level) {
    Strip s;
    s.rawBytes = data.size();
    s.adler = static_cast<std::uint32_t>(adler32(1L, data.data(), static_cast<uInt>(data.size())));
    z_stream z{};
    // Level 1 and below: run-length matches only (Z_RLE), zlib's fastest search; on filtered
    // image rows it also compresses better than level 1's hashed search (a 1080p screenshot:
    // 3.27 MB against 3.77 MB, 17% less CPU for the whole preview).
    const int strategy = level <= 1 ? Z_RLE : Z_FILTERED;
    if (deflateInit2(&z, level, Z_DEFLATED, -15, 8, strategy) != Z_OK)
        throw Error("cannot start the PNG compressor");
    if (!dict.empty())
        deflateSetDictionary(&z, dict.data(), static_cast<uInt>(dict.size()));
    s.deflated.resize(deflateBound(&z, static_cast<uLong>(data.size())) + 64);
    z.next_in = const_cast<unsigned char*>(data.data());
    z.avail_in = static_cast<uInt>(data.size());
    z.next_out = s.deflated.data();
    z.avail_out = static_cast<uInt>(s.deflated.size());
    const int rc = deflate(&z, last ? Z_FINISH : Z_SYNC_FLUSH);
    const bool ok = last ? rc == Z_STREAM_END : rc == Z_OK;
    s.deflated.resize(s.deflated.size() - z.avail_out);
    deflateEnd(&z);
    if (!ok || z.avail_in != 0)
        throw Error("the PNG compressor failed");
    return s;
}

// The same with ISA-L's igzip (levels 1-3). Measured on 1 MiB strips of filtered 1080p rows (a
// noisy screenshot-like frame, a photo, a smooth gradient), one thread: igzip level 1 against zlib
// level 1 (Z_RLE) 2.1x / 5.1x / 7.6x faster, files 9% / 8% / 41% larger; igzip level 2 against
// zlib level 3, 4.7x / 10x / 5.8x faster, files -2.5% / +0.5% / +16%. zlib levels 2-3 map to
// igzip level 2, level 1 to level 1 (docs/architecture.md, formats/imageio).
Strip deflateStripIsal(const std::vector<unsigned char>& data,
                       const std::vector<unsigned char>& dict, bool last, int level) {
    Strip s;
    s.rawBytes = data.size();
    s.adler = isal_adler32(1, data.data(), data.size());
    const int igzipLevel = level <= 1 ? 1 : 2;
    // Neither is zero-filled: isal_deflate_init sets up the stream's state and the level buffer's
    // hash tables (as ISA-L's own tools allocate them: malloc).
    // The level buffer holds ISA-L's state, then the tokens of a block: a block ends when that
    // room is full. The state holds pointers, so on a 32-bit machine (WebAssembly) it is smaller
    // and the same buffer would hold a few more tokens, ending blocks elsewhere: other bytes than
    // the native build's. The buffer is sized so the token room is the 64-bit build's everywhere.
    const std::size_t state64 = igzipLevel == 1 ? kIsalLevel1State64 : kIsalLevel2State64;
    UninitBytes levelBuf((igzipLevel == 1 ? ISAL_DEF_LVL1_DEFAULT : ISAL_DEF_LVL2_DEFAULT) -
                         state64 + lutkit_isal_level_state_bytes(igzipLevel));
    std::unique_ptr<isal_zstream> z(new isal_zstream); // ~ 100 KiB: not on a thread's stack
    isal_deflate_init(z.get());
    z->level = static_cast<std::uint32_t>(igzipLevel);
    z->level_buf = levelBuf.data();
    z->level_buf_size = static_cast<std::uint32_t>(levelBuf.size());
    z->gzip_flag = IGZIP_DEFLATE; // raw deflate: the zlib header and Adler-32 are written here
    if (!dict.empty() && isal_deflate_set_dict(z.get(), const_cast<std::uint8_t*>(dict.data()),
                                               static_cast<std::uint32_t>(dict.size())) != COMP_OK)
        throw Error("cannot start the PNG compressor");
    z->end_of_stream = last ? 1 : 0;
    z->flush = last ? NO_FLUSH : SYNC_FLUSH;
    z->next_in = const_cast<std::uint8_t*>(data.data());
    z->avail_in = static_cast<std::uint32_t>(data.size());
    // Stored blocks bound the output: 5 bytes per 64 KiB block over the input, plus the flush.
    s.deflated.resize(data.size() + data.size() / 8192 + 1024);
    std::size_t done = 0;
    for (;;) {
        z->next_out = s.deflated.data() + done;
        z->avail_out = static_cast<std::uint32_t>(s.deflated.size() - done);
        if (isal_deflate(z.get()) != COMP_OK)
            throw Error("the PNG compressor failed");
        done = s.deflated.size() - z->avail_out;
        const bool finished =
            last ? z->internal_state.state == ZSTATE_END : z->avail_in == 0 && z->avail_out > 0;
        if (finished)
            break;
        if (z->avail_out > 0) // stopped with room left and work undone: never expected
            throw Error("the PNG compressor failed");
        s.deflated.resize(s.deflated.size() * 2); // rare: more room, and go on
    }
    s.deflated.resize(done);
    if (z->avail_in != 0)
        throw Error("the PNG compressor failed");
    return s;
}

Strip deflateStrip(const std::vector<unsigned char>& data, const std::vector<unsigned char>& dict,
                   bool last, int level) {
    return level >= 1 && level <= 3 ? deflateStripIsal(data, dict, last, level)
                                    : deflateStripZlib(data, dict, last, level);
}

// Appends filter byte + filtered row to `out` (the filter with the smallest sum of |signed
// bytes|, as libpng chooses by default; the image's first row tries neither Up nor Paeth). Each
// filter is its own loop over the raw rows, so it vectorizes. `up` is the row above (nullptr for
// the first row).
void filterRow(const unsigned char* cur, const unsigned char* up, std::size_t n, std::size_t bpp,
               std::vector<unsigned char>& out) {
    const bool first = up == nullptr;
    thread_local std::vector<unsigned char> zero, tryBuf;
    if (zero.size() < n)
        zero.assign(n, 0);
    if (first)
        up = zero.data();
    tryBuf.resize(5 * n);
    unsigned char* t[5];
    for (int f = 0; f < 5; ++f)
        t[f] = tryBuf.data() + static_cast<std::size_t>(f) * n;
    // min(o, 256 - o) is |o| as a signed byte (0 for 0), summed in 32 bits over 16 MiB pieces
    // (at most 2^31) with restrict-qualified loops, so the compiler vectorizes all of it.
    auto cost = [](const unsigned char* __restrict o, std::size_t k) {
        std::uint64_t total = 0;
        for (std::size_t at = 0; at < k; at += std::size_t(1) << 24) {
            const std::size_t end = std::min(k, at + (std::size_t(1) << 24));
            std::uint32_t sum = 0;
            for (std::size_t i = at; i < end; ++i)
                sum += std::min(o[i], static_cast<unsigned char>(-o[i]));
            total += sum;
        }
        return total;
    };
    for (std::size_t i = 0; i < bpp && i < n; ++i) { // no left neighbour
        t[0][i] = cur[i];
        t[1][i] = cur[i];
        t[2][i] = static_cast<unsigned char>(cur[i] - up[i]);
        t[3][i] = static_cast<unsigned char>(cur[i] - (up[i] >> 1));
        t[4][i] = static_cast<unsigned char>(cur[i] - up[i]); // Paeth(0, b, 0) = b
    }
    {
        const unsigned char* __restrict c = cur;
        const unsigned char* __restrict u = up;
        unsigned char* __restrict t0 = t[0];
        unsigned char* __restrict t1 = t[1];
        unsigned char* __restrict t2 = t[2];
        unsigned char* __restrict t3 = t[3];
        for (std::size_t i = bpp; i < n; ++i)
            t0[i] = c[i];
        for (std::size_t i = bpp; i < n; ++i)
            t1[i] = static_cast<unsigned char>(c[i] - c[i - bpp]);
        for (std::size_t i = bpp; i < n; ++i)
            t2[i] = static_cast<unsigned char>(c[i] - u[i]);
        for (std::size_t i = bpp; i < n; ++i)
            t3[i] = static_cast<unsigned char>(c[i] - ((c[i - bpp] + u[i]) >> 1));
    }
    for (std::size_t i = bpp; i < n; ++i) {
        const int a = cur[i - bpp], b = up[i], c = up[i - bpp];
        const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
        const int pred = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
        t[4][i] = static_cast<unsigned char>(cur[i] - pred);
    }
    std::uint64_t best = ~std::uint64_t(0);
    int bestFilter = 0;
    for (int f = 0; f < 5; ++f) {
        if (first && (f == 2 || f == 4))
            continue;
        const std::uint64_t c = cost(t[f], n);
        if (c < best) {
            best = c;
            bestFilter = f;
        }
    }
    out.push_back(static_cast<unsigned char>(bestFilter));
    out.insert(out.end(), t[bestFilter], t[bestFilter] + n);
}

// Rows of raw samples (big-endian) as the writer collected them for one strip, with the row
// above its first one (empty at the image's top).
struct RawRows {
    std::vector<unsigned char> bytes;
    std::size_t rows = 0;
    std::vector<unsigned char> above;
};

// The filtered bytes of rows [r0, r1) of `strip`.
void filterRows(const RawRows& strip, std::size_t r0, std::size_t r1, std::size_t rowBytes,
                std::size_t bpp, std::vector<unsigned char>& out) {
    for (std::size_t r = r0; r < r1; ++r) {
        const unsigned char* cur = strip.bytes.data() + r * rowBytes;
        const unsigned char* up = r > 0                 ? cur - rowBytes
                                  : strip.above.empty() ? nullptr
                                                        : strip.above.data();
        filterRow(cur, up, rowBytes, bpp, out);
    }
}

class PngSink : public ImageSink {
public:
    PngSink(const OutputTarget& target, const SinkSpec& spec) : m_out(target, false), m_spec(spec) {
        const int ch = static_cast<int>(spec.channelNames.size());
        if (ch < 1 || ch > 4)
            throw Error(target.path + ": PNG stores 1 to 4 channels, not " + std::to_string(ch));
        if (spec.type != PixelType::UInt8 && spec.type != PixelType::UInt16)
            throw Error(target.path + ": PNG stores 8 or 16 bits per channel, not " +
                        std::string(toString(spec.type)) + " (use .exr or .tif)");
        m_channels = ch;
        m_bytesPerSample = spec.type == PixelType::UInt16 ? 2 : 1;
        m_rowBytes = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(ch) *
                     static_cast<std::size_t>(m_bytesPerSample);
        m_raw = std::make_shared<RawRows>();
        // zlib level: "zip:N" (N 0..9) asks for one; 3 by default, which on image data costs a
        // third of level 6's time for files a few percent larger.
        m_level = kDefaultLevel;
        const std::string& c = spec.compression;
        if (c.size() == 5 && c.compare(0, 4, "zip:") == 0 && c[4] >= '0' && c[4] <= '9')
            m_level = c[4] - '0';
        else if (!c.empty() && c != "zip" && c != "deflate")
            throw Error(target.path + ": PNG has no compression '" + c + "' (zip:0 .. zip:9)");
        m_colour = ch == 1 ? 0 : ch == 2 ? 4 : ch == 3 ? 2 : 6;
        m_out.write(kSignature, 8);
        unsigned char ihdr[13];
        putBe32(ihdr, static_cast<std::uint32_t>(spec.width));
        putBe32(ihdr + 4, static_cast<std::uint32_t>(spec.height));
        ihdr[8] = static_cast<unsigned char>(8 * m_bytesPerSample);
        ihdr[9] = static_cast<unsigned char>(m_colour);
        ihdr[10] = ihdr[11] = ihdr[12] = 0;
        chunk("IHDR", ihdr, 13);
        writeMetadata(0);
        writeMetadata(1);
    }

    // Rows are collected raw; each strip of about kStripBytes filtered bytes is filtered and
    // deflated by one job, so filtering runs on the encoder threads too (it was a tenth of a
    // preview's CPU on the calling thread). The bytes are those of filtering row by row here.
    void writeRows(int y0, int y1, const void* src) override {
        const auto* s = static_cast<const unsigned char*>(src);
        for (int y = y0; y < y1; ++y) {
            const unsigned char* cur = s + m_rowBytes * static_cast<std::size_t>(y - y0);
            const std::size_t at = m_raw->bytes.size();
            if (at == 0) // a strip's rows, without a reallocation's copy as it grows
                m_raw->bytes.reserve((kStripBytes / (m_rowBytes + 1) + 1) * m_rowBytes);
            m_raw->bytes.resize(at + m_rowBytes);
            unsigned char* row = m_raw->bytes.data() + at;
            if (m_bytesPerSample == 2) { // host order to big-endian
                for (std::size_t i = 0; i < m_rowBytes; i += 2) {
                    row[i] = cur[i + 1];
                    row[i + 1] = cur[i];
                }
            } else {
                std::memcpy(row, cur, m_rowBytes);
            }
            ++m_raw->rows;
            if (m_raw->rows * (m_rowBytes + 1) >= kStripBytes)
                submit(false);
        }
    }

    void finish() override {
        submit(true);
        while (!m_jobs.empty())
            emitOldest();
        unsigned char adler[4];
        putBe32(adler, m_adler);
        chunk("IDAT", adler, 4);
        writeMetadata(2);
        chunk("IEND", nullptr, 0);
        m_out.commit();
    }

private:
    // A chunk of `prefixBytes` of `prefix`, then n bytes of data.
    void chunk(const char* type, const void* data, std::size_t n, std::size_t prefixBytes = 0,
               const unsigned char* prefix = nullptr) {
        unsigned char head[8];
        putBe32(head, static_cast<std::uint32_t>(prefixBytes + n));
        std::memcpy(head + 4, type, 4);
        uLong crc = crc32(0L, head + 4, 4);
        if (prefixBytes)
            crc = crc32(crc, prefix, static_cast<uInt>(prefixBytes));
        if (n)
            crc = crc32(crc, static_cast<const Bytef*>(data), static_cast<uInt>(n));
        unsigned char tail[4];
        putBe32(tail, static_cast<std::uint32_t>(crc));
        m_out.write(head, 8);
        if (prefixBytes)
            m_out.write(prefix, prefixBytes);
        if (n)
            m_out.write(data, n);
        m_out.write(tail, 4);
    }

    void writeMetadata(int place) {
        const auto& meta = m_spec.metadata;
        if (!meta)
            return;
        if (meta->format == "png") {
            // sBIT and bKGD are laid out by colour type and depth: only when both are kept.
            const bool sameLayout =
                meta->pngColourType == m_colour && meta->pngBitDepth == 8 * m_bytesPerSample;
            for (const auto& c : meta->pngChunks) {
                const bool layoutBound =
                    std::memcmp(c.type, "sBIT", 4) == 0 || std::memcmp(c.type, "bKGD", 4) == 0;
                const bool unsafeUnknown = (c.type[3] & 0x20) == 0 && !knownChunk(c.type);
                if ((c.place == place || (place == 1 && c.place == 0 && false)) &&
                    !(layoutBound && !sameLayout) && !unsafeUnknown)
                    chunk(c.type, c.data.data(), c.data.size());
            }
            return;
        }
        if (place != 0)
            return;
        if (!meta->icc.empty()) {
            std::string data = std::string("ICC Profile") + '\0' + '\0';
            uLongf n = compressBound(static_cast<uLong>(meta->icc.size()));
            std::string z(n, '\0');
            if (compress2(reinterpret_cast<Bytef*>(z.data()), &n,
                          reinterpret_cast<const Bytef*>(meta->icc.data()),
                          static_cast<uLong>(meta->icc.size()), 9) == Z_OK) {
                z.resize(n);
                data += z;
                chunk("iCCP", data.data(), data.size());
            }
        } else if (meta->srgb) {
            const char intent = 0; // perceptual
            chunk("sRGB", &intent, 1);
        }
        if (!meta->exif.empty())
            chunk("eXIf", meta->exif.data(), meta->exif.size());
        for (const auto& [key, value] : meta->text)
            if (!key.empty() && key.size() < 80) {
                // ImageDescription (TIFF, OpenImageIO, a LUT image's LUTKIT_PURPOSE tag) is
                // PNG's registered keyword "Description".
                const std::string data =
                    (key == "ImageDescription" ? std::string("Description") : key) + '\0' + value;
                chunk("tEXt", data.data(), data.size());
            }
    }

    static bool knownChunk(const char* t) {
        static const char* const kKnown[] = {"iCCP", "sRGB", "gAMA", "cHRM", "cICP", "mDCv", "cLLi",
                                             "sBIT", "bKGD", "pHYs", "oFFs", "pCAL", "sCAL"};
        for (const char* k : kKnown)
            if (std::memcmp(t, k, 4) == 0)
                return true;
        return false;
    }

    void submit(bool last) {
        std::shared_ptr<const RawRows> strip = std::move(m_raw);
        std::shared_ptr<const RawRows> prev = std::move(m_last); // its dictionary's source
        m_raw = std::make_shared<RawRows>();
        m_raw->above = strip->rows > 0
                           ? std::vector<unsigned char>(strip->bytes.end() -
                                                            static_cast<std::ptrdiff_t>(m_rowBytes),
                                                        strip->bytes.end())
                           : strip->above;
        m_last = strip;
        const int level = m_level;
        const std::size_t rowBytes = m_rowBytes;
        const std::size_t bpp = static_cast<std::size_t>(m_channels * m_bytesPerSample);
        m_jobs.push_back(std::async(
            threadsAvailable() ? std::launch::async : std::launch::deferred,
            [strip, prev, last, level, rowBytes, bpp] {
                // The dictionary: the last 32 KiB of the filtered stream so far, i.e. of the strip
                // before (every strip but the last holds at least kStripBytes), refiltered here.
                std::vector<unsigned char> dict;
                if (prev && prev->rows > 0) {
                    const std::size_t need = (kWindow + rowBytes) / (rowBytes + 1) + 1;
                    const std::size_t r0 = prev->rows > need ? prev->rows - need : 0;
                    filterRows(*prev, r0, prev->rows, rowBytes, bpp, dict);
                    if (dict.size() > kWindow)
                        dict.erase(dict.begin(), dict.end() - static_cast<std::ptrdiff_t>(kWindow));
                }
                std::vector<unsigned char> data;
                data.reserve(strip->rows * (rowBytes + 1));
                filterRows(*strip, 0, strip->rows, rowBytes, bpp, data);
                return deflateStrip(data, dict, last, level);
            }));
        const std::size_t inFlight = static_cast<std::size_t>(std::max(1, m_spec.threads)) + 1;
        while (m_jobs.size() > inFlight)
            emitOldest();
    }

    void emitOldest() {
        Strip s = m_jobs.front().get();
        m_jobs.pop_front();
        static const unsigned char kZlibHeader[2] = {0x78, 0x9c}; // deflate, 32K window
        m_adler = static_cast<std::uint32_t>(
            adler32_combine(m_adler, s.adler, static_cast<z_off_t>(s.rawBytes)));
        chunk("IDAT", s.deflated.data(), s.deflated.size(), m_headerDone ? 0 : 2, kZlibHeader);
        m_headerDone = true;
    }

    ByteWriter m_out;
    SinkSpec m_spec;
    int m_channels = 3, m_bytesPerSample = 1, m_colour = 2, m_level = 6;
    std::size_t m_rowBytes = 0;
    std::shared_ptr<RawRows> m_raw;        // the strip being collected
    std::shared_ptr<const RawRows> m_last; // the strip submitted last
    std::deque<std::future<Strip>> m_jobs;
    std::uint32_t m_adler = 1;
    bool m_headerDone = false;
};

} // namespace

std::unique_ptr<ImageSink> createPngSink(const OutputTarget& target, const SinkSpec& spec) {
    return std::make_unique<PngSink>(target, spec);
}

} // namespace lut::formats
