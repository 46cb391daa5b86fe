// SPDX-License-Identifier: Apache-2.0
#pragma once
// Clipping feedback: how many entries of a LUT fall outside the range a display (or an 8-bit
// export) can hold, cheap enough to run on every slider move (a 33^3 LUT takes tens of
// microseconds; tests/ops/test_grading.cpp checks the count against a plain one).
#include "lut/Lut3D.h"

#include <array>
#include <cstddef>

namespace lut {

struct ClipCount {
    std::size_t entries = 0;   // entries looked at
    std::size_t outside = 0;   // entries with any channel below lo, above hi or not finite
    std::size_t below = 0;     // entries with any channel below lo (-Inf counts)
    std::size_t above = 0;     // entries with any channel above hi (+Inf counts)
    std::size_t nonFinite = 0; // entries with a NaN or infinite channel
    std::array<std::size_t, 3> channelBelow{}; // per channel R, G, B
    std::array<std::size_t, 3> channelAbove{};

    double fraction() const {
        return entries ? static_cast<double>(outside) / static_cast<double>(entries) : 0.0;
    }
    bool operator==(const ClipCount&) const = default;
};

// Counts the entries outside [lo, hi] (a NaN channel counts in `outside` and `nonFinite` only).
ClipCount countOutOfRange(const Lut3D& lut, float lo = 0.0f, float hi = 1.0f);

} // namespace lut
