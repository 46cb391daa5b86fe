// SPDX-License-Identifier: Apache-2.0
// Inside lutkit_imageio.so: OpenImageIO sources and sinks for every format the native codecs do
// not take (TIFF, JPEG, DPX, HDR, WebP, tiled or multi-part EXR ...; BMP and TGA are only written
// here, BmpCodec.cpp and TgaCodec.cpp read them). No colour
// conversion is ever applied: stored values in, stored values out. Metadata: OpenImageIO's
// attributes (EXIF and TIFF tags, the ICC profile, IPTC, XMP, format-specific ones) are kept as
// exact bytes and given back to the writer.
#include "imageio/OiioImage.h"
#include "imageio/OiioMetadata.h"

#include "lut/Limits.h"
#include "lut/io/TempFiles.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace lut::formats::module {

namespace OIIO = OIIO_NAMESPACE;

namespace {

std::string oneLine(std::string s) {
    s = s.substr(0, s.find('\n')); // OIIO stacks libpng's and libjpeg's own lines: one is ours
    while (!s.empty() && (s.back() == ' ' || s.back() == '\r'))
        s.pop_back();
    return s;
}

// A writer's error, never empty (OpenImageIO's IFF writer fails without a message).
std::string writerError(const std::string& s) {
    const std::string line = oneLine(s);
    return line.empty() ? "OpenImageIO's writer failed without saying why" : line;
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

namespace {

// A private file holding `bytes` (mode 0600, in the temporary folder), registered for removal on
// an interrupt; its path.
std::string scratchFile(const std::string& bytes, const std::string& suffix,
                        TempPathRegistration& registration) {
    std::string path =
        (std::filesystem::temp_directory_path() / ("lutkit-stdin-XXXXXX" + suffix)).string();
    const int fd = ::mkstemps(path.data(), static_cast<int>(suffix.size()));
    if (fd < 0)
        throw Error("cannot create a temporary file in " +
                    std::filesystem::temp_directory_path().string() + ": " + std::strerror(errno));
    registration = TempPathRegistration(path);
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            const std::string why = std::strerror(errno);
            ::close(fd);
            ::unlink(path.c_str());
            registration.release();
            throw Error(path + ": cannot write: " + why);
        }
        done += static_cast<std::size_t>(n);
    }
    ::close(fd);
    return path;
}

} // namespace

OiioSource::OiioSource(const SourceOpen& req) : m_path(req.path) {
    try {
        open(req);
        listParts();
        // OpenImageIO 2.4's WebP reader loses its frame iterator when asked for the frame after
        // the last one (how listParts finds the end): every later read then failed with
        // "Couldn't decode subimage 0", even for files oiiotool itself wrote. The reader starts
        // afresh instead.
        if (std::strcmp(m_in->format_name(), "webp") == 0)
            open(req);
    } catch (...) {
        removeScratch(); // no destructor runs for a constructor that throws
        throw;
    }
}

void OiioSource::removeScratch() noexcept {
    m_in.reset();
    if (!m_scratch.empty()) {
        ::unlink(m_scratch.c_str());
        m_scratchRegistration.release();
        m_scratch.clear();
    }
}

void OiioSource::open(const SourceOpen& req) {
    m_in.reset();
    OIIO::ImageSpec config;
    // Keep colour values as stored: by default OIIO premultiplies PNG/TIFF colour by an
    // unassociated alpha, which would scale every pixel whose alpha is not 1.
    config.attribute("oiio:UnassociatedAlpha", 1);
    std::string name = req.memory && !req.format.empty() ? "stdin." + req.format : req.path;
    if (req.memory) {
        // Only the readers checked to read through an IOProxy get one (each read from standard
        // input in tests/formats/test_oiio_formats_read.cpp); any other gets the bytes in a
        // private temporary file, removed with this source (and on an interrupt: it is
        // registered). OpenImageIO 2.4's GIF, SGI, FITS and HEIF readers say they take a proxy
        // but open the file by name ("Could not open file stdin.gif").
        static const std::string kProxyReaders[] = {"tiff", "jpeg", "openexr", "png", "dpx", "webp",
                                                    "iff",  "bmp",  "targa",   "hdr", "psd", "pnm"};
        if (!req.format.empty() && std::find(std::begin(kProxyReaders), std::end(kProxyReaders),
                                             req.format) == std::end(kProxyReaders)) {
            if (m_scratch.empty())
                m_scratch = scratchFile(*req.memory, "." + req.format, m_scratchRegistration);
            name = m_scratch;
        } else {
            m_memory = std::make_unique<OIIO::Filesystem::IOMemReader>(req.memory->data(),
                                                                       req.memory->size());
            void* proxy = m_memory.get();
            config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        }
    }
    // OpenImageIO's open() tries every other reader when the one the name picks cannot open the
    // file, and some of those abort the process on bytes meant for another format (2.4's RLA
    // reader asserts on a damaged PSD: found by fuzz_image_oiio, `lutkit apply` died with
    // SIGABRT). So the reader the name picks opens the file alone; only a name that no reader
    // claims is left to that probing. The reader is created from the extension alone: created
    // from the file's name, OpenImageIO 2.4 asks that reader's valid_file() and probes the
    // others already there.
    const std::string ext = OIIO::Filesystem::extension(name, false);
    auto byName = ext.empty() ? nullptr : OIIO::ImageInput::create(ext, false, &config);
    if (byName) {
        OIIO::ImageSpec opened;
        if (!byName->open(name, opened, config)) {
            std::string err = withoutScratch(oneLine(byName->geterror()));
            (void)OIIO::geterror();
            throw Error(req.path + ": cannot read image: " +
                        (err.empty() ? "not an image OpenImageIO can read" : err));
        }
        m_in = std::move(byName);
        return;
    }
    (void)OIIO::geterror();
    m_in = OIIO::ImageInput::open(name, &config);
    if (!m_in) {
        std::string err = withoutScratch(oneLine(OIIO::geterror()));
        throw Error(req.path + ": cannot read image: " +
                    (err.empty() ? "not an image OpenImageIO can read" : err));
    }
}

