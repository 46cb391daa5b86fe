// SPDX-License-Identifier: Apache-2.0
#pragma once
// Every size limit and format constant lutlib enforces, in one place.
#include <cstddef>
#include <cstdint>

namespace lut::limits {

constexpr int kMin3DSize = 2;
constexpr int kMax3DSize = 256;
constexpr int kMin1DSize = 2;
constexpr int kMax1DSize = 65536;
// Longest line a text LUT reader accepts before refusing the file (Adobe's spec says 250 bytes;
// files in the wild exceed that with long comments, so we accept far more but never unbounded).
constexpr std::size_t kMaxTextLineBytes = 1 << 16;
// Largest image (width*height) any reader accepts: guards allocations on hostile headers.
constexpr std::uint64_t kMaxImagePixels = 1ull << 28;
// Largest picture extract searches whole for a round-trip patch: an 8K UHD screenshot
// (7680x4320). The search needs the whole picture as a float frame (16 bytes a pixel, 506 MiB
// here); a larger one is refused before it is read, with advice to crop it.
constexpr std::uint64_t kMaxPatchSearchPixels = 7680ull * 4320ull;
// Largest LUT file a reader will open (a 256^3 .cube with long lines is ~600 MB).
constexpr std::uint64_t kMaxLutFileBytes = 2ull << 30;

// Largest magnitude a colour value keeps once sanitized, by the preview pipeline (frames) and by
// the LUT operations (entries): the half-float maximum, what the game's R16G16B16A16_FLOAT render
// targets can hold; beyond it a value is not a colour any more. NaN becomes 0, +-Inf +-this.
constexpr float kMaxColorValue = 65504.0f;

} // namespace lut::limits
