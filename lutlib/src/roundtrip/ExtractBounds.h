// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib: extract's expected error (lut/roundtrip/Extract.h, ExpectedError), an upper
// estimate built from the patch's own redundancy. At every input x the error is bounded by
//     model(x) + interpolation(x) + noise(x)
//   model          what the LUT does against the edit as the patch measured it (computed)
//   interpolation  how far the patch's interpolant can be from the true edit between its entries:
//                  the sub-lattice check's residuals around x, all of the largest nearby (an
//                  entry predicted from neighbours a spacing away: four times the error for
//                  smooth edits, about the error at kinks and steep powers near black)
//   noise          the read error of the entries around x: half a storage step, the noise the
//                  neighbouring entries show beyond that (a cubic through the neighbours along
//                  each axis predicts every entry; the median misfit, robust to kinks, gives a
//                  noise level), the pixel spread of their blocks and the marker cells' spread
// summarised over a grid four times finer than the output LUT's lattice, the maximum bounded
// between the grid's points too (lut/ops/ErrorBound.h; docs/roundtrip.md, docs/accuracy.md).
#include "lut/Lut3D.h"
#include "lut/roundtrip/Extract.h"
#include "lut/roundtrip/PatchReader.h"
#include "roundtrip/ExtractChecks.h"

#include <glm/vec3.hpp>

#include <functional>

namespace lut::detail {

// The read error of the patch's entries, 8-bit steps.
struct ReadNoise {
    double half = 0.0;                 // half a storage step of the edited file
    double sigma[3] = {0.0, 0.0, 0.0}; // per channel, beyond the storage rounding
    double frame = 0.0;                // the marker cells' spread
    Lut3D spread;                      // per entry and channel: the block's pixel spread (RMS)
    // Per entry bounds of three kinds: the largest error, the 99th percentile, the mean.
    Lut3D max, p99, mean;
};
ReadNoise estimateReadNoise(const PatchReading& patch);

// Smash: `shipped` is the LUT as the game receives it (8-bit values), `wanted` what the game
// should show at s as the patch says (display colours), `originalLut` the stage's LUT (null:
// neutral) for locating the colours a product-lattice patch was read at.
ExpectedError smashExpectedError(const PatchReading& patch, const SubLattice& sub,
                                 const ReadNoise& noise, const Lut3D& shipped,
                                 const std::function<glm::dvec3(const glm::dvec3&)>& wanted,
                                 const Lut3D* originalLut, GameError& model, int nthreads);

// Raw: the LUT as written (applied with trilinear interpolation) against the edit.
ExpectedError rawExpectedError(const PatchReading& patch, const SubLattice& sub,
                               const ReadNoise& noise, const Lut3D& lut, const PatchFunction& edit,
                               GameError& model, int nthreads);

} // namespace lut::detail
