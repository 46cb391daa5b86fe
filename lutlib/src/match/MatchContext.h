// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to lutlib's match: what fitMatch learnt of the pictures, kept for matchLook's
// measurements so the pictures are read once.
#include "lut/match/DistributionDistance.h"
#include "lut/match/Match.h"
#include "match/MatchSamples.h"

namespace lut::detail {

struct MatchContext {
    SampleSet source;             // every counted pixel (a grid beyond 4 megapixels)
    ColourDistribution reference; // the references' distribution (CIELAB)
};

MatchFitResult fitMatch(const MatchPicture& source, const std::vector<MatchPicture>& references,
                        const MatchOptions& options, MatchContext* context,
                        const Progress* progress = nullptr);

} // namespace lut::detail
