// SPDX-License-Identifier: Apache-2.0
// Inside lutkit_imageio.so: the OpenImageIO sink for every format the native codecs do not write.
// Its bytes go through the caller's checked callbacks (CallbackProxy), except where a writer
// must read back what it wrote: OpenImageIO 2.4's TIFF writer, given Exif tags, writes its
// directory, then the Exif directory, then goes back to the first directory to point at it
// (TIFFSetDirectory), which reads the file; through an IOProxy its read procedure returns
// nothing, so the Exif entries became the file's only directory (issue 41: every TIFF written
// from a JPEG, "missing required ImageLength", exit 0). Such a file is written by name: the
// caller's temporary file (ByteCallbacks::file), or a private scratch file whose bytes are then
// copied through the callbacks (standard output, memory). A file written by name is read back
// before it is accepted.
#include "imageio/OiioSink.h"

#include "imageio/OiioCommon.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

// From OpenImageIO/tiffutils.h, which needs libtiff's headers for the rest of what it declares.
OIIO_NAMESPACE_BEGIN
OIIO_API bool decode_exif(string_view exif, ImageSpec& spec);
OIIO_API bool exif_tag_lookup(string_view name, int& tag, int& tifftype, int& count);
OIIO_NAMESPACE_END

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <limits>
#include <unistd.h>

namespace lut::formats::module {

namespace OIIO = OIIO_NAMESPACE;

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

// Whether OpenImageIO's writer for fmt reads the file back while writing these images: the TIFF
// writer when it writes an Exif directory (tiffoutput.cpp, write_exif_data: any attribute
// OpenImageIO maps to an Exif tag, unless "tiff:write_exif" is 0; it adds Exif:ColorSpace itself
// to an image whose oiio:ColorSpace is sRGB, which every JPEG's is).
bool readsBackWhileWriting(const std::string& fmt, const std::vector<OIIO::ImageSpec>& specs) {
    if (fmt != "tiff")
        return false;
    for (const OIIO::ImageSpec& spec : specs) {
        if (spec.get_int_attribute("tiff:write_exif", 1) == 0)
            continue;
        if (OIIO::Strutil::iequals(spec.get_string_attribute("oiio:ColorSpace"), "sRGB"))
            return true;
        for (const OIIO::ParamValue& p : spec.extra_attribs) {
            int tag = 0, type = 0, count = 0;
            if (OIIO::exif_tag_lookup(p.name(), tag, type, count) && type != 0)
                return true;
        }
    }
    return false;
}

// OpenImageIO's readers give an Exif SHORT or LONG as uint16 or uint32, and its TIFF writer
// writes an integer Exif tag only when it is int16 or int32 (tiffoutput.cpp): a JPEG's Flash,
// WhiteBalance or LightSource vanished from the TIFF written from it (oiiotool loses them too).
// One value of an integer type becomes an int, which the writer takes.
void exifIntegersAsInt(OIIO::ImageSpec& spec) {
    for (OIIO::ParamValue& p : spec.extra_attribs) {
        const OIIO::TypeDesc t = p.type();
        if (p.nvalues() != 1 || t.aggregate != OIIO::TypeDesc::SCALAR || t.arraylen != 0 ||
            !(t.basetype == OIIO::TypeDesc::UINT16 || t.basetype == OIIO::TypeDesc::UINT32 ||
              t.basetype == OIIO::TypeDesc::UINT8))
            continue;
        int tag = 0, type = 0, count = 0;
        if (!OIIO::exif_tag_lookup(p.name(), tag, type, count) || type == 0)
            continue;
        const long long v =
            t.basetype == OIIO::TypeDesc::UINT16   ? *static_cast<const std::uint16_t*>(p.data())
            : t.basetype == OIIO::TypeDesc::UINT32 ? *static_cast<const std::uint32_t*>(p.data())
                                                   : *static_cast<const std::uint8_t*>(p.data());
        if (v <= std::numeric_limits<int>::max()) {
            const int asInt = static_cast<int>(v);
            p = OIIO::ParamValue(p.name(), OIIO::TypeDesc::INT, 1, &asInt);
        }
    }
}

// OpenEXR's parts share one display window (OpenEXR refuses the file otherwise: "Conflicting
// attributes found for header :: subimage01 'displayWindow'"): pages of several sizes (a TIFF's)
// become parts whose data windows keep their sizes inside the window holding them all.
void shareDisplayWindow(std::vector<OIIO::ImageSpec>& specs,
                        std::vector<OIIO::ImageSpec>& subimages) {
    int x0 = subimages.front().full_x, y0 = subimages.front().full_y;
    int x1 = x0 + subimages.front().full_width, y1 = y0 + subimages.front().full_height;
    for (const OIIO::ImageSpec& s : subimages) {
        x0 = std::min({x0, s.full_x, s.x});
        y0 = std::min({y0, s.full_y, s.y});
        x1 = std::max({x1, s.full_x + s.full_width, s.x + s.width});
        y1 = std::max({y1, s.full_y + s.full_height, s.y + s.height});
    }
    for (auto* list : {&specs, &subimages})
        for (OIIO::ImageSpec& s : *list) {
            s.full_x = x0;
            s.full_y = y0;
            s.full_width = x1 - x0;
            s.full_height = y1 - y0;
        }
}

} // namespace

