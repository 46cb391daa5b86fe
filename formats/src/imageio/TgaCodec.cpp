// SPDX-License-Identifier: Apache-2.0
// Truevision TGA, natively (read only; OpenImageIO writes TGA): image types 1, 2, 3 and their
// run-length forms 9, 10, 11 (colour-mapped, true colour, greyscale), 15/16/24/32-bit true colour,
// 8- and 16-bit indices into a 15/16/24/32-bit colour map, 8-bit grey and 16-bit grey with alpha,
// rows bottom-up or top-down, left-to-right or right-to-left; the TGA 2.0 footer and extension
// area (Truevision's "TGA File Format Specification" 2.0). No magic number: a file is taken for
// TGA by its name (.tga), the named format or its 2.0 footer (ImageHeaderChecks.cpp).
// Samples, channels, ImageInfo and the attributes handed to OpenImageIO's writers are what
// OpenImageIO 2.4 (targainput.cpp, what lutkit read TGA with before) gives with lutkit's setting
// oiio:UnassociatedAlpha = 1, checked against it in tests/formats/test_bmp_tga_read.cpp:
//   - R, G, B (and A for 32 bits), one "Y" for grey; 15/16-bit pixels are 5-5-5 widened by
//     repeating their bits (the 16th bit is not alpha); a colour map's alpha is dropped;
//   - alpha is kept as stored (with that setting OpenImageIO does not premultiply, whatever the
//     extension area's alpha type says);
//   - compression "rle" (else none said), targa:ImageID, targa:version; from the extension area
//     Artist, ImageDescription (its four lines), DateTime, DocumentName, targa:JobTime, Software
//     (name and version), PixelAspectRatio, the gamma as oiio:ColorSpace ("linear" or "Gamma2.2")
//     and oiio:Gamma, targa:alpha_type, the postage stamp's size; the text ones also in
//     ImageMetadata::text for the other writers.
// Where OpenImageIO 2.4 reads a file oddly, lutkit reads what the file means:
//   - 16-bit grey with alpha is "Y", "A" (alpha channel 1); OpenImageIO named them "R", "G" and
//     said no alpha (the samples are the same);
//   - bitsPerSample is the bits a channel is stored with (5 for 15/16-bit colour or colour-map
//     entries, else 8); OpenImageIO divided the pixel's bits by the channels (2 for an 8-bit
//     colour-mapped file);
//   - a colour-map index v means entry v - first (the header's first entry index), as the
//     specification and ImageMagick read it; OpenImageIO read entry first + v, and past its map
//     for an index the map does not hold (read here: refused, naming the pixel);
//   - an alpha channel that is 0 everywhere in a file that does not vouch for it (a TGA 1.0 file,
//     or a 2.0 extension area whose alpha type is not 3 "useful" or 4 "premultiplied") is
//     opaque (255): OpenImageIO's own reader calls such an alpha meaningless, but with lutkit's
//     setting gave a picture that vanishes;
//   - the software version letter is appended only when it is a letter (OpenImageIO appended a
//     NUL byte for 0);
//   - refused where OpenImageIO read garbage: true colour at 8 bits, colour-map indices of 24 or
//     32 bits, grey at other than 8 or 16 bits.
// Where OpenImageIO refuses a file (a short header, types and sizes outside the specification, a
// colour map on a grey image or none on a colour-mapped one, an extension area or postage stamp
// past the end, pixel data that ends early), so does this reader, at open, in one line naming the
// field.
// Memory: uncompressed rows are read where they lie, in blocks of at most 1 MiB; a run-length
// stream (packets may run across rows) is decoded once at open (checked whole: truncation, indices,
// alpha) noting the packet state where each row starts (24 bytes a row), and rows are decoded from
// there when asked, where OpenImageIO held the whole image.
#include "imageio/ByteIO.h"
#include "imageio/ImageCodec.h"
#include "imageio/OiioAttributes.h"
#include "imageio/RowWindowSource.h"

#include "lut/Error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace lut::formats {