// OpenImageIO's messages name the file it opened: the caller's name stands for the bytes.
std::string OiioSource::withoutScratch(std::string text) const {
    for (std::size_t at; !m_scratch.empty() && (at = text.find(m_scratch)) != std::string::npos;)
        text.replace(at, m_scratch.size(), m_path);
    return text;
}

OiioSource::~OiioSource() {
    removeScratch();
}

// Every image the file holds: subimage by subimage, each one's MIP levels. A PSD's subimages
// after the first are its layers, which the first (the merged image) already shows.
void OiioSource::listParts() {
    constexpr std::size_t kMaxParts = 1024;
    const bool layers = std::strcmp(m_in->format_name(), "psd") == 0;
    for (int s = 0;; ++s) {
        if (s > 0 && (layers || !m_in->seek_subimage(s, 0)))
            break;
        for (int m = 0;; ++m) {
            if (m > 0 && !m_in->seek_subimage(s, m))
                break;
            if (m_parts.size() == kMaxParts)
                throw LimitError(m_path + ": holds more than " + std::to_string(kMaxParts) +
                                 " images (subimages and MIP levels), over the limit");
            m_parts.push_back({s, m});
        }
        m_subimages = s + 1;
    }
    (void)m_in->geterror(); // seeking one past the last is how the end was found
}

void OiioSource::fail(const std::string& what, bool ok) {
    std::string err = withoutScratch(oneLine(m_in->geterror()));
    if (err.empty())
        err = ok ? "the codec reported an error" : "truncated or corrupt";
    throw Error(m_path + ": " + what + ": " + err);
}

void OiioSource::select(int index, ImageInfo& info, ImageMetadata& meta, int& granularity) {
    m_current = m_parts.at(static_cast<std::size_t>(index));
    if (!m_in->seek_subimage(m_current.subimage, m_current.mipLevel) || m_in->has_error())
        fail("cannot read image " + std::to_string(index + 1) + " of " +
                 std::to_string(m_parts.size()),
             false);
    m_spec = m_in->spec();
    const OIIO::ImageSpec& s = m_spec;
    if (s.deep)
        throw Error(m_path + ": holds deep data (several samples per pixel), which lutkit does "
                             "not grade (flatten it first: oiiotool --flatten)");
    if (s.depth > 1 || s.tile_depth > 1)
        throw Error(m_path + ": is a volume (" + std::to_string(s.depth) +
                    " slices), not an image");
    if (s.tile_width > 0) {
        // A row of tiles is what one read covers: its size is bounded like an image's.
        const std::uint64_t tile = static_cast<std::uint64_t>(s.tile_width) *
                                   static_cast<std::uint64_t>(std::max(1, s.tile_height));
        if (s.tile_width < 1 || s.tile_height < 1 || tile > (std::uint64_t(1) << 24))
            throw LimitError(m_path + ": tiles of " + std::to_string(s.tile_width) + "x" +
                             std::to_string(s.tile_height) +
                             " pixels, over the limit of 16777216 pixels per tile");
    }
    info = ImageInfo();
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
    // An alpha index past the stored channels (OpenImageIO's GIF reader said 4 of 4 for a fuzzed
    // file) is taken by name instead, or as no alpha.
    info.alphaChannel = s.alpha_channel;
    if (info.alphaChannel >= s.nchannels) {
        const auto a = std::find(s.channelnames.begin(), s.channelnames.end(), "A");
        const auto at = static_cast<int>(a - s.channelnames.begin());
        info.alphaChannel = a != s.channelnames.end() && at < s.nchannels ? at : -1;
    }
    info.colorSpace = s.get_string_attribute("oiio:ColorSpace");
    info.chromaSubsampling = s.get_string_attribute("jpeg:subsampling");
    info.tileWidth = s.tile_width;
    info.tileHeight = s.tile_width > 0 ? s.tile_height : 0;
    info.subimages = m_subimages;
    info.subimage = m_current.subimage;
    info.mipLevel = m_current.mipLevel;
    info.mipLevels = 0;
    for (const Part& p : m_parts)
        info.mipLevels += p.subimage == m_current.subimage ? 1 : 0;
    granularity = s.tile_width > 0 ? s.tile_height : 1;
    meta = ImageMetadata();
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
    meta.hasWindows = true;
    meta.x = s.x;
    meta.y = s.y;
    meta.fullX = s.full_x;
    meta.fullY = s.full_y;
    meta.fullWidth = s.full_width;
    meta.fullHeight = s.full_height;
}

