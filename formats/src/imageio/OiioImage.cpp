// Inside lutkit_imageio.so: OpenImageIO sources and sinks for every format the native codecs do
// not take (TIFF, JPEG, DPX, BMP, TGA, HDR, WebP, tiled or multi-part EXR ...). No colour
// conversion is ever applied: stored values in, stored values out. Metadata: OpenImageIO's
// attributes (EXIF and TIFF tags, the ICC profile, IPTC, XMP, format-specific ones) are kept as
// exact bytes and given back to the writer.
#include "imageio/OiioImage.h"

#include "lut/Limits.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

// From OpenImageIO/tiffutils.h, which needs libtiff's headers for the rest of what it declares.
OIIO_NAMESPACE_BEGIN
OIIO_API bool decode_exif(string_view exif, ImageSpec& spec);
OIIO_API void encode_exif(const ImageSpec& spec, std::vector<char>& blob);
OIIO_NAMESPACE_END

#include <cstring>

namespace lut::formats::module {

namespace OIIO = OIIO_NAMESPACE;

namespace {

std::string oneLine(std::string s) {
    s = s.substr(0, s.find('\n')); // OIIO stacks libpng's and libjpeg's own lines: one is ours
    while (!s.empty() && (s.back() == ' ' || s.back() == '\r'))
        s.pop_back();
    return s;
}

PixelType pixelTypeOf(OIIO::TypeDesc t) {
    switch (t.basetype) {
    case OIIO::TypeDesc::UINT8:
        return PixelType::UInt8;
    case OIIO::TypeDesc::UINT16:
        return PixelType::UInt16;
    case OIIO::TypeDesc::HALF:
        return PixelType::Half;
    default:
        return PixelType::Float; // 32-bit integers, double ...: read as float
    }
}

OIIO::TypeDesc typeDescOf(PixelType t) {
    switch (t) {
    case PixelType::UInt8:
        return OIIO::TypeDesc::UINT8;
    case PixelType::UInt16:
        return OIIO::TypeDesc::UINT16;
    case PixelType::Half:
        return OIIO::TypeDesc::HALF;
    case PixelType::Float:
        return OIIO::TypeDesc::FLOAT;
    }
    return OIIO::TypeDesc::FLOAT;
}

// ParamValueList <-> bytes: name, type, count, then the values (strings as length + bytes).
void putInt(std::string& s, std::uint32_t v) {
    s.append(reinterpret_cast<const char*>(&v), 4);
}
std::uint32_t getInt(const std::string& s, std::size_t& at) {
    std::uint32_t v = 0;
    if (at + 4 <= s.size())
        std::memcpy(&v, s.data() + at, 4);
    at += 4;
    return v;
}
void putBytes(std::string& s, const void* p, std::size_t n) {
    putInt(s, static_cast<std::uint32_t>(n));
    s.append(static_cast<const char*>(p), n);
}
std::string getBytes(const std::string& s, std::size_t& at) {
    const std::uint32_t n = getInt(s, at);
    if (at + n > s.size())
        return {};
    std::string v = s.substr(at, n);
    at += n;
    return v;
}

std::string serialize(const OIIO::ParamValueList& list) {
    std::string s;
    for (const auto& p : list) {
        const OIIO::TypeDesc t = p.type();
        putBytes(s, p.name().c_str(), p.name().size());
        putInt(s, t.basetype);
        putInt(s, t.aggregate);
        putInt(s, t.vecsemantics);
        putInt(s, static_cast<std::uint32_t>(t.arraylen));
        putInt(s, static_cast<std::uint32_t>(p.nvalues()));
        if (t.basetype == OIIO::TypeDesc::STRING) {
            const auto* strs = static_cast<const OIIO::ustring*>(p.data());
            for (int i = 0; i < p.nvalues() * static_cast<int>(t.numelements()); ++i)
                putBytes(s, strs[i].c_str(), strs[i].size());
        } else {
            putBytes(s, p.data(), t.size() * static_cast<std::size_t>(p.nvalues()));
        }
    }
    return s;
}

void deserialize(const std::string& s, OIIO::ImageSpec& spec) {
    std::size_t at = 0;
    while (at < s.size()) {
        const std::string name = getBytes(s, at);
        OIIO::TypeDesc t;
        t.basetype = static_cast<unsigned char>(getInt(s, at));
        t.aggregate = static_cast<unsigned char>(getInt(s, at));
        t.vecsemantics = static_cast<unsigned char>(getInt(s, at));
        t.arraylen = static_cast<int>(getInt(s, at));
        const int n = static_cast<int>(getInt(s, at));
        if (at > s.size() || name.empty())
            return;
        if (t.basetype == OIIO::TypeDesc::STRING) {
            std::vector<std::string> vals;
            const int count = n * static_cast<int>(t.numelements());
            for (int i = 0; i < count && at < s.size(); ++i)
                vals.push_back(getBytes(s, at));
            std::vector<const char*> ptrs;
            for (const auto& v : vals)
                ptrs.push_back(v.c_str());
            if (static_cast<int>(ptrs.size()) == count)
                spec.extra_attribs.emplace_back(name, t, n, ptrs.data());
        } else {
            const std::string bytes = getBytes(s, at);
            if (bytes.size() == t.size() * static_cast<std::size_t>(n))
                spec.extra_attribs.emplace_back(name, t, n, bytes.data());
        }
    }
}

} // namespace

// Writes through the caller's callbacks; a failed write is recorded and reported at close, and
// the codec is told the bytes went out, so no codec can answer it with exit() (libjpeg would).
class CallbackProxy : public OIIO::Filesystem::IOProxy {
public:
    CallbackProxy(const std::string& name, ByteCallbacks cb)
        : IOProxy(name, IOProxy::Write), m_cb(cb) {}
    const char* proxytype() const override { return "lutkit"; }
    size_t write(const void* buf, size_t size) override {
        pwrite(buf, size, m_pos);
        m_pos += static_cast<int64_t>(size);
        return size;
    }
    size_t pwrite(const void* buf, size_t size, int64_t offset) override {
        if (m_failed.empty() && size > 0 &&
            !m_cb.pwrite(m_cb.context, buf, size, static_cast<std::uint64_t>(offset), m_failed) &&
            m_failed.empty())
            m_failed = "write failed";
        m_end = std::max<int64_t>(m_end, offset + static_cast<int64_t>(size));
        return size;
    }
    size_t size() const override { return static_cast<size_t>(m_end); }
    const std::string& failure() const { return m_failed; }

private:
    ByteCallbacks m_cb;
    std::string m_failed;
    int64_t m_end = 0;
};

OiioSource::OiioSource(const SourceOpen& req) : m_path(req.path) {
    OIIO::ImageSpec config;
    // Keep colour values as stored: by default OIIO premultiplies PNG/TIFF colour by an
    // unassociated alpha, which would scale every pixel whose alpha is not 1.
    config.attribute("oiio:UnassociatedAlpha", 1);
    if (req.memory) {
        m_memory =
            std::make_unique<OIIO::Filesystem::IOMemReader>(req.memory->data(), req.memory->size());
        void* proxy = m_memory.get();
        config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    }
    const std::string name = req.memory && !req.format.empty() ? "stdin." + req.format : req.path;
    m_in = OIIO::ImageInput::open(name, &config);
    if (!m_in) {
        std::string err = oneLine(OIIO::geterror());
        throw Error(req.path + ": cannot read image: " +
                    (err.empty() ? "not an image OpenImageIO can read" : err));
    }
    m_spec = m_in->spec();
}

OiioSource::~OiioSource() = default;

void OiioSource::describe(ImageInfo& info, ImageMetadata& meta, int& granularity) const {
    const OIIO::ImageSpec& s = m_spec;
    info.width = s.width;
    info.height = s.height;
    info.channels = s.nchannels;
    info.format = m_in->format_name();
    info.type = pixelTypeOf(s.format);
    info.isFloat = info.type == PixelType::Half || info.type == PixelType::Float;
    info.bitDepth = info.isFloat ? 32 : info.type == PixelType::UInt16 ? 16 : 8;
    info.bitsPerSample = s.get_int_attribute("oiio:BitsPerSample", 8 * bytesPerSample(info.type));
    info.compression = s.get_string_attribute("compression");
    info.channelNames.assign(s.channelnames.begin(), s.channelnames.end());
    info.alphaChannel = s.alpha_channel;
    info.colorSpace = s.get_string_attribute("oiio:ColorSpace");
    info.chromaSubsampling = s.get_string_attribute("jpeg:subsampling");
    granularity = s.tile_height > 0 ? s.tile_height : 1;
    meta.format = info.format;
    meta.oiioAttributes = serialize(s.extra_attribs);
    if (const OIIO::ParamValue* icc = s.find_attribute("ICCProfile"))
        meta.icc.assign(static_cast<const char*>(icc->data()), icc->type().size());
    std::vector<char> exif;
    OIIO::encode_exif(s, exif);
    if (exif.size() > 8)
        meta.exif.assign(exif.begin(), exif.end());
    for (const char* key : {"ImageDescription", "Copyright", "Artist", "DateTime", "Software"})
        if (const std::string v = s.get_string_attribute(key); !v.empty())
            meta.text.emplace_back(key, v);
}

void OiioSource::readRows(int y0, int y1, void* dst) {
    const OIIO::TypeDesc type = typeDescOf(pixelTypeOf(m_spec.format));
    if (!m_in->read_scanlines(0, 0, m_spec.y + y0, m_spec.y + y1, 0, 0, m_spec.nchannels, type,
                              dst)) {
        const std::string err = oneLine(m_in->geterror());
        throw Error(m_path +
                    ": cannot read image data: " + (err.empty() ? "truncated or corrupt" : err));
    }
}

OiioSink::OiioSink(const SinkSpec& s, const std::string& name, ByteCallbacks bytes)
    : m_path(name), m_spec(s) {
    m_out = OIIO::ImageOutput::create(name);
    if (!m_out)
        throw Error(name + ": no image writer for this extension");
    const std::string fmt = m_out->format_name();
    OIIO::ImageSpec spec(s.width, s.height, static_cast<int>(s.channelNames.size()),
                         typeDescOf(s.type));
    if (s.metadata && !s.metadata->oiioAttributes.empty()) {
        deserialize(s.metadata->oiioAttributes, spec);
        // OpenImageIO reads IPTC's Creator, Caption and CopyrightNotice into both the IPTC name
        // and its synonym, and writes both into the IPTC block: keep one, or they double.
        for (const auto& [iptc, synonym] :
             {std::pair<const char*, const char*>{"IPTC:Creator", "Artist"},
              {"IPTC:Caption", "ImageDescription"},
              {"IPTC:CopyrightNotice", "Copyright"}})
            if (spec.get_string_attribute(iptc) == spec.get_string_attribute(synonym))
                spec.erase_attribute(iptc);
    } else if (s.metadata) {
        if (!s.metadata->icc.empty())
            spec.attribute(
                "ICCProfile",
                OIIO::TypeDesc(OIIO::TypeDesc::UINT8, static_cast<int>(s.metadata->icc.size())),
                s.metadata->icc.data());
        if (!s.metadata->exif.empty())
            OIIO::decode_exif(OIIO::string_view(s.metadata->exif), spec);
        for (const auto& [k, v] : s.metadata->text)
            spec.attribute(k, v);
    }
    spec.channelnames.assign(s.channelNames.begin(), s.channelNames.end());
    spec.alpha_channel = s.alphaChannel;
    spec.erase_attribute("oiio:BitsPerSample");
    if (s.bitsPerSample > 0 && s.bitsPerSample != 8 * bytesPerSample(s.type))
        spec.attribute("oiio:BitsPerSample", s.bitsPerSample);
    // Our pixels are unassociated (colour not multiplied by alpha): without this OIIO divides
    // colour by alpha when writing PNG/TIFF, changing every pixel whose alpha is below 1.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    const bool sameFormat = s.metadata && s.metadata->format == fmt;
    if (!s.compression.empty())
        spec.attribute("compression", s.compression);
    else if (!sameFormat)
        spec.erase_attribute("compression");
    if (s.tileWidth > 0 && m_out->supports("tiles")) {
        spec.tile_width = s.tileWidth;
        spec.tile_height = s.tileHeight;
        spec.tile_depth = 1;
    }
    if (s.type == PixelType::Float && !m_out->supports("floatpixels") && fmt == "png")
        throw Error(name + ": PNG stores 8 or 16 bits per channel, not float (use .exr or .tif)");
    if (s.type != PixelType::UInt8 && fmt == "jpeg")
        throw Error(name + ": JPEG stores 8 bits per channel only");
    m_tiled = spec.tile_width > 0;
    m_tileHeight = spec.tile_height;
    m_proxy = std::make_unique<CallbackProxy>(name, bytes);
    if (!m_out->supports("ioproxy"))
        throw Error(name + ": the " + fmt + " writer cannot write through lutkit's checked output");
    m_out->set_ioproxy(m_proxy.get());
    if (!m_out->open(name, spec))
        throw Error(name + ": cannot write: " + oneLine(m_out->geterror()));
}

OiioSink::~OiioSink() = default;

void OiioSink::writeRows(int y0, int y1, const void* src) {
    const OIIO::TypeDesc type = typeDescOf(m_spec.type);
    const bool ok = m_tiled ? m_out->write_tiles(0, m_spec.width, y0, y1, 0, 1, type, src)
                            : m_out->write_scanlines(y0, y1, 0, type, src);
    if (!ok || !m_proxy->failure().empty())
        throw Error(
            m_path + ": cannot write: " +
            (!m_proxy->failure().empty() ? m_proxy->failure() : oneLine(m_out->geterror())));
}

void OiioSink::finish() {
    const bool ok = m_out->close();
    if (!m_proxy->failure().empty())
        throw Error(m_path + ": cannot write: " + m_proxy->failure());
    if (!ok)
        throw Error(m_path + ": cannot write: " + oneLine(m_out->geterror()));
}

} // namespace lut::formats::module