namespace {

std::uint32_t le16(const unsigned char* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8;
}
std::uint32_t le32(const unsigned char* p) {
    return le16(p) | le16(p + 2) << 16;
}

// A 1-5-5-5 pixel (little-endian) to 8-bit R, G, B: OpenImageIO's bit_range_convert<5, 8>.
void widen555(const unsigned char* in, unsigned char* out) {
    const unsigned v = le16(in);
    const unsigned r = (v >> 10) & 31, g = (v >> 5) & 31, b = v & 31;
    out[0] = static_cast<unsigned char>(r << 3 | r >> 2);
    out[1] = static_cast<unsigned char>(g << 3 | g >> 2);
    out[2] = static_cast<unsigned char>(b << 3 | b >> 2);
}

// A fixed-size text field: up to its first NUL.
std::string field(const unsigned char* p, std::size_t n) {
    const auto* c = reinterpret_cast<const char*>(p);
    return std::string(c, static_cast<std::size_t>(std::find(c, c + n, '\0') - c));
}

class TgaSource : public RowWindowSource {
public:
    TgaSource(const std::string& path, std::string memory)
        : RowWindowSource(path, std::move(memory), "TGA") {
        readHeader();
    }

private:
    void readPackedRows(std::int64_t a, std::int64_t b, const RowPlace& place) override {
        Mark m = m_marks[static_cast<std::size_t>(a)];
        m_window.seek(m.offset);
        m_row.resize(m_pixelBytes * static_cast<std::size_t>(m_info.width));
        for (std::int64_t r = a; r < b; ++r) {
            unpack(m, m_row.data(), r);
            convertRow(m_row.data(), place(r), r);
        }
    }

