// SPDX-License-Identifier: Apache-2.0
#pragma once
// What `lutkit match` says about the LUT it made (text here; --json in the CLI), and what the
// editor shows: the distance to the reference's colours before and after, how the LUT
// interpolates, what it clips, what the fit had to limit, and the time it took.
#include "lut/match/DistributionDistance.h"
#include "lut/match/LutQuality.h"
#include "lut/match/MatchOptions.h"
#include "lut/smash/GameError.h"

#include <cstddef>
#include <string>
#include <vector>

namespace lut {

struct MatchCandidate {
    MatchMethod method = MatchMethod::HmMklHm;
    DistributionDistance after; // the method's transfer applied to SOURCE vs REFERENCE
    double seconds = 0.0;       // its fit
    // auto: what keeps its LUT from being free of fold-overs and reversals ("folds colours over
    // in 12 of 32768 cells", "goes down along grey by 0.8 8-bit steps"...), "" when nothing does;
    // such a method is not eligible unless no method is free of them.
    std::string shapeProblem;
    bool eligible = true;
    // "; not eligible: its LUT folds colours over in 12 of 32768 cells" (or "; its LUT ..." when
    // no method was free of it), "" when shapeProblem is: the report's and the editor's wording.
    std::string shapeNote() const {
        if (shapeProblem.empty())
            return {};
        return (eligible ? "; its LUT " : "; not eligible: its LUT ") + shapeProblem;
    }
};

struct MatchReport {
    MatchMethod asked = MatchMethod::Auto;
    MatchMethod method = MatchMethod::HmMklHm; // the one used
    std::string choice;                        // why: "asked for", or auto's reason
    std::vector<MatchCandidate> candidates;    // auto: every method tried, in the order tried
    bool linear = false;                       // SOURCE is scene-linear (working encoding ACEScct)
    // The kind of look the reference is when its colours lie on a curve of lightness
    // ("posterised palette of 4 colours", "gradient map or duotone ..."); "" otherwise; and how
    // far its colours are from that curve (root mean square, 8-bit steps).
    std::string look;
    double lookRmsSteps = 0.0;

    // SOURCE vs REFERENCE, and the LUT (as baked: shaper, table, tetrahedral) applied to SOURCE
    // vs REFERENCE, over a regular subsample of up to 32768 pixels of each.
    DistributionDistance before, after;
    // The LUT against the transfer it tabulates (strength and preserve included), over every
    // distinct colour of SOURCE's counted pixels: 8-bit steps of the working encoding.
    GameError interpolation;
    std::size_t interpolationColours = 0;
    // The LUT's form: a 1D shaper then the table, or the table alone; where both were measured
    // (MatchLutForm::Auto and a transfer with curves), each one's error as `interpolation`.
    bool shaper = false;
    bool bothForms = false;
    bool tableFitted = false; // gradient map: the table's values fitted over SOURCE's colours
    GameError tableAloneError, shaperError;
    // A dip along grey repaired on the table (0 when none was): how far the channel went down
    // before, in 8-bit steps, how many of the table's grey nodes moved and by how much at most;
    // `quality` measures the LUT after.
    double greyDipRepaired = 0.0;
    int greyNodesMoved = 0;
    // HM-MKL-HM (or auto's floor) with its second histogram match sharp, not smoothed: its LUT
    // was clean and at least 10% closer to the reference (lutlib/src/match/MatchFit.cpp).
    bool sharpSecondMatch = false;
    double greyLargestMove = 0.0;
    LutQuality quality;

    // What the LUT does to SOURCE's counted pixels: channel values more than half an 8-bit step
    // outside [0, 1] (display encoded; below 0 for scene-linear), which an 8-bit output clips.
    std::size_t clippedValues = 0;
    std::size_t values = 0;
    double clippedMaxSteps = 0.0;       // the farthest, 8-bit steps beyond the range
    std::size_t tableValuesOutside = 0; // table entries' channel values outside the range
    std::size_t tableValues = 0;

    std::size_t sourcePixels = 0, sourceUsed = 0;       // counted: not masked, not NaN
    std::size_t referencePixels = 0, referenceUsed = 0; // all references together
    int references = 0;

    double secondsFit = 0.0;     // statistics and the transfer (every candidate for auto)
    double secondsBake = 0.0;    // the LUT
    double secondsMeasure = 0.0; // this report's figures
    double secondsTotal() const { return secondsFit + secondsBake + secondsMeasure; }

    // Several lines, each "label   text".
    std::string str() const;
};

} // namespace lut