void OiioSource::readRows(int y0, int y1, void* dst) {
    const OIIO::TypeDesc type = typeDescOf(pixelTypeOf(m_spec.format));
    const OIIO::ImageSpec& s = m_spec;
    // Tiled files by rows of tiles: OpenImageIO 2.4's read_scanlines() divides by zero on them
    // (SIGFPE). Chunks are whole tile rows (the granularity), the last one ending at the edge.
    const bool ok =
        s.tile_width > 0
            ? m_in->read_tiles(m_current.subimage, m_current.mipLevel, s.x, s.x + s.width, s.y + y0,
                               s.y + y1, s.z, s.z + 1, 0, s.nchannels, type, dst)
            : m_in->read_scanlines(m_current.subimage, m_current.mipLevel, s.y + y0, s.y + y1, s.z,
                                   0, s.nchannels, type, dst);
    // A read can return true with pixels missing: libtiff's failed strips, libjpeg's "premature
    // end of data" (the rest grey) are recorded as the reader's error, not its result.
    if (!ok || m_in->has_error())
        fail("cannot read image data", ok);
}

OIIO::ImageSpec OiioSink::makeSpec(const SinkSpec& s) const {
    const std::string fmt = m_out->format_name();
    const std::string& name = m_path;
    OIIO::ImageSpec spec(s.width, s.height, static_cast<int>(s.channelNames.size()),
                         typeDescOf(s.type));
    if (s.metadata && !s.metadata->oiioAttributes.empty()) {
        deserialize(s.metadata->oiioAttributes, spec);
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
        // What lutkit's own JPEG reader keeps (JpegCodec.cpp), as OpenImageIO's would have read it.
        // In the file's order, as OpenImageIO's JPEG reader decodes them (the second adds to
        // the first's repeatable fields).
        const auto& m = *s.metadata;
        if (!m.iptc.empty() && m.iptcBeforeXmp)
            decodePhotoshopIptc(m.iptc, spec);
        if (!m.xmp.empty())
            OIIO::decode_xmp(m.xmp, spec);
        if (!m.iptc.empty() && !m.iptcBeforeXmp)
            decodePhotoshopIptc(m.iptc, spec);
        if (!s.metadata->jpegSubsampling.empty())
            spec.attribute("jpeg:subsampling", s.metadata->jpegSubsampling);
        if (s.metadata->xResolution > 0 && s.metadata->yResolution > 0) {
            spec.attribute("XResolution", static_cast<float>(s.metadata->xResolution));
            spec.attribute("YResolution", static_cast<float>(s.metadata->yResolution));
            spec.attribute("ResolutionUnit", s.metadata->resolutionUnit);
        }
    }
    // OpenImageIO reads IPTC's Creator, Caption and CopyrightNotice into both the IPTC name and
    // its synonym, and writes both into the IPTC block: keep one, or they double.
    for (const auto& [iptc, synonym] :
         {std::pair<const char*, const char*>{"IPTC:Creator", "Artist"},
          {"IPTC:Caption", "ImageDescription"},
          {"IPTC:CopyrightNotice", "Copyright"}})
        if (spec.get_string_attribute(iptc) == spec.get_string_attribute(synonym))
            spec.erase_attribute(iptc);
    spec.erase_attribute("oiio:subimages");
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
    // The data window's place and the display window, where the file had them and the output is
    // of the same format (an OpenEXR's overscan, a TIFF's position).
    if (sameFormat && s.metadata->hasWindows && s.metadata->fullWidth > 0 &&
        s.metadata->fullHeight > 0) {
        spec.x = s.metadata->x;
        spec.y = s.metadata->y;
        spec.full_x = s.metadata->fullX;
        spec.full_y = s.metadata->fullY;
        spec.full_width = s.metadata->fullWidth;
        spec.full_height = s.metadata->fullHeight;
    }
    if (s.tileWidth > 0 && m_out->supports("tiles")) {
        spec.tile_width = s.tileWidth;
        spec.tile_height = s.tileHeight;
        spec.tile_depth = 1;
    }
    if (s.type == PixelType::Float && !m_out->supports("floatpixels") && fmt == "png")
        throw Error(name + ": PNG stores 8 or 16 bits per channel, not float (use .exr or .tif)");
    if (s.type != PixelType::UInt8 && fmt == "jpeg")
        throw Error(name + ": JPEG stores 8 bits per channel only");
    return spec;
}

