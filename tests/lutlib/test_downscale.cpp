// SPDX-License-Identifier: Apache-2.0
// lut::downscale (lut/Downscale.h) against block means computed in double here.
#include "lut/Downscale.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lut;

namespace {

Image ramp(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c)
                img.pixel(x, y)[c] = float(std::sin(0.37 * x + 1.3 * y + c) * 10 + x * y);
    return img;
}

} // namespace

TEST(Downscale, EveryOutputPixelIsTheMeanOfItsBlock) {
    for (int factor : {2, 3, 4, 9}) {
        const Image img = ramp(7, 5);
        const Image d = downscale(img, factor);
        // ceil(7 / f) x ceil(5 / f): the partial edge blocks are kept.
        ASSERT_EQ(d.width(), (7 + factor - 1) / factor) << factor;
        ASSERT_EQ(d.height(), (5 + factor - 1) / factor) << factor;
        for (int y = 0; y < d.height(); ++y)
            for (int x = 0; x < d.width(); ++x)
                for (int c = 0; c < 4; ++c) {
                    double sum = 0;
                    int n = 0;
                    for (int sy = y * factor; sy < std::min(5, (y + 1) * factor); ++sy)
                        for (int sx = x * factor; sx < std::min(7, (x + 1) * factor); ++sx) {
                            sum += img.pixel(sx, sy)[c];
                            ++n;
                        }
                    EXPECT_NEAR(d.pixel(x, y)[c], sum / n, 1e-4)
                        << "factor " << factor << " at " << x << "," << y << " c" << c;
                }
    }
}

TEST(Downscale, FactorOneAndEmptyAreCopies) {
    const Image img = ramp(3, 2);
    EXPECT_EQ(downscale(img, 1).pixels(), img.pixels());
    EXPECT_EQ(downscale(img, 0).pixels(), img.pixels());
    EXPECT_TRUE(downscale(Image(), 4).empty());
}
