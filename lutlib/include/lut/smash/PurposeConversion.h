// SPDX-License-Identifier: Apache-2.0
#pragma once
// Turning a LUT made for one purpose (lut/LutPurpose.h) into the LUT for another: the one
// implementation behind lutkit convert, extract, apply, preview, compose, mix and the editor's
// exports and preview (docs/architecture.md, "Why one purpose").
//   raw -> smash  the game's 16^3 LUT that makes Smash Ultimate show the edit of its own picture:
//                 SmashAuthoring.h's exact composition (clamped to what the file can hold) or its
//                 least-squares refinement, on the picture of a stage LUT when one is given, with
//                 the one rule above white (SmashAuthoring.h: the edit of the displayed white; the
//                 stage's own entry where that is white, so a neutral edit gives the stage LUT
//                 back and a game LUT exported unchanged is itself);
//   smash -> raw  the edit the game's LUT makes of the neutral game's picture (editOfGameLut);
//   same purpose  the table as it is.
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/LutFile.h"
#include "lut/LutPurpose.h"
#include "lut/interp/Interpolation.h"
#include "lut/interp/Sampler.h"
#include "lut/smash/GameError.h"
#include "lut/smash/SmashAuthoring.h"

#include <string>

namespace lut {

struct PurposeOptions {
    // raw -> smash:
    Interpolation editInterpolation = Interpolation::Tetrahedral; // how the edit is evaluated
    const Lut3D* stageLut = nullptr; // the stage the edit was made on (null: the neutral game)
    // Report what the game shows (SmashAuthoringResult) with the exact composition; `refine` also
    // computes the least-squares refinement and ships it when it beats the exact composition on
    // colours it was not fitted on (and implies measure). Only what is asked for is computed.
    bool measure = false;
    bool refine = false;
    const ImageView* screenshot = nullptr; // the colours measured and refined over
    // smash -> raw: the lattice of the edit (display colours).
    int rawSize = 33;
    int nthreads = 0;
};

struct PurposeConversion {
    LutPurpose from = LutPurpose::Raw;
    LutPurpose to = LutPurpose::Raw;
    bool converted() const { return from != to; }
    // What to use or write: the input as it is (same purpose); smash: 16^3 in [0,1] (the exact
    // composition clamped, or the refinement when it won); raw: rawSize^3.
    Lut3D lut;
    // raw -> smash: the exact composition (unclamped), what the game shows when measured, the
    // entries it cannot reach.
    SmashAuthoringResult authoring;
    // smash -> raw: the raw table against the edit it samples, between its lattice points.
    GameError sampling;
    std::string measuredOver;
    // raw -> smash made on a stage's picture (PurposeOptions::stageLut), not the neutral game's.
    bool onStage = false;
};

PurposeConversion convertPurpose(const Lut3D& lut, LutPurpose from, LutPurpose to,
                                 const PurposeOptions& options = {});
// The same for a LUT file: a file with a 1D shaper is evaluated exactly (the shaper, then its
// table) wherever the game's LUT is computed and measured, never merged into one table first
// (raw -> smash); the game's LUT of a file with a shaper is its table as LutFile::toLut3D bakes
// it (smash -> raw, same purpose). Throws lut::Error if the file holds no table.
PurposeConversion convertPurpose(const LutFile& file, LutPurpose from, LutPurpose to,
                                 const PurposeOptions& options = {});

// The edit a game LUT makes of the neutral game's picture: for a display colour d (what the
// neutral game shows for its input s = srgbDecode(d)^(1/2.2) / 1.3703, per channel; white for
// every s from 1/1.3703 up, taken at 1/1.3703 where it starts), the colour the game shows with
// `game` (sampled trilinearly, as the game's GPU does) at that s:
//     E(d) = srgb(min(1, (((G(s) - s) * 0.99961 + s) * 1.3703)^2.2))
// sampled on a size^3 lattice over [0,1]. `error` (optional) receives how far the lattice,
// interpolated tetrahedrally, is from E between its points: measured at every combination of
// the cell centres, the lattice points and the colours where E has a kink (the game LUT's
// lattice planes), in 8-bit display steps.
Lut3D editOfGameLut(const Lut3D& game, int size, GameError* error = nullptr, int nthreads = 0,
                    std::string* measuredOver = nullptr);
// E(d) of editOfGameLut at one display colour, exactly (no lattice): what the game shows with the
// game LUT `game` (a trilinear sampler of it, as the game's GPU) where the neutral game showed d,
// as lutkit preview shows a screenshot with it.
glm::dvec3 gameShownForDisplayed(const Sampler& game, const glm::dvec3& d);

} // namespace lut
