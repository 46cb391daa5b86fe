// SPDX-License-Identifier: Apache-2.0
// OpenEXR scanline files, natively, with the OpenEXR library: single-part, flat, every channel
// half or every channel float (tiled, multi-part, deep and mixed-type files go through
// OpenImageIO). Rows are read and written straight between the file and an interleaved buffer of
// the file's own type; channels are presented R, G, B, A first, then the others by name. Writing
// an EXR from an EXR copies the whole header (every attribute, the windows, the line order), with
// the channels' type and the compression as asked.
#include "imageio/ByteIO.h"
#include "imageio/ImageCodec.h"

#include "lut/Error.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfCompressionAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVersion.h>

#include <algorithm>
#include <cstring>
#include <thread>

namespace lut::formats {

namespace {

// Thrown (and caught by openImageSource) when a file is not one the native reader takes.
struct NotNative {};

class ReaderStream : public Imf::IStream {
public:
    explicit ReaderStream(ByteReader& in) : Imf::IStream(in.path().c_str()), m_in(in) {}
    bool read(char c[], int n) override {
        if (m_in.read(c, static_cast<std::size_t>(n)) != static_cast<std::size_t>(n))
            throw Iex::InputExc("the file ends early (truncated)");
        return m_in.tell() < m_in.size();
    }
    uint64_t tellg() override { return m_in.tell(); }
    void seekg(uint64_t pos) override { m_in.seek(pos); }
    void clear() override {}

private:
    ByteReader& m_in;
};

class WriterStream : public Imf::OStream {
public:
    explicit WriterStream(ByteWriter& out) : Imf::OStream(out.path().c_str()), m_out(out) {}
    void write(const char c[], int n) override {
        m_out.pwrite(c, static_cast<std::size_t>(n), m_pos);
        m_pos += static_cast<std::uint64_t>(n);
    }
    uint64_t tellp() override { return m_pos; }
    void seekp(uint64_t pos) override { m_pos = pos; }

private:
    ByteWriter& m_out;
    std::uint64_t m_pos = 0;
};

const char* compressionName(Imf::Compression c) {
    switch (c) {
    case Imf::NO_COMPRESSION:
        return "none";
    case Imf::RLE_COMPRESSION:
        return "rle";
    case Imf::ZIPS_COMPRESSION:
        return "zips";
    case Imf::ZIP_COMPRESSION:
        return "zip";
    case Imf::PIZ_COMPRESSION:
        return "piz";
    case Imf::PXR24_COMPRESSION:
        return "pxr24";
    case Imf::B44_COMPRESSION:
        return "b44";
    case Imf::B44A_COMPRESSION:
        return "b44a";
    case Imf::DWAA_COMPRESSION:
        return "dwaa";
    case Imf::DWAB_COMPRESSION:
        return "dwab";
    default:
        return "unknown";
    }
}

bool compressionByName(const std::string& name, Imf::Compression& out) {
    for (int c = 0; c < Imf::NUM_COMPRESSION_METHODS; ++c)
        if (name == compressionName(static_cast<Imf::Compression>(c))) {
            out = static_cast<Imf::Compression>(c);
            return true;
        }
    return false;
}

int threadsFor(Imf::Compression c) {
    return c == Imf::NO_COMPRESSION
               ? 0
               : static_cast<int>(std::max(1u, std::min(4u, std::thread::hardware_concurrency())));
}

// R, G, B, A first (those present), then the others by name.
std::vector<std::string> channelOrder(const Imf::ChannelList& list) {
    std::vector<std::string> names;
    for (const char* n : {"R", "G", "B", "A"})
        if (list.findChannel(n))
            names.emplace_back(n);
    for (auto it = list.begin(); it != list.end(); ++it)
        if (std::find(names.begin(), names.end(), it.name()) == names.end())
            names.emplace_back(it.name());
    return names;
}

class ExrSource : public ImageSource {
public:
    ExrSource(const std::string& path, std::string memory)
        : m_in(path, std::move(memory)), m_stream(m_in) {
        try {
            m_file = std::make_unique<Imf::InputFile>(m_stream, 0);
        } catch (const std::exception& e) {
            throw Error(path + ": cannot read OpenEXR file: " + firstLine(e.what()));
        }
        const Imf::Header& h = m_file->header();
        // Tiled, deep and multi-part files go through OpenImageIO, which reads every part (this
        // reader would see the first part only).
        if (Imf::isMultiPart(m_file->version()) || h.hasTileDescription() ||
            (h.hasType() && h.type() != Imf::SCANLINEIMAGE))
            throw NotNative{};
        const Imf::ChannelList& list = h.channels();
        Imf::PixelType type = Imf::NUM_PIXELTYPES;
        int count = 0;
        for (auto it = list.begin(); it != list.end(); ++it, ++count) {
            if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
                throw NotNative{};
            if (type == Imf::NUM_PIXELTYPES)
                type = it.channel().type;
            else if (type != it.channel().type)
                throw NotNative{};
        }
        if (count == 0 || (type != Imf::HALF && type != Imf::FLOAT))
            throw NotNative{};
        const Imath::Box2i dw = h.dataWindow();
        const long w = static_cast<long>(dw.max.x) - dw.min.x + 1;
        const long hh = static_cast<long>(dw.max.y) - dw.min.y + 1;
        checkImageSize(path, static_cast<int>(std::min(w, 1L << 30)),
                       static_cast<int>(std::min(hh, 1L << 30)), count);
        m_info.width = static_cast<int>(w);
        m_info.height = static_cast<int>(hh);
        m_info.channels = count;
        m_info.format = "openexr";
        m_info.type = type == Imf::HALF ? PixelType::Half : PixelType::Float;
        m_info.bitDepth = 32;
        m_info.isFloat = true;
        m_info.bitsPerSample = type == Imf::HALF ? 16 : 32;
        m_info.compression = compressionName(h.compression());
        m_info.channelNames = channelOrder(list);
        for (std::size_t i = 0; i < m_info.channelNames.size(); ++i)
            if (m_info.channelNames[i] == "A")
                m_info.alphaChannel = static_cast<int>(i);
        m_pixelType = type;
        m_xMin = dw.min.x;
        m_yMin = dw.min.y;
        auto meta = std::make_shared<ImageMetadata>();
        meta->format = "openexr";
        meta->exrHeader = std::make_shared<Imf::Header>(h);
        // The header's description, for readers that look for text (a LUT image's
        // LUTKIT_PURPOSE tag); written back from exrHeader, not from here.
        if (Imf::hasComments(h))
            meta->text.emplace_back("ImageDescription", Imf::commentsAttribute(h).value());
        m_metadata = meta;
        m_granularity = std::max(1, static_cast<int>(linesPerBlock(h.compression())));
        if (const int t = threadsFor(h.compression()); t > 0) {
            // Reopened with decoding threads for compressed data (h dies with the first file).
            m_file.reset();
            m_in.seek(0);
            m_file = std::make_unique<Imf::InputFile>(m_stream, t);
        }
    }

