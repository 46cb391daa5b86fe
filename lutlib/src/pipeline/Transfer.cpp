// SPDX-License-Identifier: Apache-2.0
#include "lut/pipeline/Transfer.h"

#include "core/FastMath.h"
#include "lut/Limits.h"
#include "lut/Math.h"
#include "lut/Parallel.h"

#include <cmath>

namespace lut {

float srgbEncode(float x) {
    x = detail::sanitizeValue(x, limits::kMaxColorValue);
    const float a = std::fabs(x);
    const float e = a <= 0.0031308f ? 12.92f * a : 1.055f * lut::math::pow(a, 1.0f / 2.4f) - 0.055f;
    return x < 0.0f ? -e : e;
}

float srgbDecode(float x) {
    x = detail::sanitizeValue(x, limits::kMaxColorValue);
    const float a = std::fabs(x);
    const float d = a <= 0.04045f ? a / 12.92f : lut::math::pow((a + 0.055f) / 1.055f, 2.4f);
    return x < 0.0f ? -d : d;
}

float gammaEncode(float x, float gamma) {
    x = detail::sanitizeValue(x, limits::kMaxColorValue);
    if (!(x > 0.0f) || !(gamma > 0.0f))
        return 0.0f;
    return lut::math::pow(x, 1.0f / gamma);
}

float gammaDecode(float x, float gamma) {
    x = detail::sanitizeValue(x, limits::kMaxColorValue);
    if (!(x > 0.0f) || !(gamma > 0.0f))
        return 0.0f;
    return lut::math::pow(x, gamma);
}

template <class F> static void eachRgb(const ImageView& frame, int nthreads, F f) {
    if (frame.empty())
        return;
    parallelFor(frame.height, nthreads, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            float* p = frame.row(y);
            for (int x = 0; x < frame.width; ++x, p += 4) {
                p[0] = f(p[0]);
                p[1] = f(p[1]);
                p[2] = f(p[2]);
            }
        }
    });
}

void srgbEncode(const ImageView& frame, int nthreads) {
    eachRgb(frame, nthreads, [](float v) { return srgbEncode(v); });
}
void srgbDecode(const ImageView& frame, int nthreads) {
    eachRgb(frame, nthreads, [](float v) { return srgbDecode(v); });
}

} // namespace lut
