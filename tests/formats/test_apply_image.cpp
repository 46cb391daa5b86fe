// SPDX-License-Identifier: Apache-2.0
// The streaming apply (lut/formats/ApplyImage.h): every data type and the metadata kept (checked
// against OpenImageIO's own reading of the input and the output), pixel values against the map
// the LUT samples, streamed results bit-identical to one whole-frame chunk, values outside the
// LUT's domain counted, truncated files refused, write errors reported (never exit()).
#include "TestSupport.h"

#include "lut/Error.h"
#include "lut/Quantize.h"
#include "lut/formats/ApplyImage.h"
#include "lut/formats/ImageIO.h"
#include "lut/interp/Sampler.h"
#include "lut/io/OutputPolicy.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

using namespace lut;
using namespace lut::formats;
namespace OIIO = OIIO_NAMESPACE;

namespace {

// An affine map: every interpolation reproduces it exactly from a 2^3 lattice.
double affine(int c, double r, double g, double b) {
    return c == 0 ? 0.21 + 0.4837 * r : c == 1 ? 1.0 - 0.9123 * g : 0.2519 * b + 0.4711 * r;
}

PixelChain affineChain() {
    Lut3D l(2);
    for (int b = 0; b < 2; ++b)
        for (int g = 0; g < 2; ++g)
            for (int r = 0; r < 2; ++r)
                l.at(r, g, b) = glm::vec3(static_cast<float>(affine(0, r, g, b)),
                                          static_cast<float>(affine(1, r, g, b)),
                                          static_cast<float>(affine(2, r, g, b)));
    PixelChain chain;
    chain.setLut(l, Interpolation::Tetrahedral);
    return chain;
}

struct Case {
    const char* name;
    const char* ext;
    OIIO::TypeDesc type;
    int channels;
    const char* compression; // "" = the writer's default
    int bits = 0;            // oiio:BitsPerSample (DPX 10)
};

// An image with a smooth ramp and every kind of attribute the format's OIIO writer keeps.
void writeInput(const std::string& path, const Case& c, int w, int h) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << path;
    OIIO::ImageSpec spec(w, h, c.channels, c.type);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    spec.attribute("ImageDescription", "lutkit test image");
    spec.attribute("Artist", "the test");
    const std::string ext = c.ext;
    if (*c.compression)
        spec.attribute("compression", c.compression);
    if (c.bits)
        spec.attribute("oiio:BitsPerSample", c.bits);
    if (ext == ".exr") {
        spec.attribute("owner", "lutkit");
        spec.attribute("custom:exposure", 1.5f);
        spec.attribute("capDate", "2026:11:23 12:00:00");
    }
    if (ext == ".png" || ext == ".tif" || ext == ".jpg") {
        // A minimal valid ICC header (libpng checks it): size, version 2.1, a display RGB
        // profile in XYZ, 'acsp', no tags; then some private bytes the copy must keep too.
        std::vector<unsigned char> icc(132 + 12, 0);
        const auto put32 = [&](std::size_t at, std::uint32_t v) {
            for (int k = 0; k < 4; ++k)
                icc[at + k] = static_cast<unsigned char>(v >> (24 - 8 * k));
        };
        put32(0, static_cast<std::uint32_t>(icc.size()));
        put32(8, 0x02100000);
        std::memcpy(&icc[12], "mntrRGB XYZ ", 12);
        std::memcpy(&icc[36], "acsp", 4);
        put32(68, 0x0000F6D6); // D50 illuminant
        put32(72, 0x00010000);
        put32(76, 0x0000D32D);
        for (std::size_t i = 132; i < icc.size(); ++i)
            icc[i] = static_cast<unsigned char>(i * 7);
        spec.attribute("ICCProfile", OIIO::TypeDesc(OIIO::TypeDesc::UINT8, int(icc.size())),
                       icc.data());
        spec.attribute("XResolution", 300.0f);
        spec.attribute("YResolution", 300.0f);
        spec.attribute("ResolutionUnit", "in");
    }
    if (ext == ".tif" || ext == ".jpg") {
        spec.attribute("Exif:ExposureTime", 0.004f);
        spec.attribute("Exif:ISOSpeedRatings", 200);
    }
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    std::vector<float> px(static_cast<std::size_t>(w) * h * c.channels);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int ch = 0; ch < c.channels; ++ch)
                px[(static_cast<std::size_t>(y) * w + x) * c.channels + ch] =
                    static_cast<float>(((x * 37 + y * 11 + ch * 53) % 256) / 255.0);
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data())) << out->geterror();
    ASSERT_TRUE(out->close());
}