OIIO::ImageSpec OiioSink::makeSpec(const SinkSpec& s) const {
    const std::string fmt = m_out->format_name();
    const std::string& name = m_path;
    OIIO::ImageSpec spec(s.width, s.height, static_cast<int>(s.channelNames.size()),
                         typeDescOf(s.type));
    if (s.metadata && !s.metadata->oiioAttributes.empty()) {
        deserializeAttributes(s.metadata->oiioAttributes, spec);
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
        if (s.metadata->srgb && spec.get_string_attribute("oiio:ColorSpace").empty())
            spec.attribute("oiio:ColorSpace", "sRGB"); // TIFF's and JPEG's writers: Exif 1
        applyJpegMetadata(*s.metadata, spec);
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
    if (fmt == "tiff")
        exifIntegersAsInt(spec);
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
    : m_path(name), m_openName(name), m_parts(specs, specs + count), m_bytes(std::move(bytes)) {
    // Without a pwrite callback the writer writes the file `name` itself (the caller's temporary
    // file), picked by the format's name.
    m_byName = m_bytes.pwrite == nullptr;
    m_out = OIIO::ImageOutput::create(
        m_byName && !m_parts.front().format.empty() ? m_parts.front().format : name);
    if (!m_out)
        throw Error(name + ": no image writer for this extension");
    m_format = m_out->format_name();
    const std::string& fmt = m_format;
    std::vector<OIIO::ImageSpec> subimages;
    std::size_t images = 0;
    bool mips = false;
    for (const SinkSpec& s : m_parts) {
        m_specs.push_back(makeSpec(s));
        images += s.mipLevel == 0 ? 1 : 0;
        mips = mips || s.mipLevel > 0;
    }
    // A TIFF holds MIP levels as directories after the first, which OpenImageIO's reader takes
    // for MIP levels when the first is tagged as a texture (PIXAR_TEXTUREFORMAT): its writer
    // writes them as subimages ("the tiff writer holds no MIP levels" was said of them before).
    m_mipsAsImages = mips && images == 1 && !m_out->supports("mipmap") && fmt == "tiff";
    if (m_mipsAsImages && m_specs.front().get_string_attribute("textureformat").empty())
        m_specs.front().attribute("textureformat", "Plain Texture");
    for (std::size_t i = 0; i < m_parts.size(); ++i)
        if (m_parts[i].mipLevel == 0 || m_mipsAsImages)
            subimages.push_back(m_specs[i]);
    if (fmt == "openexr" && subimages.size() > 1)
        shareDisplayWindow(m_specs, subimages);
    if (subimages.size() > 1 && !m_out->supports("multiimage"))
        throw Error(name + ": the " + fmt + " writer holds one image, not " +
                    std::to_string(subimages.size()));
    if (mips && !m_mipsAsImages && !m_out->supports("mipmap"))
        throw Error(name + ": the " + fmt + " writer holds no MIP levels" +
                    (fmt == "tiff" ? " of " + std::to_string(images) + " pages (one image's only)"
                                   : std::string()));
    if (!m_byName && readsBackWhileWriting(fmt, m_specs)) {
        m_byName = true;
        if (!m_bytes.file.empty()) {
            m_openName = m_bytes.file;
        } else {
            m_scratch = scratchFile({}, "." + fmt, m_scratchRegistration);
            m_openName = m_scratch;
        }
    }
    if (!m_byName) {
        m_proxy = std::make_unique<CallbackProxy>(name, m_bytes);
        if (!m_out->supports("ioproxy"))
            throw Error(name + ": the " + fmt +
                        " writer cannot write through lutkit's checked output");
        m_out->set_ioproxy(m_proxy.get());
    }
    errno = 0;
    const bool ok =
        subimages.size() > 1
            ? m_out->open(m_openName, static_cast<int>(subimages.size()), subimages.data())
            : m_out->open(m_openName, m_specs.front());
    if (!ok)
        failWrite(failure(errno));
}

OiioSink::~OiioSink() {
    removeScratch();
}

void OiioSink::removeScratch() noexcept {
    m_out.reset(); // closes the file
    if (!m_scratch.empty()) {
        ::unlink(m_scratch.c_str());
        m_scratchRegistration.release();
        m_scratch.clear();
    }
}

// OpenImageIO's messages name the file it opened: the caller's name stands for it.
std::string OiioSink::userText(std::string text) const {
    if (m_openName != m_path)
        for (std::size_t at; (at = text.find(m_openName)) != std::string::npos;)
            text.replace(at, m_openName.size(), m_path);
    return text;
}

void OiioSink::failWrite(const std::string& reason) const {
    // OpenEXR names the file in its own sentence ("Cannot open image file "OUT". REASON"): the
    // message names it once, first.
    std::string why = userText(reason);
    for (const char* verb : {"Cannot open image file ", "Cannot write image file "}) {
        const std::string sentence = verb + ("\"" + m_path + "\". ");
        if (const auto at = why.find(sentence); at != std::string::npos)
            why.erase(at, sentence.size());
    }
    throw Error(m_path + ": cannot write: " + why);
}

namespace {

// The errors of a write that failed for want of room or of the device: what the system says.
bool writeErrno(int err) {
    return err == ENOSPC || err == EDQUOT || err == EFBIG || err == EIO || err == EROFS;
}

} // namespace

// Why a write failed: the checked output's reason through the callbacks; a file written by name
// says the system's reason where the write left one in errno (libtiff's "Could not open" for a
// full disk said nothing of the disk), else the writer's message.
std::string OiioSink::failure(int err) const {
    if (proxyFailed())
        return m_proxy->failure();
    if (m_byName && writeErrno(err))
        return std::strerror(err);
    return writerError(m_out ? m_out->geterror() : std::string());
}

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
    const auto mode = m_parts[m_index].mipLevel > 0 && !m_mipsAsImages
                          ? OIIO::ImageOutput::AppendMIPLevel
                          : OIIO::ImageOutput::AppendSubimage;
    errno = 0;
    if (!m_out->open(m_openName, m_specs[m_index], mode) || proxyFailed())
        failWrite(failure(errno));
}

void OiioSink::writeRows(int y0, int y1, const void* src) {
    const SinkSpec& part = m_parts[m_index];
    const OIIO::ImageSpec& spec = m_specs[m_index];
    const OIIO::TypeDesc type = typeDescOf(part.type);
    errno = 0;
    const bool ok = spec.tile_width > 0
                        ? m_out->write_tiles(spec.x, spec.x + spec.width, spec.y + y0, spec.y + y1,
                                             0, 1, type, src)
                        : m_out->write_scanlines(spec.y + y0, spec.y + y1, 0, type, src);
    if (!ok || proxyFailed())
        failWrite(failure(errno));
}

void OiioSink::finish() {
    if (m_index + 1 != m_specs.size())
        throw Error(m_path + ": cannot write: " + std::to_string(m_specs.size() - m_index - 1) +
                    " parts were not written");
    errno = 0;
    const bool ok = m_out->close();
    const std::string error = ok ? std::string() : failure(errno);
    // A writer that opened the file itself (by name) keeps it open, its last bytes buffered,
    // until it is destroyed: before the caller checks and renames the file.
    m_out.reset();
    const int err = errno;
    if (proxyFailed())
        failWrite(m_proxy->failure());
    if (!ok)
        failWrite(error);
    if (m_byName) {
        try {
            checkReadsBack();
        } catch (const Error&) {
            if (writeErrno(err)) // libtiff's close says nothing of its last failed write
                failWrite(std::strerror(err));
            throw;
        }
    }
    if (!m_scratch.empty())
        copyScratch();
}

// A file a writer wrote by name is opened again by OpenImageIO's reader and its images compared
// with what was written: libtiff's TIFFClose, for one, cannot say that its last directory failed
// to reach the disk.
void OiioSink::checkReadsBack() const {
    auto in = OIIO::ImageInput::create(m_format);
    OIIO::ImageSpec spec;
    if (!in || !in->open(m_openName, spec)) {
        const std::string err = in ? oneLine(in->geterror()) : oneLine(OIIO::geterror());
        failWrite("the file written does not read back" + (err.empty() ? "" : ": " + err));
    }
    int subimage = -1;
    for (std::size_t i = 0; i < m_specs.size(); ++i) {
        if (m_parts[i].mipLevel > 0)
            continue; // the levels' sizes follow from the first: each image's first is checked
        const OIIO::ImageSpec& want = m_specs[i];
        ++subimage;
        if (!in->seek_subimage(subimage, 0, spec) || spec.width != want.width ||
            spec.height != want.height || spec.nchannels != want.nchannels)
            failWrite("the file written reads back as something else than was written (image " +
                      std::to_string(subimage + 1) + ")");
    }
    (void)in->geterror();
}

// The scratch file's bytes, in order, through the caller's callbacks.
void OiioSink::copyScratch() {
    const int fd = ::open(m_scratch.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        failWrite(std::string("cannot reopen the temporary file: ") + std::strerror(errno));
    std::vector<char> buf(std::size_t(1) << 20);
    std::uint64_t offset = 0;
    std::string error;
    for (;;) {
        const ssize_t n = ::read(fd, buf.data(), buf.size());
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            error = std::string("cannot read the temporary file: ") + std::strerror(errno);
            break;
        }
        if (n == 0)
            break;
        if (!m_bytes.pwrite(m_bytes.context, buf.data(), static_cast<std::size_t>(n), offset,
                            error)) {
            if (error.empty())
                error = "write failed";
            break;
        }
        offset += static_cast<std::uint64_t>(n);
    }
    ::close(fd);
    if (!error.empty())
        failWrite(error);
    removeScratch();
}

} // namespace lut::formats::module
