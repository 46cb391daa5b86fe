// SPDX-License-Identifier: Apache-2.0
#pragma once
// Stored samples <-> the kernel's float RGBA, run by run (a few thousand pixels, never a frame):
// 8/16-bit values v become exactly v/255 and v/65535 (correctly rounded float divisions) and go
// back through lut::toUnorm8/16 (round to nearest, clamp), so integer data round-trips bit for
// bit; half <-> float converts with round-to-nearest-even (F16C when the CPU has it, the same
// results in software otherwise).
#include "lut/formats/ImageIO.h"

#include <cstddef>
#include <cstdint>

namespace lut::formats {

// Which stored channels are R, G, B and A (-1: alpha absent, read as 1 and not written).
// A grey image has r == g == b.
struct RgbaMap {
    int r = 0, g = 1, b = 2, a = -1;
};
// From channel names (R G B A, Y, or else the first channels in order) and the alpha index.
RgbaMap rgbaMapOf(const ImageInfo& info);

// 4 * n floats from n pixels of nch channels of `type`.
void toRgba(const void* src, PixelType type, int nch, const RgbaMap& map, std::size_t n,
            float* rgba);

// Ordered-dither position of a run (whole-frame writes of 8/16-bit values).
struct DitherPos {
    bool on = false;
    int width = 0;         // image width
    std::size_t start = 0; // index of the run's first pixel in the image (y * width + x)
};

// n pixels of nch channels of `type` from 4 * n floats: R, G, B (and A when map.a >= 0) are
// written at their indices; other channels are left as they are. Grey outputs (r == g == b)
// take R.
void fromRgba(const float* rgba, std::size_t n, void* dst, PixelType type, int nch,
              const RgbaMap& map, const DitherPos& dither = {});

// Copies channel `srcChannel` of n pixels to channel `dstChannel`, converting the type (for
// channels that pass through untouched: extra EXR channels, alpha).
void copyChannel(const void* src, PixelType srcType, int srcChannels, int srcChannel, void* dst,
                 PixelType dstType, int dstChannels, int dstChannel, std::size_t n);

float halfToFloat(std::uint16_t h);
std::uint16_t floatToHalf(float f); // round to nearest even; NaN stays NaN, overflow -> Inf
void halfToFloatN(const std::uint16_t* src, float* dst, std::size_t n);
void floatToHalfN(const float* src, std::uint16_t* dst, std::size_t n);

} // namespace lut::formats