struct Read {
    OIIO::ImageSpec spec;
    std::vector<float> px;
};

Read readOiio(const std::string& path) {
    Read r;
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    EXPECT_TRUE(in) << path << ": " << OIIO::geterror();
    if (!in)
        return r;
    r.spec = in->spec();
    r.px.resize(static_cast<std::size_t>(r.spec.width) * r.spec.height * r.spec.nchannels);
    EXPECT_TRUE(in->read_image(0, 0, 0, r.spec.nchannels, OIIO::TypeDesc::FLOAT, r.px.data()));
    return r;
}

std::string bytesOf(const OIIO::ParamValue& p) {
    if (p.type().basetype == OIIO::TypeDesc::STRING)
        return p.get_string();
    return std::string(static_cast<const char*>(p.data()),
                       p.type().size() * static_cast<std::size_t>(p.nvalues()));
}

} // namespace

TEST(ApplyImage, EveryDataTypeAndItsMetadataAreKept) {
    const std::string dir = lut::test::tempDir();
    const Case cases[] = {
        {"png8", ".png", OIIO::TypeDesc::UINT8, 3, ""},
        {"png16a", ".png", OIIO::TypeDesc::UINT16, 4, ""},
        {"ppm8", ".ppm", OIIO::TypeDesc::UINT8, 3, ""},
        {"ppm16", ".ppm", OIIO::TypeDesc::UINT16, 3, ""},
        {"exrhalf", ".exr", OIIO::TypeDesc::HALF, 4, "piz"},
        {"exrfloat", ".exr", OIIO::TypeDesc::FLOAT, 3, "none"},
        {"tif8", ".tif", OIIO::TypeDesc::UINT8, 3, "lzw"},
        {"tif16", ".tif", OIIO::TypeDesc::UINT16, 4, "zip"},
        {"tifhalf", ".tif", OIIO::TypeDesc::HALF, 3, "zip"},
        {"tiffloat", ".tif", OIIO::TypeDesc::FLOAT, 3, "none"},
        {"dpx10", ".dpx", OIIO::TypeDesc::UINT16, 3, "", 10},
        {"jpg", ".jpg", OIIO::TypeDesc::UINT8, 3, ""},
    };
    const PixelChain chain = affineChain();
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        const std::string in = dir + "/" + c.name + c.ext;
        const std::string out = dir + "/" + c.name + "_out" + c.ext;
        if (std::string(c.name) == "ppm16") { // OpenImageIO writes PNM with 8 bits only
            Image img(37, 19);
            for (int y = 0; y < 19; ++y)
                for (int x = 0; x < 37; ++x)
                    for (int ch = 0; ch < 4; ++ch)
                        img.pixel(x, y)[ch] =
                            static_cast<float>(((x * 997 + y * 131 + ch * 53) % 65536) / 65535.0);
            writeImage(in, img, ImageWriteOptions(16, false, false));
        } else {
            writeInput(in, c, 37, 19);
        }
        const ApplyImageReport r =
            applyToImage(in, checkOutput(out, ExistingOutput::Refuse), chain);
        const Read a = readOiio(in), b = readOiio(out);
        EXPECT_EQ(b.spec.format, a.spec.format) << "data type";
        EXPECT_EQ(b.spec.nchannels, a.spec.nchannels);
        EXPECT_EQ(b.spec.channelnames, a.spec.channelnames);
        // Every attribute OpenImageIO reads from the input, with the same bytes.
        for (const auto& p : a.spec.extra_attribs) {
            if (p.name() == "tiff:RowsPerStrip") // how the writer cuts the data, not metadata
                continue;
            const OIIO::ParamValue* q = b.spec.find_attribute(p.name());
            ASSERT_NE(q, nullptr) << p.name() << " lost";
            EXPECT_EQ(q->type(), p.type()) << p.name();
            EXPECT_EQ(bytesOf(*q), bytesOf(p)) << p.name();
        }
        // Pixels: the affine map of the stored values, to the output's precision.
        // OpenImageIO's DPX writer truncates 16 to 10 bits (up to one 10-bit step), its PNM
        // reader rounds 16-bit samples down (a step on each of the two reads: the files hold the
        // right values);
        // JPEG is compared on average (re-encoding a lossy file).
        const bool pnm16 = std::string(c.name) == "ppm16";
        const double tol = pnm16                              ? 2.5 / 65535
                           : c.type == OIIO::TypeDesc::UINT8  ? 0.5 / 255 + 1e-6
                           : c.type == OIIO::TypeDesc::HALF   ? 1e-3
                           : c.bits == 10                     ? 1.0 / 1023 + 1e-6
                           : c.type == OIIO::TypeDesc::UINT16 ? 0.5 / 65535 + 1e-6
                                                              : 1e-5;
        const int nch = a.spec.nchannels;
        double worst = 0, sum = 0;
        for (std::size_t i = 0; i + nch <= a.px.size(); i += static_cast<std::size_t>(nch))
            for (int ch = 0; ch < std::min(nch, 3); ++ch) {
                const double want =
                    std::clamp(affine(ch, a.px[i], a.px[i + 1], a.px[i + 2]), 0.0, 1.0);
                const double e = std::fabs(b.px[i + static_cast<std::size_t>(ch)] - want);
                worst = std::max(worst, e);
                sum += e;
            }
        if (std::string(c.ext) == ".jpg")
            EXPECT_LE(sum / static_cast<double>(a.px.size()), 0.1);
        else
            EXPECT_LE(worst, tol);
        if (nch == 4) {
            for (std::size_t i = 3; i < a.px.size(); i += 4)
                ASSERT_EQ(b.px[i], a.px[i]) << "alpha changed";
        }
        EXPECT_EQ(r.output.type, r.input.type);
    }
}

