// SPDX-License-Identifier: Apache-2.0
// The content check of image reads (issue 41): an input rewritten in place at the same size while
// it is read (`dd conv=notrunc` on an uncompressed TIFF) gave rows of neither picture, exit 0;
// only a change of size was caught. Each file's change time, modification time and size are
// taken before the read and compared after it (formats/src/imageio/ImageSources.cpp,
// docs/robustness.md). Deterministic: the rewrite happens from the read's own progress callback,
// after the first chunk of rows and before the last, through a second descriptor opened for
// writing without truncation, as dd does.
#include "TestSupport.h"

#include "lut/Error.h"
#include "lut/Progress.h"
#include "lut/formats/ImageIO.h"

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fcntl.h>
#include <string>
#include <unistd.h>
#include <vector>

using ::testing::HasSubstr;

namespace {

// An uncompressed image of w x h with OpenImageIO (TIFF: read through OpenImageIO; PPM: lutkit's
// own reader).
void writeImage(const std::string& path, int w, int h, const char* compression) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
    if (compression)
        spec.attribute("compression", compression);
    std::vector<unsigned char> px(static_cast<std::size_t>(w) * h * 3);
    for (std::size_t i = 0; i < px.size(); ++i)
        px[i] = static_cast<unsigned char>((i * 7) % 251);
    ASSERT_TRUE(out->open(path, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
    ASSERT_TRUE(out->close());
}

// Reads path whole; with `rewrite`, the second half of its bytes is overwritten in place (same
// size) once the first rows are decoded. Returns the error's message, "" when it was read.
std::string readWhileRewritten(const std::string& path, bool rewrite, int* reports = nullptr) {
    bool done = false;
    int calls = 0;
    lut::Progress progress([&](double fraction) {
        ++calls;
        if (!rewrite || done || fraction >= 1.0)
            return;
        done = true;
        const int fd = ::open(path.c_str(), O_WRONLY);
        ASSERT_GE(fd, 0);
        const off_t size = ::lseek(fd, 0, SEEK_END);
        const std::vector<char> junk(static_cast<std::size_t>(size / 4), '\x55');
        ASSERT_EQ(::pwrite(fd, junk.data(), junk.size(), size / 2),
                  static_cast<ssize_t>(junk.size()));
        ::close(fd);
    });
    std::string error;
    try {
        (void)lut::formats::readImage(path, {}, &progress);
    } catch (const lut::Error& e) {
        error = e.what();
    }
    if (reports)
        *reports = calls;
    EXPECT_TRUE(!rewrite || done) << "the read gave no progress before its last row";
    return error;
}

class ChangedWhileRead : public ::testing::TestWithParam<const char*> {};

TEST_P(ChangedWhileRead, RewriteInPlaceAtTheSameSizeIsAnErrorNamingTheFile) {
    const std::string dir = lut::test::tempDir();
    const std::string path = dir + "/in." + GetParam();
    writeImage(path, 512, 2048, std::string(GetParam()) == "tif" ? "none" : nullptr);
    int reports = 0;
    EXPECT_EQ(readWhileRewritten(path, false, &reports), ""); // untouched: read, no complaint
    EXPECT_GT(reports, 2);
    const std::string error = readWhileRewritten(path, true);
    EXPECT_THAT(error, HasSubstr(path + ": the file changed while being read"));
}

INSTANTIATE_TEST_SUITE_P(Formats, ChangedWhileRead, ::testing::Values("tif", "ppm"));

} // namespace