    void readHeader() {
        unsigned char hd[18];
        if (m_in.pread(hd, 18, 0) != 18)
            fail("TGA header is cut short (" + std::to_string(m_in.size()) + " bytes of 18)");
        const int idLength = hd[0], mapType = hd[1];
        m_type = hd[2];
        m_mapFirst = le16(hd + 3);
        m_mapLength = le16(hd + 5);
        const int mapBits = hd[7];
        const int w = static_cast<int>(le16(hd + 12)), h = static_cast<int>(le16(hd + 14));
        m_bpp = hd[16];
        const int attr = hd[17];
        if (mapType != 0 && mapType != 1)
            fail("TGA colour-map type " + std::to_string(mapType) +
                 " (header byte 1) is not 0 or 1");
        if (m_type == 0)
            fail("TGA image type 0 (header byte 2) holds no image");
        if (m_type != 1 && m_type != 2 && m_type != 3 && m_type != 9 && m_type != 10 &&
            m_type != 11)
            fail("TGA image type " + std::to_string(m_type) +
                 " (header byte 2) is not one lutkit reads (1, 2, 3, 9, 10, 11)");
        m_mapped = m_type == 1 || m_type == 9;
        m_grey = m_type == 3 || m_type == 11;
        m_packed = m_type >= 9;
        const bool sizeOk = m_mapped ? m_bpp == 8 || m_bpp == 15 || m_bpp == 16
                            : m_grey ? m_bpp == 8 || m_bpp == 16
                                     : m_bpp == 15 || m_bpp == 16 || m_bpp == 24 || m_bpp == 32;
        if (!sizeOk)
            fail("TGA pixel size of " + std::to_string(m_bpp) +
                 " bits (header byte 16) is not one " +
                 (m_mapped ? "a colour-mapped image has (8, 15 or 16)"
                  : m_grey ? "a greyscale image has (8 or 16)"
                           : "a true-colour image has (15, 16, 24 or 32)"));
        if (m_mapped && mapType == 0)
            fail("colour-mapped TGA (image type " + std::to_string(m_type) + ") has no colour map");
        if (m_grey && mapType == 1)
            fail("greyscale TGA (image type " + std::to_string(m_type) + ") has a colour map");
        if (mapType == 1 && mapBits != 15 && mapBits != 16 && mapBits != 24 && mapBits != 32)
            fail("TGA colour-map entry size of " + std::to_string(mapBits) +
                 " bits (header byte 7) is not 15, 16, 24 or 32");
        m_pixelBytes = m_bpp == 15 ? 2 : static_cast<std::size_t>(m_bpp / 8);
        m_stride = m_pixelBytes * static_cast<std::size_t>(w);
        m_topDown = (attr & 0x20) != 0;
        m_rightToLeft = (attr & 0x10) != 0;
        // OpenImageIO's channel rule: alpha for 32 bits, or for 16-bit grey whose header gives 8
        // or more alpha bits.
        const bool greyAlpha = m_grey && m_bpp > 8 && (attr & 0x08) != 0;
        const int channels = (m_grey ? 1 : 3) + (m_bpp == 32 || greyAlpha ? 1 : 0);
        checkImageSize(m_in.path(), w, h, channels);
        m_info.width = w;
        m_info.height = h;
        m_info.channels = channels;
        m_info.format = "targa";
        m_info.type = PixelType::UInt8;
        m_info.bitDepth = 8;
        m_info.bitsPerSample =
            (!m_mapped && !m_grey && m_bpp <= 16) || (m_mapped && (mapBits == 15 || mapBits == 16))
                ? 5
                : 8;
        m_info.channelNames = channels == 1   ? std::vector<std::string>{"Y"}
                              : channels == 2 ? std::vector<std::string>{"Y", "A"}
                              : channels == 3 ? std::vector<std::string>{"R", "G", "B"}
                                              : std::vector<std::string>{"R", "G", "B", "A"};
        m_info.alphaChannel = channels == 2 ? 1 : channels == 4 ? 3 : -1;
        m_info.compression = m_packed ? "rle" : "";

        OiioAttributes a;
        a.addInt("oiio:BitsPerSample", m_info.bitsPerSample);
        if (m_packed)
            a.addString("compression", "rle");
        std::uint64_t at = 18;
        if (idLength > 0) {
            unsigned char id[255];
            if (m_in.pread(id, static_cast<std::size_t>(idLength), at) !=
                static_cast<std::size_t>(idLength))
                fail("TGA image ID of " + std::to_string(idLength) +
                     " bytes (header byte 0) runs past the end of the file (truncated)");
            a.addString("targa:ImageID", field(id, static_cast<std::size_t>(idLength)));
            at += static_cast<std::uint64_t>(idLength);
        }
        if (mapType == 1) {
            const std::size_t entryBytes =
                mapBits == 15 ? 2 : static_cast<std::size_t>(mapBits / 8);
            std::vector<unsigned char> raw(entryBytes * m_mapLength);
            if (m_in.pread(raw.data(), raw.size(), at) != raw.size())
                fail("TGA colour map of " + std::to_string(m_mapLength) +
                     " entries runs past the end of the file (truncated)");
            m_palette.resize(m_mapLength);
            for (std::size_t i = 0; i < m_mapLength; ++i) {
                const unsigned char* e = raw.data() + i * entryBytes;
                if (entryBytes == 2)
                    widen555(e, m_palette[i].data());
                else
                    m_palette[i] = {e[2], e[1], e[0]};
            }
            at += raw.size();
        }
        m_dataStart = at;

        auto meta = std::make_shared<ImageMetadata>();
        meta->format = "targa";
        int alphaType = -1; // the 2.0 extension area's, when there is one
        const bool v2 = readExtension(a, *meta, alphaType);
        a.addInt("targa:version", v2 ? 2 : 1);
        // OpenImageIO's "useful alpha" (the header's alpha bits, or the extension's type 3) with
        // an alpha channel it names (4 channels).
        const bool useful = alphaType >= 0 ? alphaType == 3 : m_bpp == 32 && (attr & 0x08) != 0;
        if (channels == 4 && useful)
            a.addInt("oiio:UnassociatedAlpha", 1);

        const std::uint64_t pixels = static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h);
        bool anyAlpha = false;
        if (m_packed) {
            indexRle(anyAlpha);
        } else {
            const std::uint64_t need = m_dataStart + pixels * m_pixelBytes;
            if (m_in.size() < need)
                fail("TGA pixel data ends early: " + std::to_string(w) + "x" + std::to_string(h) +
                     " pixels at " + std::to_string(m_bpp) + " bits need " +
                     std::to_string(need - m_dataStart) + " bytes from byte " +
                     std::to_string(m_dataStart) + ", the file has " + std::to_string(m_in.size()) +
                     " (truncated)");
            anyAlpha = channels % 2 == 0 && uncompressedAlpha();
        }
        const bool vouched = alphaType == 3 || alphaType == 4;
        m_opaque = channels % 2 == 0 && !vouched && !anyAlpha;
        m_info.decoderBytes =
            m_marks.capacity() * sizeof(Mark) + (std::size_t(1) << 16) +
            std::max<std::size_t>(m_pixelBytes * static_cast<std::size_t>(w), std::size_t(1) << 20);
        meta->oiioAttributes = a.bytes();
        m_metadata = meta;
    }

