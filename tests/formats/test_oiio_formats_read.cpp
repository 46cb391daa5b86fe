// SPDX-License-Identifier: Apache-2.0
// Images of the formats OpenImageIO reads for lutkit, each written by oiiotool, read by
// lut::formats::readImage as oiiotool reads them: every pixel's stored code equals the one
// `oiiotool --dumpdata` prints, from the file and from its bytes in memory (standard input's
// path). OpenImageIO 2.4's WebP reader refused every file here ("Couldn't decode subimage 0")
// after the listing of its frames had asked for one past the last; its GIF, SGI and FITS readers
// refused every in-memory image ("Could not open file stdin.gif").
#include "TestSupport.h"

#include "lut/formats/ImageIO.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

using namespace lut;
using namespace lut::test;

namespace {

// "Pixel (x, y): c0 c1 c2 (...)" lines of oiiotool --dumpdata: the stored values by pixel
// (integer codes, or floats for a float file).
std::map<std::pair<int, int>, std::vector<double>> dumped(const std::string& path) {
    const RunResult r = runCommand("oiiotool --dumpdata " + shellQuoted(path));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    std::map<std::pair<int, int>, std::vector<double>> out;
    std::istringstream in(r.out);
    for (std::string line; std::getline(in, line);) {
        int x = 0, y = 0, n = 0;
        if (std::sscanf(line.c_str(), " Pixel (%d, %d):%n", &x, &y, &n) != 2)
            continue;
        std::istringstream codes(line.substr(static_cast<std::size_t>(n)));
        std::vector<double> v;
        for (double c; codes >> c;)
            v.push_back(c);
        out[{x, y}] = v;
    }
    return out;
}

} // namespace

TEST(OiioFormatsRead, EveryPixelIsTheCodeOiiotoolReads) {
    const std::string dir = tempDir();
    const std::string pattern = "--pattern fill:topleft=0.1,0.2,0.3:topright=0.9,0.5,0.1:"
                                "bottomleft=0.2,0.8,0.4:bottomright=1,1,1 24x10 3 -d uint8";
    const std::pair<const char*, const char*> cases[] = {
        {"lossless.webp", " --compression lossless"},
        {"lossy.webp", ""},
        {"a.tga", ""},
        {"a.bmp", ""},
        {"a.jpg", ""},
        {"a.dpx", ""},
        {"a.gif", ""},
        {"a.sgi", ""},
        {"a.fits", ""},
        {"a.tif", ""},
        {"a.hdr", ""},
    };
    for (const auto& [file, extra] : cases) {
        SCOPED_TRACE(file);
        const std::string path = dir + "/" + file;
        ASSERT_EQ(runCommand("oiiotool " + pattern + extra + " -o " + shellQuoted(path)).exitCode,
                  0);
        const auto want = dumped(path);
        ASSERT_EQ(want.size(), 240u);
        const bool hdr = std::string(file).find(".hdr") != std::string::npos;
        for (int memory = 0; memory < 2; ++memory) {
            SCOPED_TRACE(memory ? "from memory" : "from the file");
            formats::LoadedImage got;
            ASSERT_NO_THROW(got = memory ? formats::readImageMemory(fileBytes(path), "-")
                                         : formats::readImage(path));
            ASSERT_EQ(got.image.width(), 24);
            ASSERT_EQ(got.image.height(), 10);
            int wrong = 0;
            for (const auto& [xy, codes] : want) {
                const float* p = got.image.pixel(xy.first, xy.second);
                for (std::size_t c = 0; c < 3 && c < codes.size(); ++c)
                    wrong += hdr ? std::fabs(p[c] - codes[c]) > 1e-6
                                 : std::lround(p[c] * 255.0f) != std::lround(codes[c]);
            }
            EXPECT_EQ(wrong, 0);
        }
    }
}
