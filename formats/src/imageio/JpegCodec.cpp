// SPDX-License-Identifier: Apache-2.0
// JPEG, natively: libjpeg-turbo's decoder, row by row, as OpenImageIO's JPEG reader calls it (the
// default islow DCT and fancy upsampling; CMYK and YCCK files made RGB by OpenImageIO's formula),
// so the samples are the ones lutkit read through OpenImageIO before, without loading its module
// (~190 ms of CPU) for a Switch screenshot. The portable builds compile the same libjpeg-turbo
// release (cmake/LutkitThirdParty.cmake) and decode the same samples.
//
// libjpeg only warns about damaged data (a premature end of a data segment, extraneous bytes
// before a marker, a bad Huffman code) and fills what it could not decode with grey; here every
// such warning is an error naming the file, with libjpeg's own words (docs/robustness.md). Only
// two warnings about harmless metadata pass: an unknown JFIF revision and an unknown Adobe
// colour transform code.
//
// Metadata kept for writers: the EXIF block (APP1 "Exif"), the XMP packet (APP1), the ICC profile
// (APP2, joined), the IPTC block (APP13 "Photoshop 3.0"), the comment (COM, as ImageDescription),
// the JFIF resolution and the chroma subsampling.
#include "imageio/ByteIO.h"
#include "imageio/ImageCodec.h"

#include "lut/Error.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <jerror.h>
#include <jpeglib.h>

namespace lut::formats {

namespace {

constexpr std::size_t kReadChunk = 65536;

// libjpeg's error manager, with the message kept. libjpeg's error leaves through an exception, not
// a longjmp (as libpng's does in PngCodec.cpp: the browser edition's WebAssembly exceptions do not
// mix with setjmp); libjpeg's C frames are unwound without cleanups and its memory is freed by
// jpeg_destroy_decompress, as after a longjmp.
struct ErrorManager {
    jpeg_error_mgr pub;
    char message[JMSG_LENGTH_MAX] = {};
};

struct JpegAbort {};

[[noreturn]] void onError(j_common_ptr cinfo) {
    auto* e = reinterpret_cast<ErrorManager*>(cinfo->err);
    (*cinfo->err->format_message)(cinfo, e->message);
    throw JpegAbort{};
}

void onMessage(j_common_ptr cinfo, int level) {
    if (level >= 0)
        return; // trace messages
    const int code = cinfo->err->msg_code;
    if (code == JWRN_JFIF_MAJOR || code == JWRN_ADOBE_XFORM)
        return; // about the headers' words, not the pixels
    onError(cinfo);
}

// The bytes, a chunk at a time, from the file or from memory.
struct Source {
    jpeg_source_mgr pub;
    ByteReader* reader = nullptr;
    std::vector<JOCTET> buffer;
    bool ended = false;
};

void initSource(j_decompress_ptr) {}

boolean fillInput(j_decompress_ptr cinfo) {
    auto* s = reinterpret_cast<Source*>(cinfo->src);
    const std::size_t n = s->reader->read(s->buffer.data(), s->buffer.size());
    if (n == 0) {
        // As libjpeg's own sources do: a fake end-of-image marker, and a warning (an error here).
        WARNMS(cinfo, JWRN_JPEG_EOF);
        s->buffer[0] = 0xFF;
        s->buffer[1] = JPEG_EOI;
        s->pub.next_input_byte = s->buffer.data();
        s->pub.bytes_in_buffer = 2;
        return TRUE;
    }
    s->pub.next_input_byte = s->buffer.data();
    s->pub.bytes_in_buffer = n;
    return TRUE;
}

void skipInput(j_decompress_ptr cinfo, long count) {
    auto* s = reinterpret_cast<Source*>(cinfo->src);
    if (count <= 0)
        return;
    auto n = static_cast<std::size_t>(count);
    while (n > s->pub.bytes_in_buffer) {
        n -= s->pub.bytes_in_buffer;
        s->pub.bytes_in_buffer = 0;
        (void)fillInput(cinfo);
    }
    s->pub.next_input_byte += n;
    s->pub.bytes_in_buffer -= n;
}

void termSource(j_decompress_ptr) {}

bool startsWith(const jpeg_saved_marker_ptr m, const char* tag, std::size_t n) {
    return m->data_length >= n && std::memcmp(m->data, tag, n) == 0;
}

// OpenImageIO's names for a file's chroma subsampling (jpeg:subsampling), from the first three
// components' sampling factors as OpenImageIO reads them (a CMYK file's too); "" for another or
// for fewer than three components.
std::string subsamplingOf(const jpeg_decompress_struct& c) {
    if (c.num_components < 3)
        return {};
    const jpeg_component_info* k = c.comp_info;
    for (int i = 1; i < 3; ++i)
        if (k[i].h_samp_factor != 1 || k[i].v_samp_factor != 1)
            return {};
    const int h = k[0].h_samp_factor, v = k[0].v_samp_factor;
    if (h == 2 && v == 2)
        return "4:2:0";
    if (h == 2 && v == 1)
        return "4:2:2";
    if (h == 4 && v == 1)
        return "4:1:1";
    if (h == 1 && v == 1)
        return "4:4:4";
    return {};
}

class JpegSource : public ImageSource {
public:
    JpegSource(const std::string& path, std::string memory)
        : m_path(path), m_reader(path, std::move(memory)) {
        std::memset(&m_cinfo, 0, sizeof m_cinfo);
        m_cinfo.err = jpeg_std_error(&m_err.pub);
        m_err.pub.error_exit = onError;
        m_err.pub.emit_message = onMessage;
        try {
            open();
        } catch (const JpegAbort&) {
            destroy();
            fail();
        } catch (...) {
            destroy();
            throw;
        }
    }