    // The TGA 2.0 footer ("TRUEVISION-XFILE.\0" in the last 18 bytes after the extension and
    // developer areas' offsets) and its extension area, read as OpenImageIO 2.4 reads them.
    bool readExtension(OiioAttributes& a, ImageMetadata& meta, int& alphaType) {
        const std::uint64_t size = m_in.size();
        unsigned char foot[26];
        if (size <= 26 + 18 || m_in.pread(foot, 26, size - 26) != 26 ||
            std::memcmp(foot + 8, "TRUEVISION-XFILE.", 17) != 0)
            return false;
        const std::uint64_t ext = le32(foot);
        if (ext == 0)
            return true; // a footer without an extension area
        unsigned char e[495];
        const std::size_t got = m_in.pread(e, sizeof e, ext);
        if (got < 2)
            fail("TGA 2.0 extension area at byte " + std::to_string(ext) +
                 " (from the footer) lies past the end of the file");
        if (le16(e) < 495)
            return true; // too short to hold the fields: ignored, as the specification says
        if (got < sizeof e)
            fail("TGA 2.0 extension area at byte " + std::to_string(ext) +
                 " runs past the end of the file (truncated)");
        std::vector<std::pair<std::string, std::string>> text;
        auto put = [&](const char* key, const std::string& v) {
            a.addString(key, v);
            text.emplace_back(key, v);
        };
        char buf[96];
        if (e[2] != 0)
            put("Artist", field(e + 2, 41));
        std::string comments = field(e + 43, 81);
        for (int line = 1; line < 4; ++line)
            if (e[43 + 81 * line] != 0)
                comments += "\n" + field(e + 43 + 81 * line, 81);
        if (!comments.empty())
            put("ImageDescription", comments);
        unsigned stamp[6];
        for (int i = 0; i < 6; ++i)
            stamp[i] = le16(e + 367 + 2 * i); // month, day, year, hour, minute, second
        if (stamp[0] || stamp[1] || stamp[2] || stamp[3] || stamp[4] || stamp[5]) {
            std::snprintf(buf, sizeof buf, "%04u:%02u:%02u %02u:%02u:%02u", stamp[2], stamp[0],
                          stamp[1], stamp[3], stamp[4], stamp[5]);
            put("DateTime", buf);
        }
        if (e[379] != 0)
            a.addString("DocumentName", field(e + 379, 41));
        const unsigned hours = le16(e + 420), minutes = le16(e + 422), seconds = le16(e + 424);
        if (hours || minutes || seconds) {
            std::snprintf(buf, sizeof buf, "%u:%02u:%02u", hours, minutes, seconds);
            a.addString("targa:JobTime", buf);
        }
        if (e[426] != 0) {
            const unsigned version = le16(e + 467);
            std::snprintf(buf, sizeof buf, " %u.%u", version / 100, version % 100);
            std::string software = field(e + 426, 41) + buf;
            const char letter = static_cast<char>(e[469]);
            if (letter != ' ' && letter != '\0')
                software += letter;
            put("Software", software);
        }
        if (le16(e + 476) != 0)
            a.addFloat("PixelAspectRatio",
                       static_cast<float>(le16(e + 474)) / static_cast<float>(le16(e + 476)));
        if (le16(e + 480) != 0) {
            float gamma = static_cast<float>(le16(e + 478)) / static_cast<float>(le16(e + 480));
            gamma = std::roundf(static_cast<float>(100.0 * gamma)) / 100.0f; // OpenImageIO's
            if (gamma == 1.0f) {
                a.addString("oiio:ColorSpace", "linear");
                m_info.colorSpace = "linear";
            } else {
                std::snprintf(buf, sizeof buf, "Gamma%.2g", static_cast<double>(gamma));
                a.addString("oiio:ColorSpace", buf);
                a.addFloat("oiio:Gamma", gamma);
                m_info.colorSpace = buf;
            }
        }
        alphaType = e[494];
        if (alphaType != 0)
            a.addInt("targa:alpha_type", alphaType);
        const std::uint64_t thumb = le32(e + 486);
        if (thumb > 0) {
            unsigned char wh[2];
            if (m_in.pread(wh, 2, thumb) != 2)
                fail("TGA postage stamp at byte " + std::to_string(thumb) +
                     " (from the extension area) lies past the end of the file");
            if (wh[0] > 0 && wh[1] > 0) {
                a.addInt("thumbnail_width", wh[0]);
                a.addInt("thumbnail_height", wh[1]);
                a.addInt("thumbnail_nchannels", m_info.channels);
            }
        }
        // ImageMetadata::text in the order the OpenImageIO reader's metadata listed them.
        for (const char* key : {"ImageDescription", "Copyright", "Artist", "DateTime", "Software"})
            for (const auto& kv : text)
                if (kv.first == key)
                    meta.text.push_back(kv);
        return true;
    }

