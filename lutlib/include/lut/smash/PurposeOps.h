// SPDX-License-Identifier: Apache-2.0
#pragma once
// Compose and mix for LUTs that say what they are for (lut/LutPurpose.h): the rule lutkit compose
// and lutkit mix follow, written once.
//   mix      both LUTs are made for the result's purpose first (lut::convertPurpose), then mixed
//            entry by entry (lut::mix): a blend of two game LUTs, or of two edits.
//   compose  "B after A" on the picture: B's edit of the picture A gives. For a game LUT result
//            with A the game's LUT, the game's LUT that shows B's edit of the picture A makes
//            (A is the stage: SmashAuthoring's composition on A's picture, exact at the game's
//            lattice); otherwise both as edits (a game LUT as the edit it makes), B's after A's
//            (lut::compose), then made for the result's purpose.
//   diff     what the player sees with each: an edit as the edit of the picture (its table on
//            display colours), a game LUT as the game shows it (gameShownForDisplayed: where the
//            neutral game showed d, as lutkit preview shows a screenshot), over a lattice of
//            display colours or a screenshot's pixels. Two edits are compared as tables, as
//            lut::diffLuts does.
#include "lut/Image.h"
#include "lut/LutPurpose.h"
#include "lut/ops/Compose.h"
#include "lut/ops/Diff.h"
#include "lut/ops/OpResult.h"
#include "lut/smash/PurposeConversion.h"

#include <string>
#include <vector>

namespace lut {

struct PurposedLut3D {
    const Lut3D* lut = nullptr;
    LutPurpose purpose = LutPurpose::Raw;
};

struct PurposeOpResult {
    OpResult result;     // the LUT for `to`; error: the table operation's (compose, mix), if any
    bool tableOp = true; // false: no table operation (the composition was authored directly)
    // Each conversion on the way, with what it was for: "A", "B", "result".
    std::vector<std::pair<std::string, PurposeConversion>> conversions;
};

PurposeOpResult mixForPurpose(const PurposedLut3D& a, const PurposedLut3D& b, double t,
                              LutPurpose to, Interpolation method = Interpolation::Tetrahedral,
                              const PurposeOptions& options = {});
struct PurposeDiff {
    DiffReport report;
    std::string compared; // "what the game shows with each (...)", "the two edits"
};
// options.size: the lattice (0: the larger of the two sizes, at least 33 with a game LUT).
PurposeDiff diffForPurpose(const PurposedLut3D& a, const PurposedLut3D& b,
                           const ImageView* image = nullptr, const DiffOptions& options = {});

PurposeOpResult composeForPurpose(const PurposedLut3D& a, const PurposedLut3D& b, LutPurpose to,
                                  const ComposeOptions& compose = {},
                                  const PurposeOptions& options = {});

} // namespace lut
