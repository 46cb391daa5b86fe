// SPDX-License-Identifier: Apache-2.0
// lutkit's own JPEG reader (formats/src/imageio/JpegCodec.cpp) against OpenImageIO's read of the
// same files (its JPEG reader is libjpeg too: the oracle of what lutkit read through it before):
// the same samples, channels and ImageInfo for every kind of JPEG ImageMagick and oiiotool make;
// and damaged files refused with libjpeg's own words, where ImageMagick (-regard-warnings) flags
// them too (a truncated progressive file with an end-of-image marker appended was graded, exit 0).
#include "TestSupport.h"

#include "imageio/ImageCodec.h"
#include "lut/Error.h"

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace OIIO = OIIO_NAMESPACE;
using lut::test::shellQuoted;
using ::testing::HasSubstr;

namespace {

std::string workDir() {
    static const std::string d = lut::test::tempDir();
    return d;
}

void make(const std::string& command) {
    const auto r = lut::test::runCommand(command);
    ASSERT_EQ(r.exitCode, 0) << command << "\n" << r.err;
}

// What OpenImageIO reads: the spec and every sample as 8 bits; false where it reports an error.
bool oiioRead(const std::string& path, OIIO::ImageSpec& spec, std::vector<unsigned char>& px) {
    auto in = OIIO::ImageInput::open(path);
    if (!in)
        return false;
    spec = in->spec();
    px.resize(spec.image_bytes());
    const bool ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, px.data());
    return ok && !in->has_error();
}

std::vector<unsigned char> lutkitRead(const std::string& path, lut::formats::ImageInfo& info) {
    auto src = lut::formats::openImageSource(path);
    info = src->info();
    std::vector<unsigned char> px(static_cast<std::size_t>(info.width) * info.height *
                                  info.channels);
    src->readRows(0, info.height, px.data());
    src->finish();
    return px;
}

} // namespace

TEST(JpegRead, EveryKindReadsAsOpenImageIOReadsIt) {
    const std::string d = workDir();
    const std::string src = shellQuoted(lut::test::samplePath("sample_scene.png"));
    struct Kind {
        const char* name;
        const char* imagemagick; // options before the output
    };
    const Kind kinds[] = {
        {"baseline420.jpg", "-quality 92 -sampling-factor 2x2"},
        {"baseline444.jpg", "-quality 95 -sampling-factor 1x1"},
        {"baseline422.jpg", "-quality 90 -sampling-factor 2x1"},
        {"progressive.jpg", "-interlace JPEG -quality 85"},
        {"grey.jpg", "-colorspace Gray -quality 90"},
        {"cmyk.jpg", "-colorspace CMYK -quality 90"},
        {"restart.jpg", "-define jpeg:restart-interval=2 -quality 80"},
        {"arithmetic.jpg", "-define jpeg:arithmetic-coding=true -quality 80"},
        {"odd-size.jpg", "-resize 333x77! -quality 75"},
    };
    for (const Kind& k : kinds) {
        SCOPED_TRACE(k.name);
        const std::string path = d + "/" + k.name;
        make("convert " + src + " -resize 256x144! " + k.imagemagick + " " + shellQuoted(path));
        OIIO::ImageSpec spec;
        std::vector<unsigned char> want;
        ASSERT_TRUE(oiioRead(path, spec, want)) << OIIO::geterror();
        lut::formats::ImageInfo info;
        const std::vector<unsigned char> got = lutkitRead(path, info);
        EXPECT_EQ(info.width, spec.width);
        EXPECT_EQ(info.height, spec.height);
        EXPECT_EQ(info.channels, spec.nchannels);
        EXPECT_EQ(info.format, "jpeg");
        EXPECT_EQ(info.colorSpace, spec.get_string_attribute("oiio:ColorSpace"));
        EXPECT_EQ(info.chromaSubsampling, spec.get_string_attribute("jpeg:subsampling"));
        std::vector<std::string> names(spec.channelnames.begin(), spec.channelnames.end());
        EXPECT_EQ(info.channelNames, names);
        ASSERT_EQ(got.size(), want.size());
        std::size_t differ = 0;
        for (std::size_t i = 0; i < got.size(); ++i)
            differ += got[i] != want[i];
        EXPECT_EQ(differ, 0u) << "of " << got.size() << " samples";
    }
}