    // Whether an uncompressed file's alpha samples (a pixel's last byte) are anything but 0
    // (read until one is).
    bool uncompressedAlpha() const {
        const std::uint64_t total =
            static_cast<std::uint64_t>(m_info.width) * m_info.height * m_pixelBytes;
        std::vector<unsigned char> buf((std::size_t(1) << 20) / m_pixelBytes * m_pixelBytes);
        for (std::uint64_t at = 0; at < total;) {
            const std::size_t n =
                static_cast<std::size_t>(std::min<std::uint64_t>(buf.size(), total - at));
            if (m_in.pread(buf.data(), n, m_dataStart + at) != n)
                fail("TGA pixel data ends early (truncated)");
            for (std::size_t i = m_pixelBytes - 1; i < n; i += m_pixelBytes)
                if (buf[i] != 0)
                    return true;
            at += n;
        }
        return false;
    }

    // Run-length packets: a byte (bit 7: a run; bits 0-6: pixels - 1), then one pixel (a run)
    // or that many (raw). A packet may run on into the next row.
    struct Mark {
        std::uint64_t offset = 0; // the next byte: a packet's header, or a raw packet's pixel
        std::uint32_t left = 0;   // pixels left in the current packet
        bool run = false;
        unsigned char pixel[4] = {0, 0, 0, 0};
    };

    // The next row of a run-length stream (file row r, for messages) into out, from state m.
    void unpack(Mark& m, unsigned char* out, std::int64_t r) {
        const std::size_t pb = m_pixelBytes;
        for (std::uint32_t n = static_cast<std::uint32_t>(m_info.width); n > 0;) {
            if (m.left == 0) {
                const unsigned char* p = m_window.take(1);
                if (!p)
                    fail("TGA run-length data ends in row " + std::to_string(r + 1) + " of " +
                         std::to_string(m_info.height) + " (truncated)");
                m.left = (p[0] & 0x7fu) + 1;
                m.run = (p[0] & 0x80u) != 0;
                if (m.run) {
                    const unsigned char* v = m_window.take(pb);
                    if (!v)
                        fail("TGA run-length data ends in row " + std::to_string(r + 1) +
                             " (truncated)");
                    std::memcpy(m.pixel, v, pb);
                }
            }
            const std::uint32_t k = std::min(m.left, n);
            if (m.run) {
                for (std::uint32_t i = 0; i < k; ++i, out += pb)
                    std::memcpy(out, m.pixel, pb);
            } else {
                const unsigned char* v = m_window.take(pb * k);
                if (!v)
                    fail("TGA run-length data ends in row " + std::to_string(r + 1) + " of " +
                         std::to_string(m_info.height) + " (truncated)");
                std::memcpy(out, v, pb * k);
                out += pb * k;
            }
            m.left -= k;
            n -= k;
        }
        m.offset = m_window.tell();
    }

