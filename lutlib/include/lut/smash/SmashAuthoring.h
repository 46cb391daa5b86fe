// SPDX-License-Identifier: Apache-2.0
#pragma once
// Authoring a Smash Ultimate LUT for a look the modder made on the game's picture: the exact
// composition at the game's 16^3 lattice, an optional least-squares refinement between lattice
// points, and what the game then shows, measured (docs/roundtrip.md, "The compensation";
// docs/specs/smash-pipeline.md). One implementation for `lutkit convert --target smash`, the
// round trip's `extract --target smash` and the editor's game export.
//
// For every lattice input s of the game's LUT (s = (i, j, k)/15), in double precision:
//     shown(s)  = srgb(min(1, (((G(s) - s) * 0.99961 + s) * 1.3703)^2.2))   G = the stage LUT
//     wanted(s) = clamp(edit(shown(s)))              (display colours: the edited screenshot)
//     L(s)      = (srgb^-1(wanted)^(1/2.2) / 1.3703 - s) / 0.99961 + s      the exact entry
// and, for a channel where wanted(s) is white, L(s) = max(that entry, G(s)) (the rule above white,
// below), so the game shows wanted(s) at every lattice point. Between lattice points the game
// interpolates L trilinearly, which is not the composition evaluated there: the refinement chooses
// the entries that minimise the squared error of what the game shows over colours that occur (three
// quarters of a screenshot's distinct colours, else the inputs on a grid four times finer than the
// LUT's), rounds them to the 8-bit values the nutexb stores by a search on the true error, and is
// shipped only when it beats the exact composition on the colours it was not fitted on (the other
// quarter, or the centres between the grid's points; a screenshot's refinement that wins is then
// fitted again on all its colours). What the game shows is reported where
// nothing was fitted: over every input (a bound, lut/ops/ErrorBound.h) or every pixel of the
// screenshot (smash/GameMeasure.h).
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/interp/Interpolation.h"
#include "lut/smash/GameError.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <functional>
#include <string>

namespace lut {

// The one rule above white, for every way of making a game LUT (convert of a graded strip or a
// LUT file, embed/extract, the editor's exports; docs/roundtrip.md, "Above white"). Every input
// with s > 1/1.3703 = 0.73 showed white in the unedited game, and a screenshot holds white there
// whatever the scene was: the edited screenshot shows edit(white), and that is what the game
// should show (wanted is the edit of the displayed, clipped colour, clamped to [0,1]). Where a
// channel of wanted is white, every entry from the one that reaches white up shows the same
// white; the entry is then the stage LUT's own (s for the neutral game) when it reaches white
// too. So a neutral edit gives the stage LUT back (the neutral nutexb for the neutral game), a
// game LUT opened and exported unchanged gives itself back, and an edit that darkens white (x0.8)
// shows edit(white) for every bright colour, as the graded screenshot does.

// The display colour the game should show for its LUT input s (gamma space, [0,1]^3).
using WantedDisplay = std::function<glm::dvec3(const glm::dvec3& s)>;
// An edit of display colours (what a modder does to a screenshot), [0,1]^3 -> colours.
using DisplayEdit = std::function<glm::vec3(glm::vec3)>;

struct SmashAuthoringOptions {
    const Lut3D* gameLut = nullptr; // the stage's LUT the picture was made with (null: neutral)
    // Also compute the least-squares refinement, and ship it when it beats the exact composition
    // on the held-out colours. Off: only the exact composition is computed (and measured).
    bool refine = false;
    // The colours that occur: a screenshot the game showed (display-encoded, unedited). Null: the
    // inputs s on a grid gridSubdivision times finer than the LUT's (61^3 for 4).
    const ImageView* screenshot = nullptr;
    std::size_t maxSamples = 250000; // the refinement's pixels are subsampled regularly beyond this
    int gridSubdivision = 4;
    bool measure = true; // false: only the exact composition (no error report, no refinement)
    int nthreads = 0;
};

struct SmashAuthoringResult {
    Lut3D exact; // the composition at the lattice points, unclamped (16^3)
    // What to ship: the refinement when it won on the held-out colours, else exact in [0,1].
    Lut3D lut;
    bool refined = false;            // lut is the refinement
    bool refinementComputed = false; // options.refine: the refinement was computed and checked
    // What the game shows with the 8-bit LUT vs wanted, over measuredOver (display steps; the
    // max an upper bound over it):
    GameError exactError;   // with exact rounded to nearest
    GameError refinedError; // with the refinement (count 0 unless computed)
    // The same over the held-out colours only (the refinement never saw them): what decided.
    GameError heldOutExact, heldOutRefined;
    std::string fittedOn; // "the 61^3 grid's points, checked on the 216000 centres between them"
    std::string decision; // which LUT is shipped and why ("" unless the refinement was computed)
    std::size_t clampedEntries = 0; // channel values of exact outside [0,1]
    double clampedMax = 0.0;        // ... the farthest (in [0,1] units)
    std::string
        measuredOver; // "every input (a bound ...)" / "the screenshot's 921600 pixels (...)"
};

// The general form: any wanted colour per input (the round trip uses it with the patch), clamped
// to [0,1]; where it is white the rule above white keeps gameLut's entry.
SmashAuthoringResult authorSmashLut(const WantedDisplay& wanted,
                                    const SmashAuthoringOptions& options);
// wanted(s) = clamp(edit(shown(s))).
SmashAuthoringResult authorSmashLutForEdit(const DisplayEdit& edit,
                                           const SmashAuthoringOptions& options);
// The edit as a LUT file (any size and domain) sampled with `editInterpolation`; outside its
// domain the edit takes the edge value (the displayed colours it is evaluated at are in [0,1]).
SmashAuthoringResult authorSmashLutForEdit(const Lut3D& edit, Interpolation editInterpolation,
                                           const SmashAuthoringOptions& options);

// The display colour (display-encoded) the game shows for its LUT input s with the stage LUT
// `gameLut` (null: neutral); unclipped above 1 when `clip` is false.
glm::dvec3 smashShownColour(const glm::dvec3& s, const Lut3D* gameLut, bool clip = true);

} // namespace lut