    ~JpegSource() override { destroy(); }

    void readRows(int y0, int y1, void* dst) override {
        auto* out = static_cast<unsigned char*>(dst);
        const std::size_t stride = rowBytes(m_info);
        try {
            if (!m_started) {
                jpeg_start_decompress(&m_cinfo); // a progressive file's scans are all read here
                m_started = true;
            }
            for (int y = y0; y < y1; ++y, out += stride) {
                JSAMPROW row = m_cmyk ? m_row.data() : out;
                if (jpeg_read_scanlines(&m_cinfo, &row, 1) != 1)
                    throw Error(m_path + ": JPEG file ends before its last row");
                if (m_cmyk)
                    cmykToRgb(m_row.data(), out, static_cast<int>(m_cinfo.output_width));
            }
        } catch (const JpegAbort&) {
            fail();
        }
        m_rowsRead = y1;
    }

    void finish() override {
        try {
            if (m_rowsRead == static_cast<int>(m_cinfo.output_height))
                jpeg_finish_decompress(&m_cinfo); // reads to the end-of-image marker
        } catch (const JpegAbort&) {
            fail();
        }
    }

private:
    void open() {
        jpeg_create_decompress(&m_cinfo);
        m_created = true;
        m_src.reader = &m_reader;
        m_src.buffer.resize(kReadChunk);
        m_src.pub.init_source = initSource;
        m_src.pub.fill_input_buffer = fillInput;
        m_src.pub.skip_input_data = skipInput;
        m_src.pub.resync_to_restart = jpeg_resync_to_restart;
        m_src.pub.term_source = termSource;
        m_src.pub.bytes_in_buffer = 0;
        m_src.pub.next_input_byte = nullptr;
        m_cinfo.src = &m_src.pub;
        jpeg_save_markers(&m_cinfo, JPEG_APP0 + 1, 0xFFFF);
        jpeg_save_markers(&m_cinfo, JPEG_APP0 + 2, 0xFFFF);
        jpeg_save_markers(&m_cinfo, JPEG_APP0 + 13, 0xFFFF);
        jpeg_save_markers(&m_cinfo, JPEG_COM, 0xFFFF);
        jpeg_read_header(&m_cinfo, TRUE);
        // Sizes before anything is allocated for them.
        checkImageSize(m_path,
                       static_cast<int>(std::min<JDIMENSION>(m_cinfo.image_width, 1u << 30)),
                       static_cast<int>(std::min<JDIMENSION>(m_cinfo.image_height, 1u << 30)),
                       std::max(1, m_cinfo.num_components));
        m_cmyk = m_cinfo.jpeg_color_space == JCS_CMYK || m_cinfo.jpeg_color_space == JCS_YCCK;
        if (m_cmyk)
            m_cinfo.out_color_space = JCS_CMYK;
        jpeg_calc_output_dimensions(&m_cinfo);
        describe(); // decoding starts with the first rows asked for, after the memory is checked
        if (m_cmyk)
            m_row.resize(static_cast<std::size_t>(m_cinfo.output_width) * 4);
    }

    [[noreturn]] void fail() const {
        throw Error(m_path + ": cannot read image data: JPEG error: " + std::string(m_err.message));
    }

    void destroy() {
        if (m_created)
            jpeg_destroy_decompress(&m_cinfo);
        m_created = false;
    }

