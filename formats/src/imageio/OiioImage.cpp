// SPDX-License-Identifier: Apache-2.0
// Inside lutkit_imageio.so: the OpenImageIO source for every format the native codecs do not
// take (TIFF, JPEG, DPX, BMP, TGA, HDR, WebP, tiled or multi-part EXR ...); the sink is in
// OiioSink.cpp. No colour conversion is ever applied: stored values in, stored values out.
// Metadata: OpenImageIO's attributes (EXIF and TIFF tags, the ICC profile, IPTC, XMP,
// format-specific ones) are kept as exact bytes and given back to the writer.
#include "imageio/OiioImage.h"

#include "imageio/OiioCommon.h"

#include "lut/Limits.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

// From OpenImageIO/tiffutils.h, which needs libtiff's headers for the rest of what it declares.
OIIO_NAMESPACE_BEGIN
OIIO_API void encode_exif(const ImageSpec& spec, std::vector<char>& blob);
OIIO_NAMESPACE_END

#include <algorithm>
#include <cstring>

namespace lut::formats::module {

namespace OIIO = OIIO_NAMESPACE;

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
    meta.oiioAttributes = serializeAttributes(s.extra_attribs);
    meta.srgb = OIIO::Strutil::iequals(info.colorSpace, "sRGB") ||
                s.get_int_attribute("Exif:ColorSpace", 0) == 1;
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

} // namespace lut::formats::module
