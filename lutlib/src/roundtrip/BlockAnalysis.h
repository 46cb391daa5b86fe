// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: gathers lut::BlockEvidence (lut/roundtrip/BlockEvidence.h) from a patch's
// pixels; readPatch calls it.
#include "lut/Image.h"
#include "lut/roundtrip/BlockEvidence.h"
#include "lut/roundtrip/PatchPlacement.h"

namespace lut::detail {

BlockEvidence gatherBlockEvidence(const ImageView& image, const PatchPlacement& placement);

} // namespace lut::detail