    // OpenImageIO's CMYK to RGB (JPEG stores CMYK inverted, as Adobe writes it): each of R, G, B
    // is (C/255)(K/255) in float, rounded to 8 bits.
    static void cmykToRgb(const unsigned char* cmyk, unsigned char* rgb, int width) {
        for (int x = 0; x < width; ++x, cmyk += 4, rgb += 3) {
            const float k = cmyk[3] / 255.0f;
            for (int c = 0; c < 3; ++c) {
                const float v = (cmyk[c] / 255.0f) * k * 255.0f + 0.5f;
                rgb[c] = static_cast<unsigned char>(std::clamp(v, 0.0f, 255.0f));
            }
        }
    }

    void describe() {
        m_info = ImageInfo();
        m_info.width = static_cast<int>(m_cinfo.output_width);
        m_info.height = static_cast<int>(m_cinfo.output_height);
        m_info.channels = m_cmyk ? 3 : m_cinfo.output_components;
        m_info.format = "jpeg";
        m_info.type = PixelType::UInt8;
        m_info.bitDepth = 8;
        m_info.bitsPerSample = 8;
        m_info.channelNames = m_info.channels == 1 ? std::vector<std::string>{"Y"}
                                                   : std::vector<std::string>{"R", "G", "B"};
        m_info.colorSpace = "sRGB"; // as OpenImageIO says of every JPEG
        m_info.chromaSubsampling = subsamplingOf(m_cinfo);
        // A progressive (or multi-scan) file is decoded whole before its first row: its
        // coefficients, two bytes each, padded to whole blocks.
        if (jpeg_has_multiple_scans(&m_cinfo)) {
            std::uint64_t coefficients = 0;
            for (int i = 0; i < m_cinfo.num_components; ++i) {
                const jpeg_component_info& k = m_cinfo.comp_info[i];
                coefficients += static_cast<std::uint64_t>(k.width_in_blocks + 2) *
                                (k.height_in_blocks + 2) * DCTSIZE2;
            }
            m_info.decoderBytes = coefficients * sizeof(JCOEF);
        }
        auto meta = std::make_shared<ImageMetadata>();
        meta->format = "jpeg";
        meta->srgb = true; // as OpenImageIO said of every JPEG (ImageMetadata::srgb)
        meta->jpegSubsampling = m_info.chromaSubsampling;
        std::vector<std::pair<int, std::string>> iccChunks;
        for (jpeg_saved_marker_ptr m = m_cinfo.marker_list; m; m = m->next) {
            const char* d = reinterpret_cast<const char*>(m->data);
            if (m->marker == JPEG_APP0 + 1 && startsWith(m, "Exif\0\0", 6) && meta->exif.empty())
                meta->exif.assign(d + 6, m->data_length - 6);
            else if (m->marker == JPEG_APP0 + 1 &&
                     startsWith(m, "http://ns.adobe.com/xap/1.0/\0", 29) && meta->xmp.empty())
                meta->xmp.assign(d + 29, m->data_length - 29);
            else if (m->marker == JPEG_APP0 + 2 && startsWith(m, "ICC_PROFILE\0", 12) &&
                     m->data_length > 14)
                iccChunks.emplace_back(m->data[12], std::string(d + 14, m->data_length - 14));
            else if (m->marker == JPEG_APP0 + 13 && startsWith(m, "Photoshop 3.0\0", 14) &&
                     meta->iptc.empty()) {
                meta->iptc.assign(d + 14, m->data_length - 14);
                meta->iptcBeforeXmp = meta->xmp.empty();
            } else if (m->marker == JPEG_COM && m->data_length > 0) {
                std::string text(d, m->data_length);
                text.erase(std::find(text.begin(), text.end(), '\0'), text.end());
                if (!text.empty())
                    meta->text.emplace_back("ImageDescription", text);
            }
        }
        // The ICC profile's chunks joined in their sequence numbers' order.
        std::stable_sort(iccChunks.begin(), iccChunks.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& c : iccChunks)
            meta->icc += c.second;
        if (m_cinfo.saw_JFIF_marker && m_cinfo.density_unit != 0 && m_cinfo.X_density > 0 &&
            m_cinfo.Y_density > 0) {
            meta->xResolution = m_cinfo.X_density;
            meta->yResolution = m_cinfo.Y_density;
            meta->resolutionUnit = m_cinfo.density_unit == 1 ? "in" : "cm";
        }
        m_metadata = std::move(meta);
    }

    std::string m_path;
    ByteReader m_reader;
    jpeg_decompress_struct m_cinfo;
    ErrorManager m_err;
    Source m_src;
    bool m_created = false;
    bool m_started = false;
    bool m_cmyk = false;
    std::vector<unsigned char> m_row;
    int m_rowsRead = 0;
};

} // namespace

std::unique_ptr<ImageSource> openJpegSource(const std::string& path, std::string memory) {
    return std::make_unique<JpegSource>(path, std::move(memory));
}

} // namespace lut::formats
