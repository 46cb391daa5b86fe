// SPDX-License-Identifier: Apache-2.0
#include "lut/Downscale.h"

#include "lut/Parallel.h"

#include <algorithm>

namespace lut {

Image downscale(const Image& image, int factor, int nthreads) {
    if (factor <= 1 || image.empty())
        return image;
    const int w = (image.width() + factor - 1) / factor;
    const int h = (image.height() + factor - 1) / factor;
    Image out(w, h);
    parallelFor(h, nthreads, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const int sy0 = y * factor, sy1 = std::min(sy0 + factor, image.height());
            for (int x = 0; x < w; ++x) {
                const int sx0 = x * factor, sx1 = std::min(sx0 + factor, image.width());
                float acc[4] = {0, 0, 0, 0};
                for (int sy = sy0; sy < sy1; ++sy)
                    for (int sx = sx0; sx < sx1; ++sx) {
                        const float* p = image.pixel(sx, sy);
                        for (int c = 0; c < 4; ++c)
                            acc[c] += p[c];
                    }
                const float n = static_cast<float>((sy1 - sy0) * (sx1 - sx0));
                float* o = out.pixel(x, y);
                for (int c = 0; c < 4; ++c)
                    o[c] = acc[c] / n;
            }
        }
    });
    return out;
}

} // namespace lut