    // Decodes the whole stream once: it must hold every row, its indices must be in the map;
    // notes where each row starts and whether any alpha sample is set.
    void indexRle(bool& anyAlpha) {
        const int h = m_info.height;
        const std::size_t pb = m_pixelBytes, w = static_cast<std::size_t>(m_info.width);
        m_marks.resize(static_cast<std::size_t>(h));
        m_row.resize(pb * w);
        m_window.seek(m_dataStart);
        Mark m;
        m.offset = m_dataStart;
        const bool alpha = m_info.channels % 2 == 0;
        for (int r = 0; r < h; ++r) {
            m_marks[static_cast<std::size_t>(r)] = m;
            unpack(m, m_row.data(), r);
            if (m_mapped)
                for (std::size_t x = 0; x < w; ++x)
                    entry(m_row.data() + x * pb, x, r);
            if (alpha && !anyAlpha)
                for (std::size_t i = pb - 1; i < pb * w; i += pb)
                    anyAlpha = anyAlpha || m_row[i] != 0;
        }
    }

    // The colour-map entry of a stored index (at x of file row r, for the message).
    const std::array<unsigned char, 3>& entry(const unsigned char* p, std::size_t x,
                                              std::int64_t r) const {
        const std::uint32_t v = m_pixelBytes == 1 ? p[0] : le16(p);
        if (v < m_mapFirst || v - m_mapFirst >= m_mapLength) {
            const std::int64_t y = m_topDown ? r : m_info.height - 1 - r;
            const std::size_t col = m_rightToLeft ? m_info.width - 1 - x : x;
            fail("TGA pixel (" + std::to_string(col) + ", " + std::to_string(y) +
                 ") is colour-map index " + std::to_string(v) + ", the map holds " +
                 (m_mapLength == 0 ? std::string("none")
                                   : std::to_string(m_mapFirst) + " to " +
                                         std::to_string(m_mapFirst + m_mapLength - 1)));
        }
        return m_palette[v - m_mapFirst];
    }

    // A stored row (file row r) to the image's channels, right-to-left rows mirrored.
    void convertRow(const unsigned char* s, unsigned char* out, std::int64_t r) override {
        const int w = m_info.width, ch = m_info.channels;
        const std::size_t pb = m_pixelBytes;
        for (int i = 0; i < w; ++i) {
            const int x = m_rightToLeft ? w - 1 - i : i;
            const unsigned char* p = s + static_cast<std::size_t>(i) * pb;
            unsigned char* o = out + static_cast<std::size_t>(x) * static_cast<std::size_t>(ch);
            if (m_mapped) {
                std::memcpy(o, entry(p, static_cast<std::size_t>(i), r).data(), 3);
            } else if (m_grey) {
                o[0] = p[0];
                if (ch == 2)
                    o[1] = m_opaque ? 255 : p[1];
            } else if (pb == 2) {
                widen555(p, o);
            } else {
                o[0] = p[2];
                o[1] = p[1];
                o[2] = p[0];
                if (ch == 4)
                    o[3] = m_opaque ? 255 : p[3];
            }
        }
    }

    int m_type = 0;
    int m_bpp = 0;
    std::size_t m_pixelBytes = 1;
    std::uint32_t m_mapFirst = 0, m_mapLength = 0;
    bool m_mapped = false, m_grey = false;
    bool m_rightToLeft = false;
    bool m_opaque = false;
    std::vector<std::array<unsigned char, 3>> m_palette; // R, G, B
    std::vector<Mark> m_marks;
    UninitBytes m_row;
};

} // namespace

std::unique_ptr<ImageSource> openTgaSource(const std::string& path, std::string memory) {
    return std::make_unique<TgaSource>(path, std::move(memory));
}

} // namespace lut::formats
