// SPDX-License-Identifier: Apache-2.0
// Progress and cancellation of whole-frame image reads and writes (lut/formats/ImageIO.h with a
// lut::Progress): the editor decodes pictures and writes its preview on workers, and a picture
// that is opened while another one decodes stops the first (a 200 KB PNG can hold 8192x8192
// pixels). With a Progress the pixels are the same; a cancelled read throws CancelledError naming
// the file; a cancelled write leaves the old file as it was and no temporary file behind.
#include "TestSupport.h"

#include "lut/formats/ImageIO.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

using namespace lut;
using namespace lut::formats;
namespace fs = std::filesystem;

namespace {

Image pattern(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img.pixel(x, y);
            p[0] = float((x * 3 + y) % 256) / 255.0f;
            p[1] = float((y * 5) % 256) / 255.0f;
            p[2] = float((x ^ y) % 256) / 255.0f;
            p[3] = 1.0f;
        }
    return img;
}

using lut::test::fileBytes;

} // namespace

TEST(ImageProgress, AReadReportsItsRowsAndGivesTheSamePixels) {
    const std::string dir = lut::test::tempDir();
    for (const char* name : {"p.png", "p.exr", "p.ppm", "p.tif"}) {
        const std::string path = dir + "/" + name;
        writeImage(path, pattern(640, 480), ImageWriteOptions(16, false, false));
        std::vector<double> seen;
        Progress p([&](double f) { seen.push_back(f); });
        const LoadedImage with = readImage(path, {}, &p);
        const LoadedImage without = readImage(path);
        EXPECT_EQ(with.image.pixels(), without.image.pixels()) << name;
        ASSERT_FALSE(seen.empty()) << name;
        EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end())) << name;
        EXPECT_DOUBLE_EQ(seen.back(), 1.0) << name;
    }
}

TEST(ImageProgress, ACancelledReadStopsBeforeTheEndAndNamesTheFile) {
    const std::string dir = lut::test::tempDir();
    const std::string path = dir + "/big.png";
    writeImage(path, pattern(2048, 1024), ImageWriteOptions(8, false, false));
    // Cancelled from another thread at the first chunk of rows.
    double reached = 0.0;
    Progress* self = nullptr;
    Progress p([&](double f) {
        reached = f;
        std::thread([self] { self->cancel(); }).join();
    });
    self = &p;
    try {
        readImage(path, {}, &p);
        FAIL() << "the read was not stopped";
    } catch (const CancelledError& e) {
        EXPECT_EQ(std::string(e.what()), path + ": cancelled");
    }
    EXPECT_GT(reached, 0.0);
    EXPECT_LT(reached, 0.5);
    // Cancelled before it starts: nothing is opened.
    Progress before;
    before.cancel();
    EXPECT_THROW(readImage(dir + "/missing.png", {}, &before), CancelledError);
}

TEST(ImageProgress, ACancelledWriteLeavesTheOldFileAndNoTemporaryFile) {
    const std::string dir = lut::test::tempDir();
    const std::string path = dir + "/out.png";
    writeImage(path, pattern(64, 64), ImageWriteOptions(8, false, false));
    const std::string old = fileBytes(path);
    std::vector<double> seen;
    Progress p([&](double f) {
        seen.push_back(f);
        if (seen.size() == 2)
            std::thread([&p] { p.cancel(); }).join();
    });
    ImageWriteOptions o(8, false, false);
    o.progress = &p;
    EXPECT_THROW(writeImage(path, pattern(1024, 2048), o), CancelledError);
    EXPECT_EQ(fileBytes(path), old);
    for (const auto& e : fs::directory_iterator(dir))
        EXPECT_EQ(e.path().filename().string(), "out.png") << "left behind: " << e.path();
    // Not cancelled: reports up to 1 and writes the picture.
    std::vector<double> all;
    Progress q([&](double f) { all.push_back(f); });
    o.progress = &q;
    writeImage(path, pattern(256, 256), o);
    ASSERT_FALSE(all.empty());
    EXPECT_DOUBLE_EQ(all.back(), 1.0);
    EXPECT_EQ(readImage(path).image.width(), 256);
}