    int rowGranularity() const override { return m_granularity; }

    void readRows(int y0, int y1, void* dst) override {
        const std::size_t bps = static_cast<std::size_t>(bytesPerSample(m_info.type));
        const std::size_t xs = bps * static_cast<std::size_t>(m_info.channels);
        const std::size_t ys = xs * static_cast<std::size_t>(m_info.width);
        char* base = static_cast<char*>(dst) - static_cast<std::ptrdiff_t>(xs) * m_xMin -
                     static_cast<std::ptrdiff_t>(ys) * (static_cast<long>(m_yMin) + y0);
        Imf::FrameBuffer fb;
        for (std::size_t c = 0; c < m_info.channelNames.size(); ++c)
            fb.insert(m_info.channelNames[c], Imf::Slice(m_pixelType, base + c * bps, xs, ys));
        try {
            m_file->setFrameBuffer(fb);
            m_file->readPixels(m_yMin + y0, m_yMin + y1 - 1);
        } catch (const std::exception& e) {
            throw Error(m_in.path() + ": cannot read OpenEXR pixels: " + firstLine(e.what()));
        }
    }

private:
    static std::string firstLine(std::string s) { return s.substr(0, s.find('\n')); }
    static int linesPerBlock(Imf::Compression c) {
        switch (c) {
        case Imf::ZIP_COMPRESSION:
        case Imf::PXR24_COMPRESSION:
            return 16;
        case Imf::PIZ_COMPRESSION:
        case Imf::B44_COMPRESSION:
        case Imf::B44A_COMPRESSION:
        case Imf::DWAA_COMPRESSION:
            return 32;
        case Imf::DWAB_COMPRESSION:
            return 256;
        default:
            return 1;
        }
    }

