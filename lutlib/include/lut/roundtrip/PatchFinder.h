// SPDX-License-Identifier: Apache-2.0
#pragma once
// Finding a round-trip patch again in an edited screenshot by its marker frame (the frame is
// described in lut/roundtrip/PatchPlacement.h).
#include "lut/Image.h"
#include "lut/roundtrip/EditCause.h"
#include "lut/roundtrip/PatchPlacement.h"

#include <string>

namespace lut {

enum class FindStatus { Found, NotFound, Scaled };
struct FindResult {
    FindStatus status = FindStatus::NotFound;
    PatchPlacement placement;
    // Scaled: the marker's observed cell period in pixels (not a whole number); Found: cell/scale.
    double observedPeriod = 0.0;
    std::string message; // why it was not found / how it looks scaled
    // Not found: what most likely hid a marker frame that seems to be there (EditCause::None
    // when nothing like one was seen).
    EditCause cause = EditCause::None;
};
// Searches the whole image (the patch may have been moved or the image cropped by whole pixels).
FindResult findPatch(const ImageView& image);

} // namespace lut