TEST(ApplyImage, StreamedEqualsOneWholeFrameChunk) {
    const std::string dir = lut::test::tempDir();
    const PixelChain chain = affineChain();
    const Case cases[] = {
        {"half", ".exr", OIIO::TypeDesc::HALF, 4, "zip"},
        {"u16", ".png", OIIO::TypeDesc::UINT16, 3, ""},
        {"f32", ".tif", OIIO::TypeDesc::FLOAT, 3, "none"},
        {"u8", ".ppm", OIIO::TypeDesc::UINT8, 3, ""},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        const std::string in = dir + "/" + c.name + c.ext;
        writeInput(in, c, 301, 97);
        ApplyImageOptions streamed;
        streamed.rowsPerChunk = 3;
        streamed.threads = 2;
        ApplyImageOptions whole;
        whole.rowsPerChunk = 97;
        whole.overlap = false;
        whole.threads = 1;
        const std::string s = dir + "/" + c.name + "_s" + c.ext;
        const std::string w = dir + "/" + c.name + "_w" + c.ext;
        applyToImage(in, checkOutput(s, ExistingOutput::Refuse), chain, streamed);
        applyToImage(in, checkOutput(w, ExistingOutput::Refuse), chain, whole);
        const Read rs = readOiio(s), rw = readOiio(w);
        ASSERT_EQ(rs.px.size(), rw.px.size());
        EXPECT_EQ(std::memcmp(rs.px.data(), rw.px.data(), rs.px.size() * sizeof(float)), 0);
    }
    // And the same values as the float frame path (readImage, the sampler, the quantiser).
    const std::string in = dir + "/u16.png";
    LoadedImage frame = readImage(in);
    Lut3D l(2);
    for (int b = 0; b < 2; ++b)
        for (int g = 0; g < 2; ++g)
            for (int r = 0; r < 2; ++r)
                l.at(r, g, b) = glm::vec3(static_cast<float>(affine(0, r, g, b)),
                                          static_cast<float>(affine(1, r, g, b)),
                                          static_cast<float>(affine(2, r, g, b)));
    makeSampler(l, Interpolation::Tetrahedral)->apply(frame.image.view(), 1);
    const Read rs = readOiio(dir + "/u16_s.png");
    for (int y = 0; y < 97; ++y)
        for (int x = 0; x < 301; ++x)
            for (int ch = 0; ch < 3; ++ch)
                ASSERT_EQ(toUnorm16(rs.px[(static_cast<std::size_t>(y) * 301 + x) * 3 + ch]),
                          toUnorm16(frame.image.pixel(x, y)[ch]))
                    << x << "," << y;
}