TEST(JpegRead, MetadataIsKept) {
    const std::string d = workDir();
    const std::string path = d + "/tagged.jpg";
    make("oiiotool --pattern fill:top=0.2,0.4,0.6:bottom=0.9,0.1,0.3 64x48 3 -d uint8 "
         "--attrib Artist 'the test' --attrib ImageDescription 'a description' "
         "--attrib Exif:ExposureTime 0.004 -o " +
         shellQuoted(path));
    auto src = lut::formats::openImageSource(path);
    const auto meta = src->metadata();
    ASSERT_TRUE(meta);
    EXPECT_FALSE(meta->exif.empty());
    // The EXIF block holds what OpenImageIO wrote (its own decoder reads it back).
    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().get_string_attribute("Artist"), "the test");
    EXPECT_NE(meta->exif.find("the test"), std::string::npos);
}

// Damaged files: libjpeg only warns and fills with grey; lutkit refuses them in every command,
// naming the file and quoting libjpeg.
TEST(JpegRead, DamagedFilesAreRefusedWithLibjpegsWords) {
    const std::string d = workDir();
    const std::string src = shellQuoted(lut::test::samplePath("sample_scene.png"));
    const std::string prog = d + "/prog.jpg", base = d + "/base.jpg";
    make("convert " + src + " -resize 320x192! -interlace JPEG -quality 90 " + shellQuoted(prog));
    make("convert " + src + " -resize 320x192! -quality 90 " + shellQuoted(base));
    struct Bad {
        std::string name, bytes, words;
    };
    std::vector<Bad> bad;
    const std::string p = lut::test::fileBytes(prog), b = lut::test::fileBytes(base);
    for (const int percent : {30, 60, 90}) {
        const std::size_t cut = p.size() * percent / 100;
        bad.push_back({"prog-cut" + std::to_string(percent) + ".jpg", p.substr(0, cut) + "\xff\xd9",
                       "premature end"});
    }
    bad.push_back({"base-cut.jpg", b.substr(0, b.size() / 2) + "\xff\xd9", "premature end"});
    // Bytes between the entropy-coded data and the end-of-image marker.
    bad.push_back({"extraneous.jpg", b.substr(0, b.size() - 2) + "garbage" + "\xff\xd9",
                   "extraneous bytes before marker"});
    for (const Bad& x : bad) {
        SCOPED_TRACE(x.name);
        const std::string path = d + "/" + x.name;
        {
            std::FILE* f = std::fopen(path.c_str(), "wb");
            ASSERT_TRUE(f);
            std::fwrite(x.bytes.data(), 1, x.bytes.size(), f);
            std::fclose(f);
        }
        // The oracle: ImageMagick, told to take libjpeg's warnings as errors, says it is damaged
        // in the same words (OpenImageIO 2.4 reads the extraneous bytes without a word).
        const auto im = lut::test::runCommand("convert -regard-warnings " + shellQuoted(path) +
                                              " " + shellQuoted(d + "/im.png"));
        EXPECT_NE(im.exitCode, 0) << "ImageMagick reads it as whole";
        EXPECT_THAT(im.err, HasSubstr(x.words));
        lut::formats::ImageInfo info;
        try {
            (void)lutkitRead(path, info);
            ADD_FAILURE() << "read without an error";
        } catch (const lut::Error& e) {
            EXPECT_THAT(e.what(), HasSubstr(path + ": cannot read image data: JPEG error:"));
            EXPECT_THAT(e.what(), HasSubstr(x.words));
        }
        // Every command refuses it, exit 1, nothing written.
        for (const std::string& cmd :
             {"apply --lut builtin:neutral " + shellQuoted(path) + " -o " +
                  shellQuoted(d + "/o.png"),
              "preview " + shellQuoted(path) + " -o " + shellQuoted(d + "/o.png")}) {
            const auto r = lut::test::runCli(cmd);
            EXPECT_EQ(r.exitCode, 1) << cmd << "\n" << r.err;
            EXPECT_THAT(r.err, HasSubstr(x.words)) << cmd;
        }
        EXPECT_FALSE(std::filesystem::exists(d + "/o.png"));
    }
}
