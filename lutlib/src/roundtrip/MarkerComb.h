// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: a regular comb of marker-like edges that the patch finder saw but could
// not decode, and why (blur, noise, a damaged header): the finder's "not found" message.
#include "lut/Image.h"
#include "lut/roundtrip/PatchFinder.h"

#include <vector>

namespace lut::detail {

// A regular comb of edges (20+ at a whole-number spacing) that did not decode: remembered to say
// why no patch was found.
struct Comb {
    bool seen = false;
    int y = 0;
    std::vector<double> edges;
    int cell = 0;
};

// Fills result's message and cause for a comb that did not decode; false when nothing explains
// it (the caller keeps its generic message).
bool diagnoseComb(const ImageView& image, const Comb& comb, FindResult& result);

} // namespace lut::detail