TEST(ApplyImage, ValuesOutsideTheDomainAreCounted) {
    const std::string dir = lut::test::tempDir();
    const std::string in = dir + "/hdr.exr";
    auto out = OIIO::ImageOutput::create(in);
    ASSERT_TRUE(out->open(in, OIIO::ImageSpec(4, 2, 3, OIIO::TypeDesc::FLOAT)));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float px[] = {0.5f, 0.5f, 0.5f, 2.0f, 0.1f, 0.1f, 0.2f, -0.75f, 0.3f, nan,  0,    0,
                        1.0f, 1.0f, 1.0f, 0,    0,    0,    7.5f, 0.2f,   0.2f, 0.1f, 0.1f, 0.1f};
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px));
    out->close();
    const ApplyImageReport r =
        applyToImage(in, checkOutput(dir + "/o.exr", ExistingOutput::Refuse), affineChain());
    EXPECT_EQ(r.domain.pixels, 8u);
    EXPECT_EQ(r.domain.outside, 4u); // 2.0, -0.75, NaN, 7.5
    EXPECT_EQ(r.domain.nan, 1u);
    EXPECT_EQ(r.domain.worst, 7.5f);
}

// 8-bit pixels always lie in [0, 1]: the count is skipped only when the LUT's domain holds
// [0, 1]. Here it ends at 0.5, so every code above 127.5 in any channel is outside (counted
// plainly from the stored codes).
TEST(ApplyImage, IntegerPixelsOutsideANarrowDomainAreCounted) {
    const std::string dir = lut::test::tempDir();
    const std::string in = dir + "/shot.png";
    auto out = OIIO::ImageOutput::create(in);
    ASSERT_TRUE(out->open(in, OIIO::ImageSpec(16, 16, 3, OIIO::TypeDesc::UINT8)));
    std::vector<unsigned char> px(16 * 16 * 3);
    std::size_t expected = 0;
    for (std::size_t i = 0; i < 16 * 16; ++i) {
        bool outside = false;
        for (std::size_t c = 0; c < 3; ++c) {
            px[3 * i + c] = static_cast<unsigned char>((i * 37 + c * 101) % 256);
            outside = outside || px[3 * i + c] / 255.0 > 0.5;
        }
        expected += outside;
    }
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
    out->close();
    Lut3D l(2);
    l.setDomain(glm::vec3(0.0f), glm::vec3(0.5f));
    for (int b = 0; b < 2; ++b)
        for (int g = 0; g < 2; ++g)
            for (int r = 0; r < 2; ++r)
                l.at(r, g, b) = glm::vec3(r, g, b) * 0.5f;
    PixelChain chain;
    chain.setLut(l, Interpolation::Tetrahedral);
    ASSERT_FALSE(chain.unitInputStaysInDomain());
    const ApplyImageReport r =
        applyToImage(in, checkOutput(dir + "/o.png", ExistingOutput::Refuse), chain);
    ASSERT_GT(expected, 0u);
    EXPECT_EQ(r.domain.outside, expected);
    // The same picture through a LUT over [0, 1] with entries in [0, 1]: nothing can be outside
    // its domain or clamped by the 8-bit output, nothing is counted.
    ASSERT_TRUE(affineChain().unitInputGivesUnitOutput());
    const ApplyImageReport unit =
        applyToImage(in, checkOutput(dir + "/o2.png", ExistingOutput::Refuse), affineChain());
    EXPECT_EQ(unit.domain.outside, 0u);
}