    ByteReader m_in;
    ReaderStream m_stream;
    std::unique_ptr<Imf::InputFile> m_file;
    Imf::PixelType m_pixelType = Imf::HALF;
    int m_xMin = 0, m_yMin = 0, m_granularity = 1;
};

// Why a write failed, without the file's name: OpenEXR passes on the stream's own error ("OUT:
// cannot write: REASON") or names the file itself ("Cannot open image file "OUT". REASON"), and
// OutputFile::fail names it again ("OUT: cannot write: OUT: cannot write: No space left on
// device" was printed).
std::string reasonOnly(std::string text, const std::string& path) {
    const std::string own = path + ": cannot write: ";
    if (const auto at = text.find(own); at != std::string::npos)
        return text.substr(at + own.size());
    const std::string quoted = "\"" + path + "\".";
    if (const auto at = text.find(quoted); at != std::string::npos) {
        text.erase(0, at + quoted.size());
        while (!text.empty() && text.front() == ' ')
            text.erase(0, 1);
    }
    return text;
}

class ExrSink : public ImageSink {
public:
    ExrSink(const OutputTarget& target, const SinkSpec& spec)
        : m_out(target, true), m_stream(m_out), m_spec(spec) {
        if (spec.type != PixelType::Half && spec.type != PixelType::Float)
            throw Error(target.path + ": this OpenEXR writer stores half or float, not " +
                        std::string(toString(spec.type)));
        Imf::Header header(spec.width, spec.height);
        if (spec.metadata && spec.metadata->exrHeader) {
            header = *static_cast<const Imf::Header*>(spec.metadata->exrHeader.get());
            const Imath::Box2i dw = header.dataWindow();
            if (dw.max.x - dw.min.x + 1 != spec.width || dw.max.y - dw.min.y + 1 != spec.height) {
                header.dataWindow() = Imath::Box2i({0, 0}, {spec.width - 1, spec.height - 1});
                header.displayWindow() = header.dataWindow();
            }
            header.channels() = Imf::ChannelList();
        } else if (spec.metadata) {
            for (const auto& [key, value] : spec.metadata->text)
                if (key == "ImageDescription" || key == "Comment" || key == "Description")
                    Imf::addComments(header, value);
        }
        m_type = spec.type == PixelType::Half ? Imf::HALF : Imf::FLOAT;
        for (const auto& n : spec.channelNames)
            header.channels().insert(n, Imf::Channel(m_type));
        if (!spec.compression.empty()) {
            const std::string base = spec.compression.substr(0, spec.compression.find(':'));
            Imf::Compression c;
            if (!compressionByName(base, c))
                throw Error(target.path + ": OpenEXR has no compression '" + spec.compression +
                            "' (none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab)");
            header.compression() = c;
            if (const auto colon = spec.compression.find(':'); colon != std::string::npos)
                header.dwaCompressionLevel() = std::stof(spec.compression.substr(colon + 1));
        } else if (!(spec.metadata && spec.metadata->exrHeader)) {
            header.compression() = Imf::ZIP_COMPRESSION; // OpenImageIO's default
        }
        header.lineOrder() = Imf::INCREASING_Y;
        m_xMin = header.dataWindow().min.x;
        m_yMin = header.dataWindow().min.y;
        try {
            m_file = std::make_unique<Imf::OutputFile>(m_stream, header,
                                                       threadsFor(header.compression()));
        } catch (const std::exception& e) {
            m_out.fail(reasonOnly(e.what(), m_out.path()));
        }
    }

    void writeRows(int y0, int y1, const void* src) override {
        const std::size_t bps = static_cast<std::size_t>(bytesPerSample(m_spec.type));
        const std::size_t nch = m_spec.channelNames.size();
        const std::size_t xs = bps * nch, ys = xs * static_cast<std::size_t>(m_spec.width);
        const char* base = static_cast<const char*>(src) -
                           static_cast<std::ptrdiff_t>(xs) * m_xMin -
                           static_cast<std::ptrdiff_t>(ys) * (static_cast<long>(m_yMin) + y0);
        Imf::FrameBuffer fb;
        for (std::size_t c = 0; c < nch; ++c)
            fb.insert(m_spec.channelNames[c],
                      Imf::Slice(m_type, const_cast<char*>(base) + c * bps, xs, ys));
        try {
            m_file->setFrameBuffer(fb);
            m_file->writePixels(y1 - y0);
        } catch (const std::exception& e) {
            m_out.fail(reasonOnly(e.what(), m_out.path()));
        }
    }

    void finish() override {
        try {
            m_file.reset(); // writes the line offset table
        } catch (const std::exception& e) {
            m_out.fail(reasonOnly(e.what(), m_out.path()));
        }
        m_out.commit();
    }

private:
    ByteWriter m_out;
    WriterStream m_stream;
    SinkSpec m_spec;
    Imf::PixelType m_type = Imf::HALF;
    std::unique_ptr<Imf::OutputFile> m_file;
    int m_xMin = 0, m_yMin = 0;
};

} // namespace

std::unique_ptr<ImageSource> openExrSource(const std::string& path, std::string memory) {
    try {
        return std::make_unique<ExrSource>(path, std::move(memory));
    } catch (const NotNative&) {
        return nullptr;
    }
}

std::unique_ptr<ImageSink> createExrSink(const OutputTarget& target, const SinkSpec& spec) {
    if (spec.tileWidth > 0 || (spec.type != PixelType::Half && spec.type != PixelType::Float))
        return nullptr;
    return std::make_unique<ExrSink>(target, spec);
}

} // namespace lut::formats