OiioSink::OiioSink(const SinkSpec* specs, int count, const std::string& name, ByteCallbacks bytes)
    : m_path(name), m_parts(specs, specs + count) {
    // Without a pwrite callback the writer writes the file `name` itself (the caller's temporary
    // file), picked by the format's name.
    const bool byName = bytes.pwrite == nullptr;
    m_out = OIIO::ImageOutput::create(
        byName && !m_parts.front().format.empty() ? m_parts.front().format : name);
    if (!m_out)
        throw Error(name + ": no image writer for this extension");
    const std::string fmt = m_out->format_name();
    std::vector<OIIO::ImageSpec> subimages;
    bool mips = false;
    for (const SinkSpec& s : m_parts) {
        m_specs.push_back(makeSpec(s));
        if (s.mipLevel == 0)
            subimages.push_back(m_specs.back());
        mips = mips || s.mipLevel > 0;
    }
    if (subimages.size() > 1 && !m_out->supports("multiimage"))
        throw Error(name + ": the " + fmt + " writer holds one image, not " +
                    std::to_string(subimages.size()));
    if (mips && !m_out->supports("mipmap"))
        throw Error(name + ": the " + fmt + " writer holds no MIP levels");
    if (!byName) {
        m_proxy = std::make_unique<CallbackProxy>(name, bytes);
        if (!m_out->supports("ioproxy"))
            throw Error(name + ": the " + fmt +
                        " writer cannot write through lutkit's checked output");
        m_out->set_ioproxy(m_proxy.get());
    }
    const bool ok = subimages.size() > 1
                        ? m_out->open(name, static_cast<int>(subimages.size()), subimages.data())
                        : m_out->open(name, m_specs.front());
    if (!ok)
        throw Error(name + ": cannot write: " + writerError(m_out->geterror()));
}

OiioSink::~OiioSink() = default;

bool OiioSink::proxyFailed() const {
    return m_proxy && !m_proxy->failure().empty();
}

int OiioSink::granularity() const {
    const OIIO::ImageSpec& spec = m_specs[m_index];
    return spec.tile_width > 0 ? spec.tile_height : 1;
}

void OiioSink::nextPart() {
    if (m_index + 1 >= m_specs.size())
        throw Error(m_path + ": cannot write: no part left to start");
    ++m_index;
    const auto mode = m_parts[m_index].mipLevel > 0 ? OIIO::ImageOutput::AppendMIPLevel
                                                    : OIIO::ImageOutput::AppendSubimage;
    if (!m_out->open(m_path, m_specs[m_index], mode) || proxyFailed())
        throw Error(m_path + ": cannot write: " +
                    (proxyFailed() ? m_proxy->failure() : writerError(m_out->geterror())));
}

void OiioSink::writeRows(int y0, int y1, const void* src) {
    const SinkSpec& part = m_parts[m_index];
    const OIIO::ImageSpec& spec = m_specs[m_index];
    const OIIO::TypeDesc type = typeDescOf(part.type);
    const bool ok = spec.tile_width > 0
                        ? m_out->write_tiles(spec.x, spec.x + spec.width, spec.y + y0, spec.y + y1,
                                             0, 1, type, src)
                        : m_out->write_scanlines(spec.y + y0, spec.y + y1, 0, type, src);
    if (!ok || proxyFailed())
        throw Error(m_path + ": cannot write: " +
                    (proxyFailed() ? m_proxy->failure() : writerError(m_out->geterror())));
}

void OiioSink::finish() {
    if (m_index + 1 != m_specs.size())
        throw Error(m_path + ": cannot write: " + std::to_string(m_specs.size() - m_index - 1) +
                    " parts were not written");
    const bool ok = m_out->close();
    const std::string error = ok ? std::string() : writerError(m_out->geterror());
    // A writer that opened the file itself (by name) keeps it open, its last bytes buffered,
    // until it is destroyed: before the caller checks and renames the file.
    m_out.reset();
    if (proxyFailed())
        throw Error(m_path + ": cannot write: " + m_proxy->failure());
    if (!ok)
        throw Error(m_path + ": cannot write: " + error);
}

} // namespace lut::formats::module