TEST(ApplyImage, TruncatedAndHostileFilesAreRefused) {
    const std::string dir = lut::test::tempDir();
    const Case png{"t", ".png", OIIO::TypeDesc::UINT8, 3, ""};
    const Case jpg{"t", ".jpg", OIIO::TypeDesc::UINT8, 3, ""};
    writeInput(dir + "/whole.png", png, 256, 256);
    writeInput(dir + "/whole.jpg", jpg, 256, 256);
    for (const char* name : {"whole.png", "whole.jpg"}) {
        std::ifstream f(dir + "/" + name, std::ios::binary);
        std::string bytes{std::istreambuf_iterator<char>(f), {}};
        const std::string cut = dir + "/cut_" + name;
        std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() * 2 / 3);
        const std::string o = dir + "/o_" + name;
        try {
            applyToImage(cut, checkOutput(o, ExistingOutput::Refuse), affineChain());
            ADD_FAILURE() << name << ": a truncated file was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
        }
        EXPECT_FALSE(std::ifstream(o).good()) << "no output for a refused input";
        EXPECT_THROW(readImage(cut), Error);
    }
    // A PNG header declaring 16384x16384 RGBA in a few bytes: refused before decoding.
    std::ifstream f(dir + "/whole.png", std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(f), {}};
    bytes[16] = 0, bytes[17] = 0, bytes[18] = 0x40, bytes[19] = 0; // width 16384
    bytes[20] = 0, bytes[21] = 0, bytes[22] = 0x40, bytes[23] = 0; // height 16384
    bytes[25] = 6;                                                 // RGBA, 8 bits
    std::uint32_t crc = 0xFFFFFFFFu;                               // the IHDR CRC, recomputed
    for (int i = 12; i < 29; ++i) {
        crc ^= static_cast<unsigned char>(bytes[static_cast<std::size_t>(i)]);
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    crc ^= 0xFFFFFFFFu;
    for (int k = 0; k < 4; ++k)
        bytes[static_cast<std::size_t>(29 + k)] = static_cast<char>(crc >> (24 - 8 * k));
    std::ofstream(dir + "/huge.png", std::ios::binary) << bytes.substr(0, 4096);
    try {
        applyToImage(dir + "/huge.png", checkOutput(dir + "/o.png", ExistingOutput::Refuse),
                     affineChain());
        ADD_FAILURE() << "a 1 KB PNG declaring 16384x16384 was accepted";
    } catch (const LimitError& e) {
        EXPECT_NE(std::string(e.what()).find("declares 16384x16384 pixels (1073758208 bytes as "
                                             "stored) in "),
                  std::string::npos)
            << e.what();
    }
}

TEST(ApplyImage, AFullDeviceIsAnErrorForEveryWriter) {
    if (!std::ifstream("/dev/full").good())
        GTEST_SKIP() << "no /dev/full";
    const std::string dir = lut::test::tempDir();
    const Case in{"in", ".png", OIIO::TypeDesc::UINT8, 3, ""};
    writeInput(dir + "/in.png", in, 64, 64);
    // PNG and PNM are native; JPEG, TIFF, BMP and TGA go through OpenImageIO (libjpeg's default
    // error handler would exit(1) on a failed write: the process must survive to report it).
    for (const char* fmt : {"png", "ppm", "jpg", "tif", "bmp", "tga"}) {
        SCOPED_TRACE(fmt);
        ApplyImageOptions o;
        o.outFormat = fmt;
        try {
            applyToImage(dir + "/in.png", checkOutput("/dev/full", ExistingOutput::Refuse),
                         affineChain(), o);
            ADD_FAILURE() << "writing to a full device succeeded";
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()), "/dev/full: cannot write: No space left on device");
        }
    }
}

namespace {

// OpenImageIO's float reading of one part (subimage, MIP level) of a file.
std::vector<float> oiioPart(const std::string& path, int subimage, int mip, int& w, int& h,
                            int& channels, int& tile) {
    auto in = OIIO::ImageInput::open(path);
    if (!in || !in->seek_subimage(subimage, mip))
        return {};
    const OIIO::ImageSpec& s = in->spec();
    w = s.width, h = s.height, channels = s.nchannels, tile = s.tile_width;
    std::vector<float> px(static_cast<std::size_t>(w) * h * channels);
    if (!in->read_image(subimage, mip, 0, channels, OIIO::TypeDesc::FLOAT, px.data()))
        return {};
    return px;
}

} // namespace

// A tiled two-part OpenEXR (parts of different sizes, partial tiles) streamed in small chunks on
// the reader, compute and writer threads: every part graded and kept, tiles kept, the memory
// reserved once before decoding (issue 29). Oracle: OpenImageIO's reading of the input, through the
// affine map.
TEST(ApplyImage, EveryPartOfATiledMultiPartFileIsStreamed) {
    const std::string dir = lut::test::tempDir();
    const std::string in = dir + "/in.exr";
    {
        auto out = OIIO::ImageOutput::create(in);
        ASSERT_TRUE(out);
        OIIO::ImageSpec specs[2] = {OIIO::ImageSpec(40, 36, 3, OIIO::TypeDesc::HALF),
                                    OIIO::ImageSpec(33, 20, 3, OIIO::TypeDesc::HALF)};
        for (auto& s : specs) {
            s.tile_width = s.tile_height = 16;
            s.attribute("openexr:levelmode", 0);
        }
        specs[1].full_width = 40; // the parts of a file share one display window
        specs[1].full_height = 36;
        ASSERT_TRUE(out->open(in, 2, specs)) << out->geterror();
        std::vector<float> px;
        auto fill = [&](int w, int h, int seed) {
            px.resize(static_cast<std::size_t>(w) * h * 3);
            for (std::size_t i = 0; i < px.size(); ++i)
                px[i] = static_cast<float>((i * 37 + static_cast<std::size_t>(seed)) % 101) / 100.f;
        };
        fill(40, 36, 1);
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
        ASSERT_TRUE(out->open(in, specs[1], OIIO::ImageOutput::AppendSubimage));
        fill(33, 20, 2);
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data())) << out->geterror();
        ASSERT_TRUE(out->close());
    }
    ApplyImageOptions o;
    o.rowsPerChunk = 16; // several chunks per part: the reader, compute and writer overlap
    int reservations = 0;
    std::uint64_t reserved = 0;
    o.reserveMemory = [&](std::uint64_t bytes, const std::string&) {
        ++reservations;
        reserved = bytes;
    };
    const std::string outPath = dir + "/out.exr";
    const ApplyImageReport r =
        applyToImage(in, checkOutput(outPath, ExistingOutput::Refuse), affineChain(), o);
    EXPECT_EQ(reservations, 1);
    EXPECT_GT(reserved, 16u * 40 * 3 * 2);
    int expectedParts = 0;
    for (int sub = 0; sub < 2; ++sub)
        for (int mip = 0;; ++mip) {
            int w = 0, h = 0, ch = 0, tile = 0, ow = 0, oh = 0, och = 0, otile = 0;
            const auto a = oiioPart(in, sub, mip, w, h, ch, tile);
            if (a.empty())
                break;
            ++expectedParts;
            const auto b = oiioPart(outPath, sub, mip, ow, oh, och, otile);
            ASSERT_EQ(b.size(), a.size()) << "subimage " << sub << " level " << mip;
            EXPECT_EQ(otile, 16);
            double worst = 0.0;
            for (std::size_t p = 0; p < a.size() / 3; ++p)
                for (int c = 0; c < 3; ++c)
                    worst =
                        std::max(worst, std::abs(b[p * 3 + c] -
                                                 affine(c, a[p * 3], a[p * 3 + 1], a[p * 3 + 2])));
            EXPECT_LT(worst, 2e-3) << "subimage " << sub << " level " << mip; // half
        }
    EXPECT_EQ(r.parts, expectedParts);
    EXPECT_EQ(expectedParts, 2);
}
